// The brake torque the 1D engine is expected to publish for the torque requests it received: the
// reference of its torque (fuel) trim, so that the trim corrects the feed-forward's steady error
// and not the engine's response time (controllers.hpp).
//
// The engine's fuel path from a request to the published brake torque (measured, README "Torque
// control"): the fuel command is latched per cylinder at inlet-valve closure and burns about
// TDC, so a request acts after a dead angle θ_d of crank rotation; the published brake torque is
// the mean over one cycle (720°), so the response then ramps over 720°. With the request T_j held
// over each past macro step j (crank angle Δθ_j = ω_j Δt_j), the expected torque at crank angle Θ
// (start of this step) is
//   T_model(Θ) = (1/720°) ∫_{Θ-θ_d-720°}^{Θ-θ_d} T(θ) dθ
// a step response of dead angle θ_d and a linear ramp over 720° (mean delay θ_d + 360°; at 700 rpm
// with θ_d = 200° about 0.13 s, at 1800 rpm 0.05 s). Angles in degrees of crank rotation.
//
// Storage: a ring of the last kCapacity steps (fixed, no allocation). When the history holds less
// than θ_d + 720° (after reset() or with steps below (θ_d + 720°)/kCapacity ≈ 1.8° of crank
// angle) the oldest stored request stands for the older angles.
#pragma once
#include <algorithm>
#include <array>

namespace hbt::engine_1d {

class TorqueResponseModel {
 public:
  static constexpr int kCapacity = 512;

  explicit TorqueResponseModel(double dead_angle_deg = 0.0) : dead_deg_(dead_angle_deg) { reset(0.0); }

  /// Steady state at torque T [Nm]: the whole history holds T.
  void reset(double torque_Nm) {
    n_ = 1;
    head_ = 0;
    ring_[0] = {kWindowDeg + dead_deg_, torque_Nm};
  }
  /// Appends one macro step: crank angle covered [deg] (>= 0) and the request held over it [Nm].
  void push(double dtheta_deg, double torque_Nm) {
    head_ = (head_ + 1) % kCapacity;
    ring_[head_] = {std::max(dtheta_deg, 0.0), torque_Nm};
    n_ = std::min(n_ + 1, kCapacity);
  }
  /// T_model [Nm]: the cycle mean of the requests θ_d before the present crank angle.
  double expected() const {
    double skip = dead_deg_, left = kWindowDeg, sum = 0.0;
    int i = head_;
    for (int k = 0; k < n_ && left > 0.0; ++k) {
      const Entry& e = ring_[i];
      double a = e.dtheta_deg;
      const double s = std::min(skip, a);  // the part of this step inside the dead angle
      skip -= s;
      a -= s;
      const double take = std::min(a, left);
      sum += take * e.torque_Nm;
      left -= take;
      i = (i + kCapacity - 1) % kCapacity;
    }
    if (left > 0.0) sum += left * ring_[(head_ + kCapacity - n_ + 1) % kCapacity].torque_Nm;
    return sum / kWindowDeg;
  }
  double deadAngle() const { return dead_deg_; }

 private:
  static constexpr double kWindowDeg = 720.0;  // one four-stroke cycle
  struct Entry {
    double dtheta_deg = 0.0, torque_Nm = 0.0;
  };
  std::array<Entry, kCapacity> ring_{};
  double dead_deg_ = 0.0;
  int n_ = 0, head_ = 0;
};

}  // namespace hbt::engine_1d
