// Driver: follows a target speed with accelerator and brake pedals (0..1).
//
// Force demand at the wheels [N]:
//   F_cmd = F_ff + m (k_p e + k_i ∫e dt),   e = v_target - v            (hbt::Pid, anti-windup)
//   F_ff  = M_eff a_target + F_roll + F_aero(v) + F_grade                (feed-forward)
// Pedal allocation with the driveline's present steady-state force range
// [F(T_min), F(T_max)] (engine motoring ... full-load torque through the current gear/TC):
//   F_cmd >= F(T_min):  accelerator = (F_cmd - F(T_min)) / (F(T_max) - F(T_min)), brake = 0
//   F_cmd <  F(T_min):  accelerator = 0, brake force = F(T_min) - F_cmd <= F_brake,max
// The PI output is limited to [F(T_min) - F_brake,max, F(T_max)] (integral frozen beyond).
// Stop: target <= stop_target_speed and v <= hold_speed -> hold brake, integral reset.
// F_brake,max = m · max_brake_decel.
#pragma once
#include "common/pid.hpp"
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
  void reset() { pid_.reset(0.0); }
  /// One update. F_ff_N: feed-forward force; F_min/F_max: driveline force range [N].
  DriverCommand update(double dt_s, double v_m_s, double v_target_m_s, double F_ff_N,
                       double F_min_N, double F_max_N);
  double maxBrakeForce() const { return f_brake_max_; }
  bool stopRequested(double v_target_m_s) const { return v_target_m_s <= p_.stop_target_speed_m_s; }

 private:
  DriverParams p_;
  double m_ = 0.0, f_brake_max_ = 0.0;
  Pid pid_;
};

}  // namespace hbt::vehicle
