// BSFC validation region (config engine_1d/validation, steady_point.hpp): the corners and the
// centre of the region as the 189-point check samples it (>= 1100 rpm, >= 35 % load: its lowest
// grid load in the region is 37 %; up to 2450 rpm / full load) run to steady state with the
// steady tool's own procedure, each within the region's max target (8 %) of the reference map.
// (Exactly at 35 % / 2450 rpm the error is +8.75 %: engine_1d README, open points.) Points
// outside are classified with their reason.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "engine_1d/steady_point.hpp"
#include "support.hpp"

using namespace hbt::engine_1d;
using namespace hbt::engine_1d::test;

TEST(Engine1DBsfcRegion, RegionLimitsComeFromConfigAndFlagTheRest) {
  const Engine1DParams& p = defaultParams();
  EXPECT_DOUBLE_EQ(p.engine.validation_min_speed_rpm, 1100.0);
  EXPECT_DOUBLE_EQ(p.engine.validation_min_load, 0.35);
  const BsfcValidationRegion r{p.engine.validation_min_speed_rpm, p.engine.validation_min_load};
  std::string why;
  EXPECT_TRUE(r.contains(1100.0, 0.35, &why));
  EXPECT_TRUE(why.empty());
  EXPECT_FALSE(r.contains(875.0, 1.0, &why));
  EXPECT_NE(why.find("below 1100 rpm"), std::string::npos) << why;
  EXPECT_FALSE(r.contains(2450.0, 0.325, &why));
  EXPECT_NE(why.find("below 35 % load"), std::string::npos) << why;
}

TEST(Engine1DBsfcRegion, CornersAndCentreWithinMaxTarget) {
  const Engine1DParams& p0 = defaultParams();
  Engine1DParams p = p0;
  p.turbo.shaft.inertia_kg_m2 *= 0.25;  // as the steady tool: steady state independent of J
  const double target_max_pct = 8.0;
  const struct { double rpm, load; } pts[] = {
      {1100.0, 0.37}, {2450.0, 0.37}, {1100.0, 1.0}, {2450.0, 1.0}, {1775.0, 0.685}};
  double sum = 0.0;
  for (const auto& q : pts) {
    Engine1D e(p, repoRoot());
    const double w = q.rpm * kRpm, treq = q.load * e.fullLoadTorque(w);
    e.reset(w, treq);
    const SteadyPointResult r = runSteadyPoint(e, q.rpm, treq);
    std::printf("%6.0f rpm %3.0f %% (%6.1f Nm): BSFC %6.1f vs map %6.1f g/kWh (%+5.2f %%), lambda %.2f, "
                "NOx %.2f g/kWh, %s after %.1f s (cpu %.2f s)\n",
                q.rpm, 100 * q.load, treq, r.bsfc_g_kWh, r.bsfc_ref_g_kWh, r.bsfc_err_pct,
                r.mean.lambda, r.nox_g_kWh, r.converged ? "converged" : "NOT converged", r.sim_s,
                r.cpu_s);
    EXPECT_TRUE(r.converged) << q.rpm << " rpm " << q.load;
    EXPECT_NEAR(r.mean.brake_torque_Nm, treq, std::max(0.01 * treq, 3.0));
    EXPECT_LT(std::fabs(r.bsfc_err_pct), target_max_pct) << q.rpm << " rpm " << q.load;
    sum += std::fabs(r.bsfc_err_pct);
  }
  std::printf("mean |e| of the 5 points: %.2f %%\n", sum / 5.0);
}
