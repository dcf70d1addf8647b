#include "vehicle/driver.hpp"

#include <algorithm>

namespace hbt::vehicle {

DriverCommand Driver::update(double dt, double v, double vt, double F_ff, double F_min,
                             double F_max, double F_stop, double e_s) {
  DriverCommand c;
  F_max = std::max(F_max, F_min + 1.0);
  const double lo = F_min - f_brake_max_;
  // PI with the distance error as the integral state (anti-windup: saturation of e_s).
  const double e_lim = p_.max_distance_error_m;
  double F = F_ff + m_ * (p_.kp_per_s * (vt - v) + p_.ki_per_s2 * std::clamp(e_s, -e_lim, e_lim));
  if (stopRequested(vt) && v > 0.0) F = std::min(F, F_stop);  // brake to standstill at the stop
  F = std::clamp(F, lo, F_max);
  c.force_command_N = F;
  if (F >= F_min) {
    c.accel_pedal = std::clamp((F - F_min) / (F_max - F_min), 0.0, 1.0);
  } else {
    c.brake_force_N = std::min(F_min - F, f_brake_max_);
  }
  if (stopRequested(vt) && v <= p_.hold_speed_m_s) {
    c.hold = true;
    c.accel_pedal = 0.0;
    c.brake_force_N = std::max(c.brake_force_N, p_.hold_brake_fraction * f_brake_max_);
  }
  c.brake_pedal = f_brake_max_ > 0.0 ? c.brake_force_N / f_brake_max_ : 0.0;
  return c;
}

}  // namespace hbt::vehicle
