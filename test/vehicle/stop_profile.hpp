// Test target profile of one bus stop (shared by the vehicle stop tests and the idle-governor
// test): stand 1 s, +0.8 m/s² to 30 km/h, cruise to 25 s, −0.9 m/s² to rest (the mission
// profile's stop deceleration), stand `stand_s`, then +0.8 m/s² back to 30 km/h. Piecewise
// linear in t: v(t) [m/s], a(t) [m/s²], s(t) [m] (exact up to the 1 ms trapezoid of a linear v).
#pragma once
#include <algorithm>

#include "common/units.hpp"

namespace hbt::vehicle::test {

struct StopProfile {
  explicit StopProfile(double stand_s) : t_go(t_zero + stand_s) {}
  double v30 = units::kmhToMps(30.0);
  double t_acc_end = 1.0 + v30 / 0.8, t_dec = 25.0, t_zero = 25.0 + v30 / 0.9;
  double t_go;
  double v(double t) const {
    if (t < 1.0) return 0.0;
    if (t < t_acc_end) return 0.8 * (t - 1.0);
    if (t < t_dec) return v30;
    if (t < t_zero) return v30 - 0.9 * (t - t_dec);
    if (t < t_go) return 0.0;
    return std::min(v30, 0.8 * (t - t_go));
  }
  double a(double t) const {
    if (t >= 1.0 && t < t_acc_end) return 0.8;
    if (t >= t_dec && t < t_zero) return -0.9;
    if (t >= t_go && 0.8 * (t - t_go) < v30) return 0.8;
    return 0.0;
  }
  // Distance of the target at t (the stop position for t in [t_zero, t_go]).
  double s(double t) const {
    double s = 0.0, tp = 0.0;
    for (int i = 1; i <= 200000 && tp < t; ++i) {
      const double tn = std::min(t, i * 1e-3);
      s += 0.5 * (v(tp) + v(tn)) * (tn - tp);
      tp = tn;
    }
    return s;
  }
};

}  // namespace hbt::vehicle::test
