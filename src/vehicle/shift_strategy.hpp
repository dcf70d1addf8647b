// Shift and lock-up logic of the 6-speed automatic (APT-S, ZF EcoLife-like), evaluated once
// per macro step. Drive modes: N (neutral), 1C (gear 1, torque converter open), gL (gear g,
// lock-up closed; g = 1..6). Following VECTO's AT-S gear sequence (1C -> 1L -> 2L ...; the
// converter is used in 1st gear only since i_1/i_2 = 1.76 < 1.85).
//
// Engine-speed shift lines interpolated in accelerator pedal p ∈ [0, 1] (load dependence):
//   ω_up(p)   = ω_up,0 + p (ω_up,1 - ω_up,0),   ω_down(p) = ω_down,0 + p (ω_down,1 - ω_down,0)
// gL -> (g+1)L  if ω_e >= ω_up(p) and ω_e i_{g+1}/i_g >= ω_down(p) + hysteresis
// gL -> (g-1)   if ω_e <  ω_down(p) and ω_e i_{g-1}/i_g <= ω_max,after;
//               into 1C instead of 1L if the new turbine speed < lock-up minimum
// (both only after min_time_between_shifts; a downshift below idle speed ignores the timer).
// 1C -> 1L if ν = ω_t/ω_e >= ν_lock and ω_t >= ω_t,lock;  1L -> 1C if ω_e < ω_unlock.
// N at standstill while the driver holds the bus for a stop (neutral_at_stop); N -> 1C on a
// start request (or the lowest suitable gear if rolling).
#pragma once
#include <vector>

#include "vehicle/vehicle_params.hpp"

namespace hbt::vehicle {

// Shifting: clutch-to-clutch change into `gear` in progress (slip phase, see vehicle_model.hpp).
enum class DriveMode { Neutral = 0, Converter = 1, Locked = 2, Shifting = 3 };

struct GearState {
  DriveMode mode = DriveMode::Neutral;
  int gear = 0;  // 0 in neutral, 1..n otherwise
  bool operator==(const GearState& o) const { return mode == o.mode && gear == o.gear; }
  bool operator!=(const GearState& o) const { return !(*this == o); }
};

// Time since the last gear change [s] before the first one: longer than any minimum time
// between shifts (no shift yet).
constexpr double kNoShiftYet_s = 1e9;

struct ShiftInputs {
  double engine_speed_rad_s = 0.0;
  double gearbox_input_speed_rad_s = 0.0;  // turbine speed in 1C; = engine speed when locked
  double output_speed_rad_s = 0.0;         // gearbox output speed (wheel speed · axle ratio)
  double accel_pedal = 0.0;                // [0, 1]
  double time_since_shift_s = kNoShiftYet_s;
  bool stopped_and_held = false;           // v = 0 and the driver holds for a stop
  bool start_request = false;              // the driver wants to move
};

class ShiftStrategy {
 public:
  ShiftStrategy() = default;
  ShiftStrategy(const ShiftParams& p, std::vector<double> ratios, double idle_speed_rad_s)
      : p_(p), r_(std::move(ratios)), idle_(idle_speed_rad_s) {}
  GearState decide(const GearState& cur, const ShiftInputs& in) const;
  double upshiftLine(double pedal) const;
  double downshiftLine(double pedal) const;

 private:
  GearState downshiftTarget(int g, double w_e) const;
  ShiftParams p_;
  std::vector<double> r_;
  double idle_ = 0.0;
};

}  // namespace hbt::vehicle
