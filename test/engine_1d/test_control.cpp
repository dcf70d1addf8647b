// Controllers: the torque PID reaches a requested torque, the wastegate PID reaches the boost
// target, and a load step shows turbo lag (1D torque rise slower than the map engine's PT1).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "engine_1d/torque_response_model.hpp"
#include "support.hpp"

using namespace hbt::engine_1d;
using namespace hbt::engine_1d::test;

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
  // turbo spools faster (1.34 s).
  EXPECT_GT(t90_1d, t90_map);
  EXPECT_NEAR(Tb, T1, 0.03 * T1);
}

// The trim's reference (torque_response_model.hpp): a step of the request appears after the dead
// angle and ramps linearly over one cycle (720°), exactly, whatever the step lengths.
TEST(Engine1DControl, TorqueResponseModelIsDeadAngleThenOneCycleMean) {
  TorqueResponseModel m(220.0);
  m.reset(100.0);
  EXPECT_DOUBLE_EQ(m.expected(), 100.0);
  double angle = 0.0;  // crank angle since the step [deg]
  auto push = [&](double d) {
    m.push(d, 250.0);
    angle += d;
  };
  push(42.0);  // 700 rpm, 10 ms
  push(42.0);
  push(100.0);
  EXPECT_DOUBLE_EQ(m.expected(), 100.0);  // 184° < 220°: nothing yet
  push(36.0);                             // 220°
  EXPECT_NEAR(m.expected(), 100.0, 1e-12);
  push(360.0);                            // 580° = 220 + 360: half way
  EXPECT_NEAR(m.expected(), 175.0, 1e-12);
  for (int i = 0; i < 40; ++i) push(7.5);  // 880° (small steps)
  EXPECT_NEAR(m.expected(), 100.0 + 150.0 * (880.0 - 220.0) / 720.0, 1e-9);
  push(60.0);                             // 940° = 220 + 720: all new
  EXPECT_NEAR(m.expected(), 250.0, 1e-9);
}

// Idle torque steps at 700 rpm (the vehicle's idle governor asks such steps after a stop): the
// trim on T_model - T_b reaches the request without integrating the engine's ~0.13 s response
// time; on T_req - T_b it overshot the 80 -> 200 -> 80 Nm step by +48 / -46 Nm (README "Torque
// control").
TEST(Engine1DControl, TorqueTrimDoesNotIntegrateTheResponseTime) {
  Engine1D e(defaultParams(), repoRoot());
  const double rpm = 700.0, w = rpm * kRpm;
  e.reset(w, 80.0);
  run(e, rpm, 80.0, 3.0);
  const double T0 = e.outputs().brake_torque_Nm;
  double up_max = -1e9, down_min = 1e9, T_up = 0.0, T_down = 0.0;
  Engine1DInputs in;
  in.speed_rad_s = w;
  for (int i = 0; i < 300; ++i) {  // 1.5 s at 200 Nm, 1.5 s at 80 Nm
    in.torque_request_Nm = i < 150 ? 200.0 : 80.0;
    const double Tb = e.step(0.01, in).brake_torque_Nm;
    if (i < 150) up_max = std::max(up_max, Tb), T_up = Tb;
    else down_min = std::min(down_min, Tb), T_down = Tb;
  }
  std::printf("idle torque steps at 700 rpm: %.1f -> 200 Nm: max %.1f, end %.1f; -> 80 Nm: min %.1f, "
              "end %.1f Nm\n", T0, up_max, T_up, down_min, T_down);
  EXPECT_NEAR(T0, 80.0, 1.0);
  EXPECT_NEAR(T_up, 200.0, 2.0);
  EXPECT_NEAR(T_down, 80.0, 2.0);
  EXPECT_LE(up_max, 200.0 + 0.15 * 120.0);  // overshoot <= 15 % of the step (was 40 %)
  EXPECT_GE(down_min, 80.0 - 0.15 * 120.0);
}
