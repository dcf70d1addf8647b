// Wall-time statistics of many short steps (the FMU participant's step and its FMU's doStep,
// src/fmi/node): each duration [s] goes into a histogram of kBin_s = 10 ns bins up to
// kRange_s = 100 us (one overflow bin above) and into a sum.
//   mean   = sum / n: what the lock-step's compute time counts (a step preempted by another
//            process on a shared machine included);
//   median = the centre of the bin in which the cumulative count first reaches n / 2 (+inf when
//            that is the overflow bin): the typical step, which preemption of a few steps does
//            not move; resolution kBin_s.
// Plain data, no clock of its own (the caller measures); deterministic for given durations.
#pragma once
#include <vector>

namespace hbt::fmi {

class StepTiming {
 public:
  static constexpr double kBin_s = 10e-9;
  static constexpr double kRange_s = 100e-6;

  StepTiming();
  /// One step's duration [s]; a negative one counts as 0.
  void add(double duration_s);
  long count() const { return n_; }
  double sum_s() const { return sum_s_; }
  /// NaN without steps.
  double mean_s() const;
  double median_s() const;

 private:
  std::vector<long> bins_;  // kRange_s / kBin_s bins, then the overflow bin
  long n_ = 0;
  double sum_s_ = 0.0;
};

}  // namespace hbt::fmi
