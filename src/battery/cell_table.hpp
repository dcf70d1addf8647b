// 1-RC equivalent-circuit parameters of one cell vs state of charge and temperature:
// OCV(SOC,T) [V], R0(SOC,T) [Ohm], R1(SOC,T) [Ohm], tau1(SOC,T) [s] (C1 = tau1/R1 [F]).
// Bilinear interpolation on the SOC x T grid, clamped at the SOC edges and at the warm edge.
// Below the coldest tabulated temperature T_1 (278 K for the Kokam/MathWorks table) the
// resistances follow the Arrhenius law of thermally activated transport and charge transfer
// (resistance ∝ exp(E_a / (R T)): Jow et al., J. Electrochem. Soc. 165 (2018) A361, the
// charge-transfer resistance of graphite/NMC cells; Ji, Zhang and Wang, J. Electrochem. Soc.
// 160 (2013) A636, the transport properties of their cold-cell model), with the activation
// temperature the table itself shows between its two coldest temperatures T_1 < T_2 at that SOC:
//   θ = E_a/R = ln(R(T_1)/R(T_2)) / (1/T_1 - 1/T_2)  [K]  (>= 0: a table falling towards the cold
//   is held at its edge),      R(T) = R(T_1) exp(θ (1/T - 1/T_1))   for T < T_1,
// for R0 and R1 each (the law passes through both tabulated points). OCV and tau1 stay at their
// T_1 values (the OCV's entropic term is millivolts over 10 K). For the Kokam table at SOC 0.5:
// θ(R0) = 1444 K (E_a 12 kJ/mol), θ(R1) = 4097 K (34 kJ/mol, within the 30-60 kJ/mol reported
// for charge transfer): at 0 °C R0 +9.7 % and R1 +30 % over 5 °C. Look-up O(log n), no
// allocation.
//
// File (common/csv_table.hpp): columns SOC [-], T [K], OCV [V], R0 [Ohm], R1 [Ohm], tau1 [s], one
// row per grid point (any order). Checked, InputError(file, column): complete grid (every SOC x T
// pair exactly once), >= 2 SOC and >= 2 T points, SOC in [0, 1], T > 0, OCV > 0 and strictly
// increasing with SOC at every T, R0, R1, tau1 > 0.
#pragma once
#include <string>

#include "common/table2d.hpp"

namespace hbt::battery {

struct CellPoint {
  double ocv_V, r0_Ohm, r1_Ohm, tau1_s;
};

class CellTable {
 public:
  CellTable() = default;
  /// Reads and validates `path` (errors name `path` and the column).
  static CellTable read(const std::string& path);
  CellPoint at(double soc, double T_K) const;
  /// The Arrhenius law above: R at T_K < T_1 from R(T_1) = r1 and R(T_2) = r2 [Ohm].
  static double arrhenius(double r1, double r2, double T1_K, double T2_K, double T_K);
  double ocv(double soc, double T_K) const { return ocv_(soc, T_K); }
  const std::vector<double>& soc() const { return ocv_.x(); }
  const std::vector<double>& temperature() const { return ocv_.y(); }

 private:
  Table2D ocv_, r0_, r1_, tau_;
};

}  // namespace hbt::battery
