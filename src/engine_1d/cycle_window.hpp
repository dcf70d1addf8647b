// Sliding one-cycle (720 deg crank) average of several signals, for outputs that must not ripple
// with the firing pulses (brake torque, flows, pressures).
//
// The cycle is split in kBins bins of 720/kBins deg. Each bin stores the time integrals
// I_c = integral x_c dt of every channel and its duration; impulses (a mass released at one
// instant, e.g. fuel at injection, NOx at exhaust-valve opening) are added to I_c directly.
// The window is exactly 720 deg: the current (partial, a deg filled) bin, the kBins-1 complete
// bins before it and the fraction (1 - a/bin) of the oldest bin:
//   <x_c> = sum_bins w_b I_c,b / sum_bins w_b dt_b,   w = 1 except the oldest bin
// i.e. the cycle mean at constant speed (time mean = crank-angle mean; impulses in the oldest
// bin are faded out linearly, so the mean does not jump when an injection leaves the window),
// a moving average otherwise. Fixed storage, no allocation after construction.
#pragma once
#include <array>
#include <cmath>

namespace hbt::engine1d {

template <int kChannels, int kBins = 144>
class CycleWindow {
 public:
  void reset() {
    for (auto& b : bins_) b = Bin{};
    cur_ = 0;
    angle_in_bin_ = 0.0;
    filled_ = 0;
  }
  /// Adds a step of dt [s] covering dtheta [deg] with channel values x (rates).
  template <class Values>
  void add(double dt, double dtheta, const Values& x) {
    Bin& b = bins_[cur_];
    b.dt += dt;
    for (int c = 0; c < kChannels; ++c) b.I[c] += x[c] * dt;
    angle_in_bin_ += dtheta;
    while (angle_in_bin_ >= kBinDeg) {
      angle_in_bin_ -= kBinDeg;
      cur_ = (cur_ + 1) % kStore;
      if (filled_ < kBins) ++filled_;
      bins_[cur_] = Bin{};
    }
  }
  /// Impulse: adds amount q (integral units) to channel c of the current bin.
  void addImpulse(int c, double q) { bins_[cur_].I[c] += q; }
  /// Cycle means of every channel (0 if nothing accumulated).
  template <class Out>
  void mean(Out& out) const {
    double T = 0.0;
    std::array<double, kChannels> s{};
    const int oldest = (cur_ + 1) % kStore;
    const double w_old = 1.0 - angle_in_bin_ / kBinDeg;
    for (int k = 0; k < kStore; ++k) {
      const Bin& b = bins_[k];
      const double w = k == oldest ? w_old : 1.0;
      T += w * b.dt;
      for (int c = 0; c < kChannels; ++c) s[c] += w * b.I[c];
    }
    for (int c = 0; c < kChannels; ++c) out[c] = T > 0.0 ? s[c] / T : 0.0;
  }
  bool fullCycle() const { return filled_ >= kBins; }

 private:
  static constexpr double kBinDeg = 720.0 / kBins;
  static constexpr int kStore = kBins + 1;
  struct Bin {
    double dt = 0.0;
    std::array<double, kChannels> I{};
  };
  std::array<Bin, kStore> bins_{};
  int cur_ = 0, filled_ = 0;
  double angle_in_bin_ = 0.0;
};

}  // namespace hbt::engine1d
