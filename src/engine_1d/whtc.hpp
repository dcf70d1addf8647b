// WHTC denormalisation and cycle-validation statistics per UN GTR No. 4 (WHDC), for the 1D engine
// tools and tests.
//
// Reference speeds from the full-load curve T_fl(n), P(n) = T_fl(n) n, P_max its maximum
// (GTR No. 4 §7.4.1 / 7.4.2, evaluated on a 1 rpm grid with linear interpolation):
//   n_lo   lowest speed where P = 0.55 P_max                       [rpm]
//   n_hi   highest speed where P = 0.70 P_max
//   n_95h  highest speed where P = 0.95 P_max
//   n_pref speed where the integral of T_fl from n_idle reaches 51 % of the integral from
//          n_idle to n_95h (the "preferred speed")
// Denormalised reference speed and torque (§7.4.2.2, §7.4.2.3):
//   n_ref = n_norm/100 (0.45 n_lo + 0.45 n_pref + 0.1 n_hi - n_idle) 2.0327 + n_idle
//   T_ref = T_norm/100 T_fl(n_ref);   motoring points (T_norm = -1 in the file): T_ref = T_mot(n_ref)
// Regression of the actual on the reference values at 1 Hz (§7.8.7): least squares y = a1 x + a0,
//   SEE = sqrt(sum (y - a1 x - a0)^2 / (N - 2)),  r^2 = 1 - sum(y - y_fit)^2 / sum(y - ybar)^2,
// judged against the GTR criteria (Table 7): torque SEE <= 10 % T_max, slope 0.83-1.03,
// r^2 >= 0.850, |a0| <= max(20 Nm, 2 % T_max); speed SEE <= 5 % n_max, slope 0.95-1.03,
// r^2 >= 0.970, |a0| <= 10 rpm; power SEE <= 10 % P_max, slope 0.83-1.03, r^2 >= 0.910,
// |a0| <= max(4 kW, 2 % P_max).
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace hbt::engine_1d {

struct GtrReferenceSpeeds {
  double n_idle = 0, n_lo = 0, n_hi = 0, n_95h = 0, n_pref = 0, p_max_W = 0, n_pmax = 0;  // rpm, W
};

/// full_load(rpm) -> Nm; scans n_idle ... n_max [rpm] with 1 rpm steps.
GtrReferenceSpeeds gtrReferenceSpeeds(const std::function<double(double)>& full_load_rpm,
                                      double n_idle_rpm, double n_max_rpm);

struct WhtcPoint {
  double t_s = 0, n_rpm = 0, torque_Nm = 0;
  bool motoring = false;
};

/// Reads the normalised cycle (columns time, n_norm, T_norm) and denormalises it.
std::vector<WhtcPoint> denormaliseWhtc(const std::string& csv_path, const GtrReferenceSpeeds& s,
                                       const std::function<double(double)>& full_load_rpm,
                                       const std::function<double(double)>& motoring_rpm);

struct Regression {
  double slope = 0, intercept = 0, r2 = 0, see = 0;
  int n = 0;
};
Regression regress(const std::vector<double>& x_ref, const std::vector<double>& y_act);

struct RegressionLimits {
  double see_max, slope_lo, slope_hi, r2_min, intercept_max;
  bool pass(const Regression& r) const {
    return r.see <= see_max && r.slope >= slope_lo && r.slope <= slope_hi && r.r2 >= r2_min &&
           (r.intercept <= intercept_max && r.intercept >= -intercept_max);
  }
};
RegressionLimits torqueLimits(double t_max_Nm);
RegressionLimits speedLimits(double n_max_rpm);
RegressionLimits powerLimits(double p_max_W);

}  // namespace hbt::engine_1d
