// StepTiming (src/fmi/step_timing.hpp) against values computed here by hand: the mean is the
// arithmetic mean of what was added; the median is the middle value to the bin's resolution
// (10 ns), unmoved by a few huge outliers (preempted steps) that move the mean; empty: NaN.
#include <gtest/gtest.h>

#include <cmath>

#include "fmi/step_timing.hpp"

namespace hbt::fmi {
namespace {

TEST(StepTiming, MeanIsTheArithmeticMeanMedianTheMiddleValue) {
  StepTiming s;
  for (double us : {1.0, 2.0, 3.0, 4.0, 100.0}) s.add(us * 1e-6);  // 100 us: the overflow bin
  EXPECT_EQ(s.count(), 5);
  EXPECT_NEAR(s.sum_s(), 110e-6, 1e-18);
  EXPECT_NEAR(s.mean_s(), 22e-6, 1e-18);
  EXPECT_NEAR(s.median_s(), 3e-6, StepTiming::kBin_s);  // the centre of the bin holding 3 us
}

TEST(StepTiming, PreemptedStepsMoveTheMeanNotTheMedian) {
  StepTiming s;
  for (int i = 0; i < 1000; ++i) s.add(2.5e-6);
  for (int i = 0; i < 5; ++i) s.add(4e-3);  // five steps preempted for 4 ms (a scheduler tick)
  EXPECT_NEAR(s.mean_s(), (1000 * 2.5e-6 + 5 * 4e-3) / 1005.0, 1e-15);
  EXPECT_GT(s.mean_s(), 8 * 2.5e-6);
  EXPECT_NEAR(s.median_s(), 2.5e-6, StepTiming::kBin_s);
}

TEST(StepTiming, EmptyIsNanAndMostlyOverflowIsInfinite) {
  StepTiming s;
  EXPECT_TRUE(std::isnan(s.mean_s()));
  EXPECT_TRUE(std::isnan(s.median_s()));
  s.add(-1e-9);  // a clock that went backwards counts as 0
  EXPECT_NEAR(s.median_s(), 5e-9, 1e-15);
  for (int i = 0; i < 3; ++i) s.add(1.0);
  EXPECT_TRUE(std::isinf(s.median_s()));
}

}  // namespace
}  // namespace hbt::fmi
