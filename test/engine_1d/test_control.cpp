// Controllers: the torque PID reaches a requested torque, the wastegate PID reaches the boost
// target, and a load step shows turbo lag (1D torque rise slower than the map engine's PT1).
#include <gtest/gtest.h>

#include <cstdio>

#include "support.hpp"

using namespace hbt::engine1d;
using namespace hbt::engine1d::test;

TEST(Engine1DControl, TorquePidReachesRequestAfterAChange) {
  Engine1D e(defaultParams(), repoRoot());
  const double rpm = 1800.0, w = rpm * kRpm;
  e.reset(w, 400.0);
  run(e, rpm, 400.0, 1.5);
  const Engine1DOutputs& o = run(e, rpm, 650.0, 2.0);
  std::printf("torque PID: request 650 Nm -> %.1f Nm after 2 s (fuel %.2f mg/cyc, ff %.2f mg, "
              "lambda %.2f)\n", o.brake_torque_Nm, o.fuel_per_cycle_kg * 1e6,
              e.command().feedforward_kg * 1e6, o.lambda);
  EXPECT_NEAR(o.brake_torque_Nm, 650.0, 6.5);
  EXPECT_FALSE(o.smoke_limited);
  // the PID trims the feed-forward: the trim is not zero (1D efficiency differs from the map)
  EXPECT_GT(std::fabs(o.fuel_per_cycle_kg - e.command().feedforward_kg), 0.0);
}

TEST(Engine1DControl, WastegatePidReachesBoostTarget) {
  Engine1D e(defaultParams(), repoRoot());
  const double rpm = 2000.0, w = rpm * kRpm, T = 0.6 * e.fullLoadTorque(w);
  e.reset(w, T);
  const Engine1DOutputs& o = run(e, rpm, T, 3.0);
  std::printf("boost PID at %.0f rpm / %.0f Nm: boost %.0f Pa, target %.0f Pa, wastegate %.3f, "
              "turbo %.0f rpm\n", rpm, T, o.boost_pressure_Pa, o.boost_target_Pa,
              o.wastegate_opening, o.turbo_speed_rad_s / kRpm);
  EXPECT_NEAR(o.boost_pressure_Pa / o.boost_target_Pa, 1.0, 0.02);
  EXPECT_GT(o.wastegate_opening, 0.0);  // controlling, not saturated
  EXPECT_LT(o.wastegate_opening, 1.0);
}

TEST(Engine1DControl, LoadStepShowsTurboLagAgainstMapEngine) {
  const Engine1DParams& p = defaultParams();
  Engine1D e(p, repoRoot());
  hbt::engine_map::MapEngine m(p.reference, repoRoot());
  const double rpm = 1200.0, w = rpm * kRpm, T0 = 200.0, T1 = e.fullLoadTorque(w);
  e.reset(w, T0);
  run(e, rpm, T0, 2.0);
  m.reset(w, T0);
  Engine1DInputs in;
  in.speed_rad_s = w;
  in.torque_request_Nm = T1;
  hbt::engine_map::MapEngineInputs mi;
  mi.speed_rad_s = w;
  mi.torque_request_Nm = T1;
  const double dt = 0.01, target = T0 + 0.9 * (T1 - T0);
  double t90_1d = -1, t90_map = -1, Tb = 0;
  for (int i = 1; i <= 600; ++i) {
    Tb = e.step(dt, in).brake_torque_Nm;
    const double Tm = m.step(dt, mi).brake_torque_Nm;
    if (t90_1d < 0 && Tb >= target) t90_1d = i * dt;
    if (t90_map < 0 && Tm >= target) t90_map = i * dt;
  }
  std::printf("load step %.0f -> %.0f Nm at %.0f rpm: 90 %% rise time 1D %.2f s (turbo lag, smoke "
              "limiter) vs map engine %.2f s (VECTO PT1); 1D torque after 6 s %.1f Nm\n",
              T0, T1, rpm, t90_1d, t90_map, Tb);
  ASSERT_GT(t90_map, 0.0);
  ASSERT_GT(t90_1d, 0.0);  // the 1D engine does reach the full-load torque
  // Turbo lag: the 1D engine's rise is limited by the turbocharger's spool-up and the smoke
  // limiter, so it is slower than the map engine's VECTO PT1 (which is itself measured on turbo
  // engines). With the NOx-calibrated (retarded) injection timing the exhaust is hotter and the
  // turbo spools faster: 1.34 s instead of 1.78 s before issue 8.
  EXPECT_GT(t90_1d, t90_map);
  EXPECT_NEAR(Tb, T1, 0.03 * T1);
}
