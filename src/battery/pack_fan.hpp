// Thermostat of the pack's ventilation fans: on/off with hysteresis on the cell temperature.
// ROS-free, deterministic.
//
//   on  when T_cell >= T_on,   off when T_cell <= T_off   (T_off < T_on; in between the state holds)
//   P_fan = P_rated when on, else 0   [W], drawn from the 48 V bus through the pack's terminals
//
// On/off rather than proportional: the fans of a small low-voltage pack are switched at one speed
// by the BMS; their flow is then the fixed operating point of pack_ventilation.hpp (a speed-
// controlled law would need the fan curve at every duty and the cells' h versus flow, not sourced). The hysteresis band keeps the fan from chattering at the 0.01 s step.
// The decision is taken on the cell temperature at the start of a step and held over it.
#pragma once

namespace hbt::battery {

struct PackFanParams {
  double rated_power_W = 6.0;   // electric power when on [W]
  double on_K = 308.15;         // switches on at and above [K]
  double off_K = 303.15;        // switches off at and below [K]
};

class PackFan {
 public:
  explicit PackFan(const PackFanParams& p) : p_(p) {}
  void reset(double cell_T_K) { on_ = cell_T_K >= p_.on_K; }
  /// Updates the on/off state for a step starting at cell temperature T_K; returns it.
  bool update(double cell_T_K) {
    if (cell_T_K >= p_.on_K) on_ = true;
    else if (cell_T_K <= p_.off_K) on_ = false;
    return on_;
  }
  bool on() const { return on_; }
  double power_W() const { return on_ ? p_.rated_power_W : 0.0; }

 private:
  PackFanParams p_;
  bool on_ = false;
};

}  // namespace hbt::battery
