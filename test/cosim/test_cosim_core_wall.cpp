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

TEST(CosimCore, StepperHungEveryParticipantClosesAfterTwiceTheTimeout) {
  // the stepper stops answering at 1 s of wall time in a long run: with its heartbeat every
  // timeout / 4 = 0.25 s, each participant hears nothing for 8 report periods (2 s) and closes
  // as at an ABORT (the recorder's bag stays readable), telling its node (stepperLost)
  Bus bus;
  addSlowPair(bus, 0.001);  // 1 ms of wall per step of a: the run moves on in wall time
  FakeParticipant& rec = bus.addRecorder({"/a/out", "/b/out"});
  bus.stepper_hung_from_wall = 1.0;
  bus.run(config({"a", "b", "recorder"}, 1000.0), 6.0);
  EXPECT_FALSE(bus.completed);  // the stepper never ends the run itself
  for (const char* n : {"a", "b", "recorder"}) {
    const FakeParticipant& p = bus.get(n);
    ASSERT_EQ(p.stepper_lost.size(), 1u) << n;
    EXPECT_GT(p.stepper_lost_wall[0], 1.0 + 2.0 - 0.25) << n;  // not before 2 s of silence
    // within a tick or two of it (the harness ticks the participants only between its pumps: a
    // longer gap than a report period there restarts their count)
    EXPECT_LE(p.stepper_lost_wall[0], 1.0 + 2.0 + 0.3) << n;
    EXPECT_NE(p.stepper_lost[0].second.find("the stepper died or hung; closed at t = "), std::string::npos)
        << p.stepper_lost[0].second;
    ASSERT_EQ(p.closed_aborted.size(), 1u) << n;
    EXPECT_TRUE(p.closed_aborted[0]) << n;
    EXPECT_EQ(p.closed_at[0], static_cast<Nanos>(p.core.next()) * 10 * MS) << n;  // at its t_n
  }
  EXPECT_GT(rec.records.size(), 10u);  // it recorded the stretch that ran
}

namespace {
/// A transport that only records the commands and their wall times.
struct CommandLog : StepperTransport {
  double wall = 0.0;
  std::vector<std::pair<double, Command>> sent;
  void sendCommand(const Command& c) override { sent.push_back({wall, c}); }
  void publishClock(Nanos) override {}
  void complete() override {}
};

Status status(const std::string& node, St st, uint64_t step) {
  Status s;
  s.node = node;
  s.status = st;
  s.step = step;
  s.t = static_cast<Nanos>(step) * 10 * MS;
  return s;
}
}  // namespace

TEST(CosimCore, StepperHeartbeatWhileTheGrantStandsStill) {
  // a is stuck in a long step at step 1 while b keeps reporting progress inside its grant (one
  // step per 0.2 s of wall): no new GRANT (the slowest does not move), no QUERY (someone
  // progresses), yet the stepper sends a command at least every timeout / 4 (its latest GRANT
  // again: the same horizons), so a participant can tell a live stepper from a dead one
  CommandLog tr;
  StepperCore st(config({"a", "b"}, 100.0), tr);
  st.begin(0.0);
  st.onStatus(status("a", St::Announce, 0), 0.0);
  st.onStatus(status("b", St::Announce, 0), 0.0);
  tr.wall = 0.05;
  st.onTick(0.05);  // -> SYNC round 1
  for (const char* n : {"a", "b"}) {
    Status ready = status(n, St::Ready, 1);
    ready.step_multiple = 1;
    st.onStatus(ready, 0.06);
  }
  tr.wall = 0.1;
  st.onTick(0.1);  // -> START, first GRANT
  ASSERT_EQ(st.phase(), Phase::Stepping);
  st.onStatus(status("a", St::Done, 1), 0.1);
  st.onStatus(status("b", St::Done, 1), 0.1);
  const uint64_t grants_at_start = st.grants();
  uint64_t n = 1;
  for (double w = 0.15; w < 9.0; w += 0.05) {
    tr.wall = w;
    if (static_cast<int>(std::lround(w / 0.05)) % 4 == 0) st.onStatus(status("b", St::Done, ++n), w);
    st.onTick(w);
  }
  ASSERT_EQ(st.phase(), Phase::Stepping) << st.reason();
  EXPECT_EQ(st.grants(), grants_at_start);  // the horizons stood still
  EXPECT_GT(st.heartbeats(), 30u);
  double last = -1.0;
  for (const auto& [wall, c] : tr.sent) {
    EXPECT_NE(c.command, Cmd::Query);
    if (c.command != Cmd::Grant) continue;
    if (last >= 0.0) {
      EXPECT_LE(wall - last, st.heartbeatPeriod_s() + 0.05 + 1e-9);
    }
    last = wall;
  }
  EXPECT_GT(last, 8.5);
}

