// Driver: follows a target speed with accelerator and brake pedals (0..1).
//
// Force demand at the wheels [N]:
//   F_cmd = F_ff + m (k_p e + k_i sat(e_s)),   e = v_target - v,   clamped to [F_min - F_b,max, F_max]
//   e_s = s_target - s: distance error = ∫e dt, with s_target = ∫v_target dt integrated by the
//   model from the targets it receives. The integral state IS the distance error (never reset,
//   not frozen), so the bus keeps the profile's position over the mission and stops where the
//   profile stops; anti-windup by saturation sat = clamp to ±max_distance_error_m (after a
//   power-limited lag the bus catches up at most k_i e_max / k_p faster than the target).
//   F_ff  = M_eff a_target + F_roll + F_aero(v) + F_grade                (feed-forward)
// Pedal allocation with the driveline's present steady-state force range [F_min, F_max]:
//   F_cmd >= F_min:  accelerator = (F_cmd - F_min) / (F_max - F_min), brake = 0
//   F_cmd <  F_min:  accelerator = 0, brake force = F_min - F_cmd <= F_brake,max
// Stop (target <= stop_target_speed, the profile is at rest at a stop point):
//   v > 0:  braking to standstill, never released: F_cmd = min(F_PI, F_stop) with
//           F_stop = -M_eff a_stop + F_roll + F_aero + F_grade (given by the model; the
//           target deceleration and hence the feed-forward have vanished at the stop, VECTO
//           drivers brake to standstill at the stop point).
//   v <= hold_speed: hold brake >= hold_brake_fraction · F_brake,max.
// F_min is the force at zero accelerator: engine motoring torque through a locked gear, the
// converter's creep force at idle in 1C (see VehicleModel::evaluateDriver).
// F_brake,max = m · max_brake_decel.
#pragma once
#include <limits>

#include "vehicle/vehicle_params.hpp"

namespace hbt::vehicle {

struct DriverCommand {
  double accel_pedal = 0.0;     // [0, 1]
  double brake_pedal = 0.0;     // [0, 1]
  double brake_force_N = 0.0;   // friction brake force demand [N] (>= 0)
  double force_command_N = 0.0; // F_cmd [N]
  bool hold = false;            // stop hold active
};

class Driver {
 public:
  Driver() = default;
  Driver(const DriverParams& p, double mass_kg)
      : p_(p), m_(mass_kg), f_brake_max_(mass_kg * p.max_brake_decel_m_s2) {}
  void reset() {}  // stateless (the distance error is kept by the model)
  /// One update. F_ff_N: feed-forward force; F_min/F_max: driveline force range [N].
  /// F_stop_N: force demand that stops the bus at the stop deceleration (used while a stop is
  /// requested and v > 0; +inf = not given: the PI alone). distance_error_m: e_s = s_target - s.
  DriverCommand update(double dt_s, double v_m_s, double v_target_m_s, double F_ff_N,
                       double F_min_N, double F_max_N,
                       double F_stop_N = std::numeric_limits<double>::infinity(),
                       double distance_error_m = 0.0);
  double maxBrakeForce() const { return f_brake_max_; }
  bool stopRequested(double v_target_m_s) const { return v_target_m_s <= p_.stop_target_speed_m_s; }

 private:
  DriverParams p_;
  double m_ = 0.0, f_brake_max_ = 0.0;
};

}  // namespace hbt::vehicle
