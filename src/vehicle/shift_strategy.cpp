#include "vehicle/shift_strategy.hpp"

#include <algorithm>

namespace hbt::vehicle {

double ShiftStrategy::upshiftLine(double p) const {
  p = std::clamp(p, 0.0, 1.0);
  return p_.upshift_speed_low_rad_s + p * (p_.upshift_speed_high_rad_s - p_.upshift_speed_low_rad_s);
}

double ShiftStrategy::downshiftLine(double p) const {
  p = std::clamp(p, 0.0, 1.0);
  return p_.downshift_speed_low_rad_s +
         p * (p_.downshift_speed_high_rad_s - p_.downshift_speed_low_rad_s);
}

GearState ShiftStrategy::downshiftTarget(int g, double w_e) const {
  const double w_new = w_e * r_[g - 2] / r_[g - 1];
  if (g - 1 == 1 && w_new < p_.lockup_min_turbine_speed_rad_s) return {DriveMode::Converter, 1};
  return {DriveMode::Locked, g - 1};
}

GearState ShiftStrategy::decide(const GearState& cur, const ShiftInputs& in) const {
  const int n = static_cast<int>(r_.size());
  const double p = in.accel_pedal;
  if (cur.mode == DriveMode::Neutral) {
    if (!in.start_request) return cur;
    // Lowest gear whose input speed does not exceed the post-downshift limit.
    for (int g = 1; g <= n; ++g) {
      const double w_in = in.output_speed_rad_s * r_[g - 1];
      if (w_in <= p_.max_speed_after_downshift_rad_s) {
        if (g == 1 && w_in < p_.lockup_min_turbine_speed_rad_s) return {DriveMode::Converter, 1};
        return {DriveMode::Locked, g};
      }
    }
    return {DriveMode::Locked, n};
  }
  if (cur.mode == DriveMode::Shifting) return cur;  // no decision during a gear change
  if (p_.neutral_at_stop && in.stopped_and_held) return {DriveMode::Neutral, 0};
  if (cur.mode == DriveMode::Converter) {
    const double w_e = in.engine_speed_rad_s, w_t = in.gearbox_input_speed_rad_s;
    if (w_e > 0.0 && w_t / w_e >= p_.lockup_speed_ratio && w_t >= p_.lockup_min_turbine_speed_rad_s)
      return {DriveMode::Locked, 1};
    return cur;
  }
  // Locked in gear g.
  const int g = cur.gear;
  const double w_e = in.engine_speed_rad_s;
  if (g == 1) {
    if (w_e < p_.unlock_engine_speed_rad_s) return {DriveMode::Converter, 1};
  }
  const bool emergency = w_e < idle_ && g > 1;
  if (in.time_since_shift_s < p_.min_time_between_shifts_s && !emergency) return cur;
  if (emergency) return downshiftTarget(g, w_e);
  if (g < n && w_e >= upshiftLine(p) &&
      w_e * r_[g] / r_[g - 1] >= downshiftLine(p) + p_.hysteresis_rad_s)
    return {DriveMode::Locked, g + 1};
  if (g > 1 && w_e < downshiftLine(p) &&
      w_e * r_[g - 2] / r_[g - 1] <= p_.max_speed_after_downshift_rad_s)
    return downshiftTarget(g, w_e);
  return cur;
}

}  // namespace hbt::vehicle
