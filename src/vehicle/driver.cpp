#include "vehicle/driver.hpp"

#include <algorithm>

namespace hbt::vehicle {

DriverCommand Driver::update(double dt, double v, double vt, double F_ff, double F_min,
                             double F_max) {
  DriverCommand c;
  F_max = std::max(F_max, F_min + 1.0);
  const double lo = F_min - f_brake_max_;
  // Re-create the PI with this step's output limits, keeping its integral state.
  const double integral = pid_.integral();
  pid_ = Pid(PidGains{m_ * p_.kp_per_s, m_ * p_.ki_per_s2, 0.0, lo, F_max});
  pid_.reset(integral);
  const double F = pid_.update(vt - v, dt, F_ff);
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
    pid_.reset(0.0);
  }
  c.brake_pedal = f_brake_max_ > 0.0 ? c.brake_force_N / f_brake_max_ : 0.0;
  return c;
}

}  // namespace hbt::vehicle
