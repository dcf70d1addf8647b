// Discrete PID controller with output limits and conditional-integration anti-windup.
//
//   u = kp*e + ki*∫e dt + kd*de/dt,   clamped to [u_min, u_max];
// the integral is frozen while the output is saturated and the error drives it further out.
// Units are those of the loop (e.g. e in m/s and u as pedal fraction [-]).
#pragma once
#include <algorithm>

namespace hbt {

// Output limit [output unit] that never binds: the default of an unlimited controller.
constexpr double kPidUnlimited = 1e300;

struct PidGains {
  double kp = 0.0, ki = 0.0, kd = 0.0;
  double u_min = -kPidUnlimited, u_max = kPidUnlimited;
};

class Pid {
 public:
  Pid() = default;
  explicit Pid(const PidGains& g) : g_(g) {}
  void reset(double integral = 0.0) { i_ = integral; first_ = true; }
  /// One update with error e over dt_s [s]; feedforward u_ff is added before clamping.
  double update(double e, double dt_s, double u_ff = 0.0) {
    const double d = first_ || dt_s <= 0.0 ? 0.0 : (e - e_prev_) / dt_s;
    first_ = false;
    e_prev_ = e;
    const double i_new = i_ + e * dt_s;
    const double u_trial = u_ff + g_.kp * e + g_.ki * i_new + g_.kd * d;
    const bool sat_hi = u_trial > g_.u_max && e > 0.0;
    const bool sat_lo = u_trial < g_.u_min && e < 0.0;
    if (!(sat_hi || sat_lo)) i_ = i_new;
    const double u = u_ff + g_.kp * e + g_.ki * i_ + g_.kd * d;
    return std::clamp(u, g_.u_min, g_.u_max);
  }
  double integral() const { return i_; }
  const PidGains& gains() const { return g_; }

 private:
  PidGains g_;
  double i_ = 0.0, e_prev_ = 0.0;
  bool first_ = true;
};

}  // namespace hbt
