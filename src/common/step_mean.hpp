// Means over a consumer's macro step from the cumulative totals its producers publish.
//
// A producer stepping every h integrates its step outputs into running sums S(t) = Σ x h; a
// consumer stepping every P = k h takes the mean of x over its step as x̄ = ΔS / P with
// ΔS = S(t) - S(t - P): exact, no aliasing of the h-rate signal. What limits it, and the defined
// answer for each case:
//
//  rounding   S is a running sum of rounded doubles and ΔS the difference of two of them, so ΔS
//             carries an absolute error of a few ulp of |S|, bounded here by
//               δS = kTotalRoundingUlps · ε · max(|S(t)|, |S(t - P)|)        (ε = DBL_EPSILON)
//             (half an ulp per addition for up to 126 additions per step, one for the
//             difference). |ΔS| <= δS is not resolved: nothing the totals can show flowed or
//             accumulated, and the mean is 0 exactly (resolvedDifference, meanRate).
//  weighting  a flow-weighted mean ȳ = ΔA / ΔM (A = ∫ṁ y dt, M = ∫ṁ dt: the exhaust
//             temperature, a mass fraction) is a ratio of two such differences; its error is at
//             most (δA + |ȳ| δM) / ΔM. It is resolved where that is at most
//             kWeightedMeanRelTol · max(|ȳ|, 1) (relative for a temperature, absolute for a
//             fraction). Below, the step carried too little flow to weight anything: the engine
//             is stopped or spinning down (its flow decays through 1e-12 kg/s, where Σṁ h still
//             grows but ΣṁT h no longer does: a "mean" of 0 K). The consumer then takes the
//             no-flow value its producer defines (the time mean of the published temperature;
//             the composition of the sample), never the ratio (weightedMean).
#pragma once
#include <algorithm>
#include <cfloat>
#include <cmath>

namespace hbt {

constexpr double kTotalRoundingUlps = 64.0;   // [-] ulps of a total bounding the error of ΔS
constexpr double kWeightedMeanRelTol = 1e-6;  // [-] largest accepted error of a weighted mean

/// Bound of the rounding error of now - prev, two samples of a running total [its unit].
inline double totalDifferenceBound(double now, double prev) {
  return kTotalRoundingUlps * DBL_EPSILON * std::max(std::fabs(now), std::fabs(prev));
}

/// now - prev, or 0 where the difference is within its rounding bound (not resolved).
inline double resolvedDifference(double now, double prev) {
  const double d = now - prev;
  return std::fabs(d) > totalDifferenceBound(now, prev) ? d : 0.0;
}

/// Mean rate of a total over a step of dt_s [s] (> 0): resolvedDifference / dt [unit/s].
inline double meanRate(double now, double prev, double dt_s) {
  return resolvedDifference(now, prev) / dt_s;
}

/// A flow-weighted mean ΔA/ΔM and whether it is resolved (header: weighting).
struct WeightedMean {
  double value = 0.0;     // ΔA / ΔM (0 where ΔM <= 0)
  bool resolved = false;  // error bound <= kWeightedMeanRelTol · max(|value|, 1)
};

/// The weighted mean of A over M between two samples (now, prev) of both totals.
inline WeightedMean weightedMean(double A_now, double A_prev, double M_now, double M_prev) {
  WeightedMean w;
  const double dM = M_now - M_prev;
  if (!(dM > 0.0)) return w;
  w.value = (A_now - A_prev) / dM;
  const double error = (totalDifferenceBound(A_now, A_prev) +
                        std::fabs(w.value) * totalDifferenceBound(M_now, M_prev)) / dM;
  w.resolved = std::isfinite(w.value) &&
               error <= kWeightedMeanRelTol * std::max(std::fabs(w.value), 1.0);
  return w;
}

}  // namespace hbt