namespace {
/// A participant alone, driven by hand: commands and ticks at chosen wall times.
struct HandHooks : ParticipantHooks {
  double wall = 0.0;
  std::vector<std::string> lost;
  void configure() override {}
  void publishOutputs(Nanos) override {}
  void step(Nanos, double) override {}
  bool finished() const override { return false; }
  void close(Nanos, bool) override {}
  bool readyToClose(Nanos) const override { return true; }
  std::string missingLinks() const override { return ""; }
  void sendStatus(const Status&) override {}
  void logError(const std::string&) override {}
  double wallNow() const override { return wall; }
  void stepperLost(Nanos, const std::string& m) override { lost.push_back(m); }
};

void startAlone(ParticipantCore& core, HandHooks& h) {
  core.start();
  Command sync;
  sync.command = Cmd::Sync;
  sync.step = 1;
  sync.dt_s = 0.01;
  core.onCommand(sync);
  Command start = sync;
  start.command = Cmd::Start;
  start.table.participants = {"p"};
  start.table.participant_multiple = {1};
  start.table.participant_group = {0};
  start.table.report_wall_s = 0.25;  // timeout 1 s: silence limit 2 s
  core.onCommand(start);
  ASSERT_TRUE(core.started());
  (void)h;
}
}  // namespace

TEST(CosimCore, StepperSilenceCountsOnlyWhileTheParticipantRuns) {
  HandHooks h;
  ParticipantCore core("p", h);
  startAlone(core, h);
  // its own thread blocked for 3 s (no ticks): no verdict at the first tick after it -- the
  // stepper's commands of those 3 s wait unread in its queue -- but 2 s of silence after that are
  for (h.wall = 0.1; h.wall < 0.55; h.wall += 0.1) core.onTick();
  h.wall = 3.5;
  core.onTick();
  EXPECT_TRUE(h.lost.empty());
  for (h.wall = 3.6; h.wall < 5.45; h.wall += 0.1) core.onTick();
  EXPECT_TRUE(h.lost.empty());  // 1.9 s of silence while running
  for (; h.wall < 5.65; h.wall += 0.1) core.onTick();
  ASSERT_EQ(h.lost.size(), 1u);  // past 2 s
  EXPECT_NE(h.lost[0].find("the stepper died or hung"), std::string::npos) << h.lost[0];
  EXPECT_FALSE(core.onTick());  // closed: the timer may stop
}

TEST(CosimCore, AnyCommandIsALifeSign) {
  HandHooks h;
  ParticipantCore core("p", h);
  startAlone(core, h);
  Command beat;
  beat.command = Cmd::Grant;  // the stepper's heartbeat: its latest grant again
  beat.dt_s = 0.01;
  for (h.wall = 0.1; h.wall < 10.0; h.wall += 0.1) {
    if (static_cast<int>(std::lround(h.wall * 10)) % 5 == 0) core.onCommand(beat);  // every 0.5 s
    core.onTick();
  }
  EXPECT_TRUE(h.lost.empty());
}

