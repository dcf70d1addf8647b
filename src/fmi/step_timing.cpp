#include "fmi/step_timing.hpp"

#include <cmath>
#include <limits>

namespace hbt::fmi {

namespace {
constexpr long kBins = static_cast<long>(StepTiming::kRange_s / StepTiming::kBin_s + 0.5);
}

StepTiming::StepTiming() : bins_(static_cast<std::size_t>(kBins) + 1, 0) {}

void StepTiming::add(double duration_s) {
  const double d = duration_s > 0.0 ? duration_s : 0.0;
  const double b = std::floor(d / kBin_s);
  ++bins_[b < static_cast<double>(kBins) ? static_cast<std::size_t>(b) : static_cast<std::size_t>(kBins)];
  ++n_;
  sum_s_ += d;
}

double StepTiming::mean_s() const {
  return n_ > 0 ? sum_s_ / static_cast<double>(n_) : std::numeric_limits<double>::quiet_NaN();
}

double StepTiming::median_s() const {
  if (n_ == 0) return std::numeric_limits<double>::quiet_NaN();
  long cumulative = 0;
  for (long i = 0; i < kBins; ++i) {
    cumulative += bins_[static_cast<std::size_t>(i)];
    if (2 * cumulative >= n_) return (static_cast<double>(i) + 0.5) * kBin_s;
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace hbt::fmi
