// Sliding one-cycle (720 deg crank) average of several signals, for outputs that must not ripple
// with the firing pulses (brake torque, flows, pressures).
//
// The cycle is split in kBins bins of 720/kBins deg. Each bin stores the time integrals
// I_c = integral x_c dt of every channel and its duration; a step (rates x held over dt,
// covering dtheta) is split over the bins it spans in proportion to its crank angle, so a bin
// holds exactly its 720/kBins deg whatever the step length. Impulses (addImpulse) are added to
// the current bin's I_c directly (the engine passes per-step amounts as rates instead: an
// impulse at a step end phase-locks with the bins when steps approach the bin width).
// The window is exactly 720 deg: the current (partial, a deg filled) bin, the kBins-1 complete
// bins before it and the fraction (1 - a/bin) of the oldest bin:
//   <x_c> = sum_bins w_b I_c,b / sum_bins w_b dt_b,   w = 1 except the oldest bin
// i.e. the cycle mean at constant speed (time mean = crank-angle mean; exact up to the rate
// variation inside the oldest bin, which is faded out linearly), a moving average otherwise.
// mean() is O(channels) (running sums, re-summed exactly once per ring). Fixed storage, no
// allocation after construction.
// Time cap (setMaxSpan(S)): a bin also closes after S/kBins seconds, so a cycle slower than S
// (spin-down, cranking, the crank at rest) is averaged over the last S seconds instead: the
// means follow the gas at any speed and relax in time at omega = 0. A bin's fill fraction is
// the larger of its angle and time fractions. Above the speed 720 deg/S the cap never binds
// and the window is the exact cycle mean above.
#pragma once
#include <array>
#include <algorithm>
#include <cmath>
#include <limits>

namespace hbt::engine_1d {

template <int kChannels, int kBins = 144>
class CycleWindow {
 public:
  /// Longest window [s] (> 0; default: none, a pure 720 deg window).
  void setMaxSpan(double seconds) { bin_max_dt_ = seconds / kBins; }
  void reset() {
    for (auto& b : bins_) b = Bin{};
    sum_ = Bin{};
    cur_ = 0;
    angle_in_bin_ = 0.0;
    filled_ = 0;
  }
  /// Adds a step of dt [s] covering dtheta [deg] with channel values x (rates).
  template <class Values>
  void add(double dt, double dtheta, const Values& x) {
    // a step is split over the bins it spans in proportion to its crank angle (steps may be
    // as long as or longer than a bin), so every bin holds exactly its 720/kBins deg
    // (or, with the time cap, over the bins its duration fills)
    double rem = dtheta, rem_t = dt;
    bool timed = false;  // a bin closed by time: the rest of the step is rem_t
    for (;;) {
      const bool by_angle = rem > 0.0 && angle_in_bin_ + rem >= kBinDeg;
      const double t_in = bins_[cur_].dt;
      const bool by_time = rem_t > 0.0 && t_in + rem_t >= bin_max_dt_;
      if (!by_angle && !by_time) break;
      const double fa = by_angle ? (kBinDeg - angle_in_bin_) / rem : 2.0;
      const double ft = by_time ? (bin_max_dt_ - t_in) / rem_t : 2.0;
      if (fa <= ft) {
        const double part = kBinDeg - angle_in_bin_;
        const double tp = timed ? rem_t * fa : dt * part / dtheta;
        accumulate(tp, x);
        rem -= part;
        rem_t -= tp;
      } else {
        const double tp = std::max(0.0, bin_max_dt_ - t_in);
        accumulate(tp, x);
        rem -= rem * ft;
        rem_t -= tp;
        timed = true;
      }
      angle_in_bin_ = 0.0;
      nextBin();
    }
    accumulate(timed ? rem_t : dtheta > 0.0 ? dt * rem / dtheta : dt, x);
    angle_in_bin_ += rem;
  }
  /// Impulse: adds amount q (integral units) to channel c of the current bin.
  void addImpulse(int c, double q) {
    bins_[cur_].I[c] += q;
    sum_.I[c] += q;
  }
  /// Cycle means of every channel (0 if nothing accumulated); O(kChannels): running sums over
  /// all stored bins minus the part of the oldest bin outside the window.
  template <class Out>
  void mean(Out& out) const {
    const Bin& o = bins_[(cur_ + 1) % kStore];
    // outside fraction of the oldest bin: the current bin's fill (angle or, capped, time)
    const double cut =
        std::min(1.0, std::max(angle_in_bin_ / kBinDeg, bins_[cur_].dt / bin_max_dt_));
    const double T = sum_.dt - cut * o.dt;
    for (int c = 0; c < kChannels; ++c) out[c] = T > 0.0 ? (sum_.I[c] - cut * o.I[c]) / T : 0.0;
  }
  bool fullCycle() const { return filled_ >= kBins; }

 private:
  static constexpr double kBinDeg = 720.0 / kBins;
  static constexpr int kStore = kBins + 1;
  struct Bin {
    double dt = 0.0;
    std::array<double, kChannels> I{};
  };
  template <class Values>
  void accumulate(double f, const Values& x) {
    Bin& b = bins_[cur_];
    b.dt += f;
    sum_.dt += f;
    for (int c = 0; c < kChannels; ++c) {
      const double q = x[c] * f;
      b.I[c] += q;
      sum_.I[c] += q;
    }
  }
  void nextBin() {
    cur_ = (cur_ + 1) % kStore;
    if (filled_ < kBins) ++filled_;
    Bin& b = bins_[cur_];
    if (cur_ == 0) {  // once per ring: exact re-summation (no drift of the running sums)
      b = Bin{};
      sum_ = Bin{};
      for (const Bin& k : bins_) {
        sum_.dt += k.dt;
        for (int c = 0; c < kChannels; ++c) sum_.I[c] += k.I[c];
      }
      return;
    }
    sum_.dt -= b.dt;
    for (int c = 0; c < kChannels; ++c) sum_.I[c] -= b.I[c];
    b = Bin{};
  }
  std::array<Bin, kStore> bins_{};
  Bin sum_{};
  int cur_ = 0, filled_ = 0;
  double angle_in_bin_ = 0.0;
  double bin_max_dt_ = std::numeric_limits<double>::infinity();  // time cap of a bin [s]
};

}  // namespace hbt::engine_1d
