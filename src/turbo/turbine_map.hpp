// Radial-turbine map in reduced quantities, with validation, scaling and extrapolation.
//
// Quantities (turbine inlet total state p_3, T_3; outlet static pressure p_4):
//   reduced speed            N_r = N/√T_3                          [rpm/√K]
//   expansion ratio          ER  = p_3/p_4 (total-to-static)        [-]
//   reduced flow parameter   Φ   = ṁ √T_3 / p_3[kPa]               [kg·√K/(s·kPa)]
//   blade-speed parameter    ν   = N_r / √(1 − ER^(−k)),  k = (γ−1)/γ   [rpm/√K]
//                            (∝ U/C_s: U = πD N/60, C_s = √(2 c_p T_3 (1 − ER^(−k))))
//
// Inside the measured domain: linear interpolation in ER along each line, linear in N_r between
// lines (measured points are reproduced exactly).
// Flow extrapolation (isentropic-nozzle law, effective area frozen at the line's end point):
//   ER above the last point:  Φ = Φ_last · ψ(1/ER)/ψ(1/ER_last)  → saturates (choke) once
//                             ER ≥ 1/π*; a line already saturated stays constant.
//   ER below the first point: Φ = Φ_first · ψ(1/ER)/ψ(1/ER_first) → 0 at ER = 1;
//   ER ≤ 1: Φ = 0 (no reverse flow through the turbine).
//   N_r outside the lines: Φ of the nearest line (flow capacity depends only weakly on speed).
// Efficiency: a least-squares parabola in the blade-speed ratio is fitted to all points,
//   η = η_max (2x − x²),  x = ν/ν_opt   (η = aν + bν², η_max = −a²/4b, ν_opt = −a/2b),
// and used as the *shape* outside the measured domain, anchored to the nearest measured value:
//   η = η_edge · G(x)/G(x_edge),  G(x) = 2x − x² (x ≤ 1),  G(x) = exp(−(x−1)²) (x > 1)
// (G is C²-continuous at x = 1, positive for x > 0, so the ratio is defined and η → 0 as N → 0,
// where a stalled turbine delivers no power). η is clamped to [0, max measured η].
// Look-ups: binary searches over ≤ a few tens of points, ≤ 3 pow(), no allocation.
#pragma once
#include <string>
#include <vector>

#include "common/perfect_gas.hpp"

namespace hbt::turbo {

struct TurbineMapFormat {
  std::string col_speed = "reduced_speed";                // [rpm/√K]
  std::string col_mfp = "reduced_mass_flow_parameter";    // [kg·√K/(s·kPa)]
  std::string col_er = "expansion_ratio";                 // total-to-static [-]
  std::string col_eff = "efficiency";                     // total-to-static [-]
};

struct TurbineLine {
  double speed = 0.0;                          // reduced speed [rpm/√K]
  std::vector<double> er, mfp, eta;            // sorted by ER
};

class TurbineMap {
 public:
  enum Region : int { kInside = 0, kErBelow = 1, kErAbove = 2, kBelowLines = 4,
                      kAboveLines = 8, kNoFlow = 16 };
  struct Point {
    double mfp = 0.0;  // [kg·√K/(s·kPa)]
    double eta = 0.0;  // [-]
    int region = kInside;
  };

  TurbineMap() = default;
  static TurbineMap read(const std::string& path, const TurbineMapFormat& fmt = {},
                         PerfectGas gas = {1.33, 287.0});
  TurbineMap(std::vector<TurbineLine> lines, PerfectGas gas, const std::string& source,
             const TurbineMapFormat& fmt = {});

  /// Φ × flow_factor; N_r × speed_factor (geometric similarity: speed_factor = 1/√flow_factor).
  void scale(double flow_factor, double speed_factor);

  Point at(double reduced_speed, double er) const;

  double bladeSpeedParameter(double reduced_speed, double er) const;  // ν [rpm/√K]
  double nuOpt() const { return nu_opt_; }       // fitted ν_opt [rpm/√K]
  double etaMaxFit() const { return eta_max_fit_; }
  double etaCap() const { return eta_cap_; }     // max measured η
  const std::vector<TurbineLine>& lines() const { return lines_; }
  const std::string& source() const { return source_; }
  const PerfectGas& gas() const { return gas_; }

 private:
  double lineMfp(int i, double er, double psi_q) const;
  double lineEta(int i, double er, double sq) const;
  double gRatio(double xq, double xc) const;
  void build(const TurbineMapFormat& fmt);

  std::string source_;
  PerfectGas gas_;
  std::vector<TurbineLine> lines_;
  std::vector<double> speed_;
  std::vector<double> psi_first_, psi_last_;   // ψ(1/ER) at the line ends
  std::vector<double> sq_first_, sq_last_;     // √(1 − ER^(−k)) at the line ends
  double nu_opt_ = 1.0, eta_max_fit_ = 0.0, eta_cap_ = 0.0;
};

}  // namespace hbt::turbo
