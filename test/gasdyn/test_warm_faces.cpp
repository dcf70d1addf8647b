// Warm-started face solvers (characteristics.hpp: warmDemandOutflowFace, warmDemandInflowFace,
// WarmStart) against the cold bracketing solvers on a sequence of changing pipe-end states (a
// pressure wave at a nozzle, as at a valve every time step): the same face within the warm
// tolerance, the face's mass flow equal to the nozzle's demand at the face state (the boundary
// condition itself), and the kept residual slope and the extrapolated first point saving
// evaluations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gasdyn/characteristics.hpp"
#include "gasdyn/gas.hpp"

using namespace hbt::gasdyn;

namespace {
const hbt::PerfectGas kExhaust{1.33, 287.0};
constexpr double kPipeArea = 1e-3, kNozzleArea = 6e-4;  // [m^2]
constexpr int kSteps = 200;

// End state k of the sequence: p = 2 bar +- 0.5 bar (a 50-step wave), 800 K, gas moving toward
// the end at 20 m/s (u_in < 0).
EndState endState(int k) {
  const double p = 2e5 + 0.5e5 * std::sin(2.0 * M_PI * k / 50.0), T = 800.0;
  return {p / (kExhaust.R * T), -20.0, p, kPipeArea};
}
}  // namespace

TEST(WarmFaces, OutflowMatchesTheColdSolverAndTheNozzle) {
  const double pv = 1.2e5;  // downstream static pressure [Pa]
  long evals = 0;
  auto nozzle = [&](double p0, double T0) {
    ++evals;
    return nozzleMassFlow(kExhaust, kNozzleArea, p0, T0, pv);
  };
  WarmStart ws;
  for (int k = 0; k < kSteps; ++k) {
    const EndState s = endState(k);
    const double hi = detail::Wave(kExhaust, s).wSonic();
    const FaceState cold = demandOutflowFace(kExhaust, s, nozzle);
    const FaceState warm = warmDemandOutflowFace(kExhaust, s, nozzle, ws);
    EXPECT_NEAR(warm.u_in, cold.u_in, 2.0 * detail::kWarmTolerance * hi) << k;
    double p0, T0;
    stagnation(kExhaust, warm, p0, T0);
    const double m = -warm.mdot_in(kPipeArea), demand = nozzleMassFlow(kExhaust, kNozzleArea, p0, T0, pv);
    ASSERT_GT(m, 0.0) << k;
    EXPECT_NEAR(m / demand, 1.0, 1e-5) << k;
  }
}

TEST(WarmFaces, InflowMatchesTheColdSolverAndTheNozzle) {
  const double pv = 3e5, Tv = 900.0;  // upstream gas at rest [Pa], [K]
  auto nozzle = [&](double pb) {
    return Supply{nozzleMassFlow(kExhaust, kNozzleArea, pv, Tv, pb), Tv};
  };
  WarmStart ws;
  for (int k = 0; k < kSteps; ++k) {
    const EndState s = endState(k);
    const FaceState cold = demandInflowFace(kExhaust, s, nozzle);
    const FaceState warm = warmDemandInflowFace(kExhaust, s, nozzle, ws);
    const double us = std::sqrt(2.0 * kExhaust.gamma * kExhaust.R * Tv / (kExhaust.gamma + 1.0));
    EXPECT_NEAR(warm.u_in, cold.u_in, 2.0 * detail::kWarmTolerance * us) << k;
    ASSERT_GT(warm.u_in, 0.0) << k;
    EXPECT_NEAR(warm.mdot_in(kPipeArea) / nozzle(warm.p).mdot, 1.0, 1e-5) << k;
  }
}

TEST(WarmFaces, TheKeptSlopeAndTheExtrapolatedStartSaveEvaluations) {
  // The same sequence solved with the full warm start, with the root before the last forgotten
  // before every call (first point = the last root), with the slope forgotten too (second point
  // then x0 -/+ 2 %), and cold: evaluations of the demand per solve.
  const double pv = 1.2e5;
  long evals = 0;
  auto nozzle = [&](double p0, double T0) {
    ++evals;
    return nozzleMassFlow(kExhaust, kNozzleArea, p0, T0, pv);
  };
  auto perSolve = [&](int mode) {  // 0 full, 1 no extrapolation, 2 neither, 3 cold
    WarmStart ws;
    evals = 0;
    for (int k = 0; k < kSteps; ++k) {
      const EndState s = endState(k);
      if (mode >= 1) ws.x_before = 0.0;
      if (mode == 2) ws.slope = 0.0;
      if (mode == 3) demandOutflowFace(kExhaust, s, nozzle);
      else warmDemandOutflowFace(kExhaust, s, nozzle, ws);
    }
    return static_cast<double>(evals) / kSteps;
  };
  const double full = perSolve(0), last = perSolve(1), neither = perSolve(2), cold = perSolve(3);
  std::printf("[warm faces] evaluations per solve: extrapolated %.2f, last root %.2f, "
              "no slope %.2f, cold %.2f\n", full, last, neither, cold);
  EXPECT_LT(full, 0.95 * last);
  EXPECT_LT(last, 0.95 * neither);
  EXPECT_LT(neither, cold);
}

TEST(WarmFaces, TheExtrapolatedStartIsTheLinearTrendInsideTheBounds) {
  WarmStart ws;
  EXPECT_EQ(ws.guess(300.0), 0.0);  // nothing known: no guess (the solver starts cold)
  ws.setRoot(100.0);
  EXPECT_EQ(ws.guess(300.0), 100.0);  // one root: itself
  ws.setRoot(110.0);
  EXPECT_EQ(ws.x_before, 100.0);
  EXPECT_EQ(ws.guess(300.0), 120.0);  // two roots: their linear trend
  EXPECT_EQ(ws.guess(115.0), 110.0);  // a trend past the sonic bound: the last root
  ws.setRoot(5.0);
  EXPECT_EQ(ws.guess(300.0), 5.0);    // a trend below zero: the last root
}