namespace {
/// Commands recorded; the kernel's view of each participant programmed by the test.
struct ProbedLog : CommandLog {
  std::map<std::string, TaskState> states;
  std::vector<std::string> warnings;
  bool completed = false;
  TaskState taskState(const std::string& name, const std::string&) override { return states[name]; }
  void warn(const std::string& m) override { warnings.push_back(m); }
  void complete() override { completed = true; }
};

/// a and b announced, ready, and stepping from 0.1 s of wall on.
void startAB(StepperCore& st) {
  st.begin(0.0);
  for (const char* n : {"a", "b"}) st.onStatus(status(n, St::Announce, 0), 0.0);
  st.onTick(0.05);
  for (const char* n : {"a", "b"}) {
    Status ready = status(n, St::Ready, 1);
    ready.step_multiple = 1;
    st.onStatus(ready, 0.06);
  }
  st.onTick(0.1);
}

/// a and b started, then neither reports again (both waiting on a starved or dead thread, as the
/// participants of one nodelet thread do). Their kernel view: state, CPU per second of wall.
double runWithSilentA(ProbedLog& tr, StepperCore& st, char a_state, double a_cpu_per_s, double until_wall) {
  startAB(st);
  st.onStatus(status("a", St::Done, 1), 0.1);
  st.onStatus(status("b", St::Done, 1), 0.1);
  for (double w = 0.15; w < until_wall && st.phase() == Phase::Stepping; w += 0.05) {
    tr.wall = w;
    tr.states["a"] = tr.states["b"] = {a_state != '?', a_state, a_cpu_per_s * w};
    st.onTick(w);
  }
  return tr.wall;
}
}  // namespace

TEST(CosimCore, StarvedIsNotDeadButStoppedIs) {
  // a runnable participant that got 5 % of a CPU since the QUERY is waited for (and the wait is
  // said once); one the kernel shows stopped (SIGSTOP: 'T'), or sleeping without answering ('S'),
  // or one it does not know, is taken as died or hung at the 1 s timeout, as before
  {
    ProbedLog tr;
    StepperCore st(config({"a", "b"}, 100.0), tr);
    runWithSilentA(tr, st, 'R', 0.05, 5.0);
    EXPECT_EQ(st.phase(), Phase::Stepping) << st.reason();
    ASSERT_EQ(tr.warnings.size(), 1u);
    EXPECT_EQ(tr.warnings[0].rfind("stepper: a, b runnable but starved of CPU: waiting beyond the", 0), 0u) << tr.warnings[0];
  }
  for (char state : {'T', 'S', '?'}) {
    ProbedLog tr;
    StepperCore st(config({"a", "b"}, 100.0), tr);
    const double ended = runWithSilentA(tr, st, state, 0.0, 5.0);
    EXPECT_TRUE(st.aborted()) << state;
    EXPECT_LT(ended, 0.1 + 1.0 + 0.11) << state;
    EXPECT_NE(st.reason().find("a (done through t = 0.010 s), b (done through t = 0.010 s) did not answer within 1 s"),
              std::string::npos) << st.reason();
  }
  {
    // computing (a step longer than the timeout: 90 % of a CPU) is not starved either
    ProbedLog tr;
    StepperCore st(config({"a", "b"}, 100.0), tr);
    runWithSilentA(tr, st, 'R', 0.9, 5.0);
    EXPECT_TRUE(st.aborted());
  }
}

TEST(CosimCore, StarvedForTenTimeoutsIsAbortedAndSaysSo) {
  ProbedLog tr;
  StepperCore st(config({"a", "b"}, 100.0), tr);
  const double ended = runWithSilentA(tr, st, 'R', 0.01, 60.0);
  ASSERT_TRUE(st.aborted());
  EXPECT_NEAR(ended, 0.1 + StepperCore::kMaxStarvedWait_timeouts * 1.0, 0.2);
  EXPECT_NE(st.reason().find("(starved of CPU)"), std::string::npos) << st.reason();
}

TEST(CosimCore, TheStepperAwayJudgesNobody) {
  // the stepper's own thread does not run from 0.2 s to 3.2 s of wall (starved, or blocked on a
  // full console pipe): its first tick after that does not abort -- the participants' statuses
  // of those 3 s are still unread behind it -- and the run goes on when they are read
  ProbedLog tr;
  StepperCore st(config({"a", "b"}, 100.0), tr);
  startAB(st);
  st.onTick(0.15);
  st.onTick(0.2);
  st.onTick(3.2);
  EXPECT_EQ(st.phase(), Phase::Stepping) << st.reason();
  for (const char* n : {"a", "b"}) st.onStatus(status(n, St::Done, 50), 3.21);
  for (double w = 3.25; w < 3.9; w += 0.05) st.onTick(w);
  EXPECT_EQ(st.phase(), Phase::Stepping) << st.reason();
  for (double w = 3.9; w < 6.0 && st.phase() == Phase::Stepping; w += 0.05) st.onTick(w);
  EXPECT_TRUE(st.aborted());  // silent for a timeout while the stepper ran: as before
}
