// The ROS-free protocol core against wall time (cosim_core_harness.hpp: simulated wall clock):
// a participant that hangs (step timeout, named with what the others wait for), start-up
// timeouts (never announces, links never ready), the CLOSED wait, /clock by simulated and by
// wall period, slow steps that report by wall time and never time out.
#include <gtest/gtest.h>

#include "cosim_core_harness.hpp"

using namespace hbt::cosim::core;
using namespace hbt::cosim::core::testing;

namespace {
/// The pair a <-> b with a's every step taking step_wall_s of (simulated) wall time.
void addSlowPair(Bus& bus, double step_wall_s) {
  Faults slow;
  slow.step_wall_s = step_wall_s;
  addPair(bus, slow, {});
}
}  // namespace

TEST(CosimCore, ClockOnlyEveryClockPeriod) {
  // /clock is for observers: at t = 0, then once per clock_period_s of simulated time
  Bus bus;
  addPair(bus);
  StepperConfig cfg = config({"a", "b"}, 0.2);
  cfg.clock_period_s = 0.05;
  bus.run(cfg);
  ASSERT_TRUE(bus.completed);
  EXPECT_FALSE(bus.stepper->aborted());
  EXPECT_EQ(bus.stepper->step(), 20u);  // every base step still stepped
  ASSERT_GE(bus.clocks.size(), 2u);  // t = 0, then at least 50 ms of simulated time apart, t_end
  EXPECT_EQ(bus.clocks.front(), 0);
  EXPECT_EQ(bus.clocks.back(), 200 * MS);
  for (std::size_t i = 1; i + 1 < bus.clocks.size(); ++i) EXPECT_GE(bus.clocks[i] - bus.clocks[i - 1], 50 * MS);
  cfg.clock_period_s = -1.0;
  EXPECT_NE(validate(cfg).find("'clock_period_s'"), std::string::npos);
  cfg.clock_period_s = 0.05;
  cfg.clock_wall_period_s = 61.0;
  EXPECT_NE(validate(cfg).find("'clock_wall_period_s'"), std::string::npos);
}

TEST(CosimCore, ClockAtMostEveryClockWallPeriod) {
  // 0.3 s of wall per step of a: at most one /clock per wall second, whatever the sim period;
  // t = 0 and t_end always
  Bus bus;
  addSlowPair(bus, 0.3);
  StepperConfig cfg = config({"a", "b"}, 0.3);
  cfg.window_steps = 1;
  cfg.clock_wall_period_s = 1.0;
  bus.run(cfg, 100.0);
  ASSERT_TRUE(bus.completed);
  EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
  ASSERT_GE(bus.clocks.size(), 4u);
  EXPECT_LT(bus.clocks.size(), 12u);  // 30 steps: 9 s of wall
  EXPECT_EQ(bus.clocks.front(), 0);
  EXPECT_EQ(bus.clocks.back(), 300 * MS);
  for (std::size_t i = 1; i + 1 < bus.clocks.size(); ++i) EXPECT_GE(bus.clock_walls[i] - bus.clock_walls[i - 1], 1.0);
}

TEST(CosimCore, HungParticipantStepTimeout) {
  Bus bus;
  Faults fb;
  fb.silent_from_step = 3;
  addPair(bus, {}, fb);
  bus.addRecorder({"/a/out", "/b/out"});
  bus.run(config({"a", "b", "recorder"}, 1.0));
  ASSERT_TRUE(bus.completed);
  EXPECT_TRUE(bus.stepper->aborted());
  const std::string& m = bus.stepper->reason();
  EXPECT_EQ(m.rfind("participant(s) b (done through t = 0.030 s) did not answer within 1 s: "
                    "node died or hung; a: step 4 (t = 0.040 s) waits for /b/out stamped 0.040 s", 0), 0u) << m;
  EXPECT_NE(m.find("recorder: "), std::string::npos) << m;  // what the alive ones wait for
  // the run ends within timeout + one tick, without waiting for b's CLOSED
  EXPECT_LT(bus.completed_wall, 2.0 + 1.0 + 0.11);
  EXPECT_TRUE(bus.get("b").closed_at.empty());
  EXPECT_TRUE(bus.get("a").closed_aborted.at(0));
}

TEST(CosimCore, StartupTimeoutNeverAnnounces) {
  Bus bus;
  Faults fb;
  fb.never_announce = true;
  addPair(bus, {}, fb);
  bus.run(config({"a", "b"}, 1.0));
  ASSERT_TRUE(bus.completed);
  EXPECT_TRUE(bus.stepper->aborted());
  EXPECT_EQ(bus.stepper->reason(), "start-up timed out after 2.000000 s; no answer from: b");
  EXPECT_GE(bus.wall, 2.0);
  EXPECT_TRUE(bus.get("a").steps.empty());
}

TEST(CosimCore, StartupTimeoutLinksNeverReady) {
  Bus bus;
  Faults fb;
  fb.missing_links = " input /a/out has no publisher;";
  addPair(bus, {}, fb);
  bus.run(config({"a", "b"}, 1.0));
  ASSERT_TRUE(bus.completed);
  EXPECT_TRUE(bus.stepper->aborted());
  EXPECT_EQ(bus.stepper->reason(),
            "start-up timed out after 2.000000 s; links not connected: b: input /a/out has no publisher;");
  EXPECT_GT(bus.stepper->peers().at("a").last_step, 5u);  // SYNC rounds repeated meanwhile
}

TEST(CosimCore, ClosedWaitForRecorderThenCloseTimeout) {
  Bus bus;
  addPair(bus);
  auto& r = bus.addRecorder({"/a/out", "/b/out"});
  r.faults.never_ready_to_close = true;
  bus.run(config({"a", "b", "recorder"}, 0.02));
  ASSERT_TRUE(bus.completed);
  EXPECT_FALSE(bus.stepper->aborted());
  EXPECT_TRUE(r.closed_at.empty());
  ASSERT_EQ(bus.warnings.size(), 1u);
  EXPECT_EQ(bus.warnings[0], "stepper: no CLOSED from recorder");
  EXPECT_GT(bus.completed_wall, 5.0);  // waited the 5 s after FINISH
}

TEST(CosimCore, SlowStepsReportByWallTimeAndNeverTimeOut) {
  // 0.3 s (wall) per step, 1 s timeout, a window of 100 steps: the participants report at least
  // every timeout / 4 of wall time, so the run is alive although no window completes in 1 s
  Bus bus;
  addSlowPair(bus, 0.3);
  auto cfg = config({"a", "b"}, 0.1);
  cfg.window_steps = 100;
  bus.run(cfg, 1000.0);
  ASSERT_TRUE(bus.completed);
  EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
  EXPECT_EQ(bus.stepper->time(), 100 * MS);
  EXPECT_GT(bus.wall, 3.0);
}
