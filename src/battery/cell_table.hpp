// 1-RC equivalent-circuit parameters of one cell vs state of charge and temperature:
// OCV(SOC,T) [V], R0(SOC,T) [Ohm], R1(SOC,T) [Ohm], tau1(SOC,T) [s] (C1 = tau1/R1 [F]).
// Bilinear interpolation on the SOC x T grid, CLAMPED at the grid edges: outside the measured
// temperatures (278-313 K for the Kokam/MathWorks table) the edge values are used, no
// extrapolation. Look-up O(log n), no allocation.
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
  CellPoint at(double soc, double T_K) const {
    return {ocv_(soc, T_K), r0_(soc, T_K), r1_(soc, T_K), tau_(soc, T_K)};
  }
  double ocv(double soc, double T_K) const { return ocv_(soc, T_K); }
  const std::vector<double>& soc() const { return ocv_.x(); }
  const std::vector<double>& temperature() const { return ocv_.y(); }

 private:
  Table2D ocv_, r0_, r1_, tau_;
};

}  // namespace hbt::battery
