// Step means from cumulative totals (common/step_mean.hpp): exact where the totals resolve the
// step, 0 / "not resolved" where rounding is all that is left, against hand sums and the totals
// an engine spinning down actually published.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>

#include "common/step_mean.hpp"

namespace hbt {

TEST(StepMean, MeanRateIsTheMeanOfTheIntegratedValues) {
  double S = 1234.5, S0 = S;  // a total that already holds something
  double sum = 0.0;
  for (int i = 0; i < 10; ++i) {  // ten 10 ms values
    const double x = 40e3 + 1e3 * i;
    S += x * 0.01;
    sum += x;
  }
  EXPECT_NEAR(meanRate(S, S0, 0.1), sum / 10.0, 1e-9 * sum);
  EXPECT_NEAR(meanRate(S0, S, 0.1), -sum / 10.0, 1e-9 * sum);  // signed (a negative heat flow)
}

TEST(StepMean, AnUnmovedTotalGivesExactlyZero) {
  EXPECT_EQ(meanRate(64.6, 64.6, 0.1), 0.0);
  EXPECT_EQ(meanRate(0.0, 0.0, 0.1), 0.0);
}

TEST(StepMean, ADifferenceWithinRoundingIsNotResolved) {
  const double S = 1e9;  // e.g. joules into the coolant after a long mission
  const double ulp = S * DBL_EPSILON;
  EXPECT_EQ(resolvedDifference(S + 8 * ulp, S), 0.0);
  EXPECT_GT(totalDifferenceBound(S, S), 8 * ulp);
  const double far = S + 1e3 * ulp;
  EXPECT_EQ(resolvedDifference(far, S), far - S);
}

TEST(StepMean, WeightedMeanOfAResolvedFlowIsExact) {
  // 0.05 kg/s at 600 K for 0.05 s, then 0.15 kg/s at 700 K for 0.05 s, on top of large totals
  double M = 65.0, A = 35000.0;
  const double M0 = M, A0 = A;
  M += 0.05 * 0.05 + 0.15 * 0.05;
  A += 0.05 * 600.0 * 0.05 + 0.15 * 700.0 * 0.05;
  const WeightedMean w = weightedMean(A, A0, M, M0);
  ASSERT_TRUE(w.resolved);
  EXPECT_NEAR(w.value, (0.05 * 600.0 + 0.15 * 700.0) / 0.2, 1e-6);
}

TEST(StepMean, AFractionOfZeroIsResolvedAsZero) {
  // CO2 in the air an unfired engine pumps: its total does not move while the flow does
  const WeightedMean w = weightedMean(12.0, 12.0, 65.0 + 0.004, 65.0);
  EXPECT_TRUE(w.resolved);
  EXPECT_EQ(w.value, 0.0);
}

TEST(StepMean, TheSpinDownTotalsAreNotAWeightedMean) {
  // /engine/exhaust of hybrid_urban at 40 degC, t = 801.79 s and 801.89 s (engine stopped at a
  // bus stop, flow ~1e-12 kg/s): the mass total still moves, the mass x temperature total no
  // longer does -- a ratio of 0 K. It is reported as not resolved.
  const double M_prev = 64.619605426301916, M_now = 64.619605426302059;
  const double A_prev = 35475.835318874568, A_now = 35475.835318874568;
  const WeightedMean w = weightedMean(A_now, A_prev, M_now, M_prev);
  EXPECT_FALSE(w.resolved);
  // the time mean of the published temperature stays what it was: 313.15 K
  EXPECT_NEAR(meanRate(390045.47771176184, 390014.16271176166, 0.1), 313.15, 1e-6);
}

TEST(StepMean, NoFlowIsNotAWeightedMean) {
  EXPECT_FALSE(weightedMean(35000.0, 35000.0, 65.0, 65.0).resolved);
  EXPECT_FALSE(weightedMean(35000.0, 35000.0, 64.0, 65.0).resolved);  // a total that fell
  EXPECT_FALSE(weightedMean(NAN, 1.0, 65.1, 65.0).resolved);
}

}  // namespace hbt
