// The ROS-free protocol core (src/cosim/core): StepperCore and ParticipantCores driven against
// each other in-process (cosim_core_harness.hpp: FIFO bus, simulated wall clock): normal run,
// end by FINISHED and by until, ERROR in configure and in step (also after the end), ABORT
// closing files, the run's end handed over at SYNC (a participant that cannot reach it refuses
// before step 0), multi-rate held values, ordered groups, arrival order, report windows, what is
// sent where, validation. What depends on wall time (timeouts, /clock, slow steps) is in
// test_cosim_core_wall.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>
#include <vector>

#include "cosim/core/process_cpu.hpp"
#include "cosim_core_harness.hpp"

using namespace hbt::cosim::core;
using namespace hbt::cosim::core::testing;

TEST(CosimCore, NormalRunEndsAtUntilWithEveryStampRecorded) {
  Bus bus;
  addPair(bus);
  bus.addRecorder({"/a/out", "/b/out"});
  bus.run(config({"a", "b", "recorder"}, 0.05));
  ASSERT_TRUE(bus.completed);
  const StepperCore& s = *bus.stepper;
  EXPECT_FALSE(s.aborted());
  EXPECT_EQ(s.reason(), "until_s reached");
  EXPECT_EQ(s.step(), 5u);
  EXPECT_EQ(s.time(), 50 * MS);
  const auto& a = bus.get("a");
  ASSERT_EQ(a.steps.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(a.steps[k].t, Nanos(k) * 10 * MS);
    EXPECT_EQ(a.steps[k].dt_s, 0.01);                           // the base step, bit for bit
    EXPECT_EQ(a.steps[k].read.at("/b/out"), Nanos(k) * 10 * MS);  // Jacobi: stamped t_k
  }
  EXPECT_EQ(a.published.front(), 0);  // t_0 published at START
  EXPECT_EQ(a.published.back(), 50 * MS);
  const auto& r = bus.get("recorder");
  ASSERT_EQ(r.records.size(), 6u);  // t = 0 .. 0.05, the last one at close
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(r.records[i].read.at("/a/out"), Nanos(i) * 10 * MS);
  for (const auto& p : bus.parts) {
    ASSERT_EQ(p->closed_at.size(), 1u) << p->core.name();
    EXPECT_FALSE(p->closed_aborted[0]);
    EXPECT_EQ(p->closed_at[0], 50 * MS);
  }
  // /clock: t = 0, times everyone is done through as the run goes, t_end
  ASSERT_GE(bus.clocks.size(), 2u);
  EXPECT_EQ(bus.clocks.front(), 0);
  EXPECT_EQ(bus.clocks.back(), 50 * MS);
  for (std::size_t i = 1; i < bus.clocks.size(); ++i) EXPECT_GT(bus.clocks[i], bus.clocks[i - 1]);
  EXPECT_EQ(s.grants(), 2u);  // not one command per base step: a grant to 5, then the observers to 5
}

TEST(CosimCore, RecorderWithoutTopicListRecordsEveryAnnouncedOutput) {
  // the SYNC table lists every output once all have announced; a recorder without a topic list
  // subscribes from it before START and records exactly what one given the full list records
  Bus listed;
  addPair(listed);
  listed.addRecorder({"/a/out", "/b/out"});
  listed.run(config({"a", "b", "recorder"}, 0.05));
  Bus all;
  addPair(all);
  all.addRecorder({}).record_all = true;
  all.run(config({"a", "b", "recorder"}, 0.05));
  ASSERT_TRUE(all.completed);
  EXPECT_FALSE(all.stepper->aborted());
  const auto& r = all.get("recorder");
  ASSERT_FALSE(r.announced_tables.empty());
  EXPECT_EQ(r.announced_tables.front(), (std::vector<std::string>{"/a/out", "/b/out"}));
  const auto& ref = listed.get("recorder");
  ASSERT_EQ(r.records.size(), ref.records.size());
  for (std::size_t i = 0; i < r.records.size(); ++i) {
    EXPECT_EQ(r.records[i].t, ref.records[i].t);
    EXPECT_EQ(r.records[i].read, ref.records[i].read);  // both topics, the same stamps
    EXPECT_EQ(r.records[i].read.size(), 2u);
  }
}

TEST(CosimCore, EndsByFinishedOnly) {
  Bus bus;
  Faults fa;
  fa.finish_at_s = 0.03;
  addPair(bus, fa);
  bus.get("a").on_configure = [](ParticipantCore& c) { c.setMissionDuration(0.03); };
  bus.addRecorder({"/a/out", "/b/out"});
  bus.run(config({"a", "b", "recorder"}, 0.0));
  ASSERT_TRUE(bus.completed);
  EXPECT_FALSE(bus.stepper->aborted());
  EXPECT_EQ(bus.stepper->reason(), "end of mission");
  EXPECT_EQ(bus.stepper->time(), 30 * MS);
  EXPECT_DOUBLE_EQ(bus.stepper->missionDuration_s(), 0.03);
  EXPECT_EQ(bus.commands.back().command, Cmd::Finish);
  EXPECT_EQ(bus.get("recorder").records.back().t, 30 * MS);
}

TEST(CosimCore, ErrorInConfigureAbortsBeforeStepZero) {
  Bus bus;
  Faults fb;
  fb.configure_throws = true;
  addPair(bus, {}, fb);
  bus.run(config({"a", "b"}, 1.0));
  ASSERT_TRUE(bus.completed);
  EXPECT_TRUE(bus.stepper->aborted());
  EXPECT_EQ(bus.stepper->reason(), "b: configuration failed: cfg.yaml: key 'mass_kg': must be > 0");
  EXPECT_EQ(bus.stepper->step(), 0u);
  EXPECT_TRUE(bus.get("a").steps.empty());
  EXPECT_EQ(bus.commands.back().command, Cmd::Abort);
}

TEST(CosimCore, SyncCarriesTheRunsEndAsKnownBeforeStepZero) {
  // until only; the mission only (until 0); both: the earlier
  for (const auto& [until_s, mission_s, want_ns] :
       std::vector<std::tuple<double, double, Nanos>>{{0.05, 0.0, 50 * MS}, {0.0, 0.03, 30 * MS},
                                                      {0.05, 0.03, 30 * MS}, {0.02, 0.03, 20 * MS}}) {
    Bus bus;
    Faults fa;
    fa.finish_at_s = mission_s > 0.0 ? mission_s : -1.0;
    addPair(bus, fa);
    const double m = mission_s;
    bus.get("a").on_configure = [m](ParticipantCore& c) { c.setMissionDuration(m); };
    bus.run(config({"a", "b"}, until_s));
    ASSERT_TRUE(bus.completed);
    EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
    ASSERT_FALSE(bus.get("b").run_ends.empty());
    for (Nanos t : bus.get("b").run_ends) EXPECT_EQ(t, want_ns) << "until " << until_s << " mission " << mission_s;
  }
}

TEST(CosimCore, AParticipantThatCannotReachTheEndAbortsBeforeStepZero) {
  Bus bus;
  Faults fb;
  fb.runs_until_s = 0.02;  // the mission (announced by a) lasts 0.03 s, until is 0
  Faults fa;
  fa.finish_at_s = 0.03;
  addPair(bus, fa, fb);
  bus.get("a").on_configure = [](ParticipantCore& c) { c.setMissionDuration(0.03); };
  bus.run(config({"a", "b"}, 0.0));
  ASSERT_TRUE(bus.completed);
  EXPECT_TRUE(bus.stepper->aborted());
  EXPECT_EQ(bus.stepper->reason(), "b: model.fmu: stopTime 0.020000 s is before the end");
  EXPECT_EQ(bus.stepper->step(), 0u);
  EXPECT_TRUE(bus.get("a").steps.empty());
  EXPECT_TRUE(bus.get("a").published.empty());  // not even the outputs at t_0: START never came
  for (const auto& c : bus.commands) EXPECT_NE(c.command, Cmd::Start);
}

TEST(CosimCore, ErrorInStepAbortsAndClosesFiles) {
  Bus bus;
  Faults fb;
  fb.throw_at_step = 2;
  addPair(bus, {}, fb);
  bus.addRecorder({"/a/out", "/b/out"});
  bus.run(config({"a", "b", "recorder"}, 1.0));
  ASSERT_TRUE(bus.completed);
  EXPECT_TRUE(bus.stepper->aborted());
  EXPECT_EQ(bus.stepper->reason(), "b: step 2 (t = 0.020000 s) failed: boom");
  EXPECT_EQ(bus.stepper->step(), 2u);
  EXPECT_EQ(bus.stepper->time(), 20 * MS);
  for (const auto& p : bus.parts) {  // ABORT closes everyone's files at once
    ASSERT_EQ(p->closed_aborted.size(), 1u) << p->core.name();
    EXPECT_TRUE(p->closed_aborted[0]);
    EXPECT_EQ(p->closed_at[0], 20 * MS);
  }
  // every step below the failed one, nothing after (whatever the others had run ahead)
  const auto& r = bus.get("recorder");
  ASSERT_EQ(r.records.size(), 2u);
  EXPECT_EQ(r.records.back().t, 10 * MS);
  EXPECT_GE(bus.get("a").steps.size(), 2u);
}

TEST(CosimCore, MultiRateHeldValues) {
  Bus bus;
  bus.add("fast", {"/slow/out"}, {"/fast/out"});
  auto& slow = bus.add("slow", {"/fast/out"}, {"/slow/out"});
  requestPeriod(slow, 0.03);
  bus.addRecorder({"/fast/out", "/slow/out"}, 0.02);
  bus.run(config({"fast", "slow", "recorder"}, 0.1));
  ASSERT_TRUE(bus.completed);
  EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
  EXPECT_EQ(bus.stepper->time(), 100 * MS);
  // slow: stepped at 0, 30, 60, 90 ms with its own macro step, reads fast stamped t
  ASSERT_EQ(slow.steps.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(slow.steps[i].t, Nanos(i) * 30 * MS);
    EXPECT_EQ(slow.steps[i].dt_s, 0.03);
    EXPECT_EQ(slow.steps[i].read.at("/fast/out"), Nanos(i) * 30 * MS);
  }
  EXPECT_EQ(slow.published.back(), 120 * MS);  // its last step ends after t_end
  // fast at every base step reads slow held: floor(t / 30 ms) * 30 ms
  const auto& fast = bus.get("fast");
  ASSERT_EQ(fast.steps.size(), 10u);
  for (std::size_t k = 0; k < 10; ++k)
    EXPECT_EQ(fast.steps[k].read.at("/slow/out"), Nanos(k) / 3 * 30 * MS) << k;
  // recorder every 20 ms, plus t_end; each topic's held value
  const auto& r = bus.get("recorder");
  ASSERT_EQ(r.records.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    const Nanos t = Nanos(i) * 20 * MS;
    EXPECT_EQ(r.records[i].t, t);
    EXPECT_EQ(r.records[i].read.at("/fast/out"), t);
    EXPECT_EQ(r.records[i].read.at("/slow/out"), t / (30 * MS) * 30 * MS) << i;
  }
  EXPECT_EQ(bus.stepper->peers().at("recorder").multiple, 2u);
  // fast's output is read by slow (every 3rd stamp) and the recorder (every 2nd): only those are
  // sent on its topic, and only the recorder's on its observer lane
  EXPECT_EQ(fast.sent.at("/fast/out"), (std::vector<Nanos>{0, 20 * MS, 30 * MS, 40 * MS, 60 * MS,
                                                          80 * MS, 90 * MS, 100 * MS}));
  EXPECT_EQ(fast.sent_lane.at("/fast/out"), (std::vector<Nanos>{0, 20 * MS, 40 * MS, 60 * MS, 80 * MS, 100 * MS}));
  EXPECT_EQ(fast.published.size(), 11u);  // built at every step
}

TEST(CosimCore, RecorderPeriodNotAMultipleFallsBackToBaseStep) {
  Bus bus;
  addPair(bus);
  bus.addRecorder({"/a/out"}, 0.025);
  bus.run(config({"a", "b", "recorder"}, 0.03));
  ASSERT_TRUE(bus.completed);
  EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
  EXPECT_EQ(bus.stepper->peers().at("recorder").multiple, 1u);
}

TEST(CosimCore, StatusesCarryTheirProcessCpu) {
  // every status names the participant's process and its CPU time so far; in this harness all
  // participants are one process (this test), as nodelets of one manager are
  Bus bus;
  addPair(bus);
  bus.run(config({"a", "b"}, 0.05));
  ASSERT_TRUE(bus.completed);
  for (const char* n : {"a", "b"}) {
    const auto& p = bus.stepper->peers().at(n);
    EXPECT_EQ(p.cpu.process, hbt::cosim::core::processName()) << n;
    EXPECT_GT(p.cpu.cpu_at_start_s, 0.0) << n;
    EXPECT_GE(p.cpu.cpu_s, p.cpu.cpu_at_start_s) << n;  // CLOSED after READY
    EXPECT_LE(p.cpu.cpu_s, hbt::cosim::core::processCpuSeconds()) << n;
  }
}

TEST(CosimCore, BadMacroStepRejectedBeforeStepZero) {
  const double bad[] = {0.015, 0.0, -0.01, std::nan("")};
  const char* what[] = {"0.015 s is not an integer multiple of the stepper's base step 0.01 s",
                        "macro step must be > 0 s", "macro step must be > 0 s", "NaN"};
  for (int i = 0; i < 4; ++i) {
    Bus bus;
    addPair(bus);
    requestPeriod(bus.get("b"), bad[i]);
    bus.run(config({"a", "b"}, 1.0));
    ASSERT_TRUE(bus.completed);
    EXPECT_TRUE(bus.stepper->aborted());
    const std::string& m = bus.stepper->reason();
    EXPECT_NE(m.find("b: configuration failed: slow.yaml: key 'cosim/macro_step_s': "), std::string::npos) << m;
    EXPECT_NE(m.find(what[i]), std::string::npos) << m;
    EXPECT_TRUE(bus.get("a").steps.empty());
  }
}

TEST(CosimCore, OrderedGroupsReadFreshValues) {
  Bus bus;
  addPair(bus);
  bus.addRecorder({"/a/out", "/b/out"});
  auto cfg = config({"a", "b", "recorder"}, 0.04);
  cfg.order = {{"a"}, {"b"}};
  bus.run(cfg);
  ASSERT_TRUE(bus.completed);
  EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
  const auto& a = bus.get("a");
  const auto& b = bus.get("b");
  ASSERT_EQ(b.steps.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(a.steps[k].read.at("/b/out"), Nanos(k) * 10 * MS);        // later group: t_k
    EXPECT_EQ(b.steps[k].read.at("/a/out"), Nanos(k + 1) * 10 * MS);    // earlier group: t_k+1
  }
  // recorder: last group, Jacobi reads (the state at its own time)
  const auto& r = bus.get("recorder");
  for (std::size_t i = 0; i < r.records.size(); ++i)
    EXPECT_EQ(r.records[i].read.at("/a/out"), r.records[i].t);
  EXPECT_EQ(bus.stepper->groups(), (std::vector<std::vector<std::string>>{{"a"}, {"b", "recorder"}}));
  // the chain needs no command per group or per base step: the data order it
  EXPECT_LE(bus.stepper->grants(), 3u);
}

TEST(CosimCore, OrderedGroupsWithMultiRate) {
  Bus bus;
  bus.add("fast", {"/slow/out"}, {"/fast/out"});
  auto& slow = bus.add("slow", {"/fast/out"}, {"/slow/out"});
  requestPeriod(slow, 0.03);
  auto cfg = config({"fast", "slow"}, 0.09);
  cfg.order = {{"fast"}, {"slow"}};
  bus.run(cfg);
  ASSERT_TRUE(bus.completed);
  EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
  ASSERT_EQ(slow.steps.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i)  // fresh value of the fast producer: t + base step
    EXPECT_EQ(slow.steps[i].read.at("/fast/out"), Nanos(i) * 30 * MS + 10 * MS);
  const auto& fast = bus.get("fast");
  for (std::size_t k = 0; k < 9; ++k)
    EXPECT_EQ(fast.steps[k].read.at("/slow/out"), Nanos(k) / 3 * 30 * MS);
  // slow reads fast's fresh value at 10, 40, 70 ms: nothing else of fast is sent on its topic; its
  // state at t_end goes to the observer lane (for an observer's last record)
  EXPECT_EQ(fast.sent.at("/fast/out"), (std::vector<Nanos>{10 * MS, 40 * MS, 70 * MS}));
  EXPECT_EQ(fast.sent_lane.at("/fast/out"), (std::vector<Nanos>{90 * MS}));
}

TEST(CosimCore, OrderValidation) {
  auto cfg = config({"a", "b", "recorder"}, 1.0);
  cfg.order = {{"a"}, {"c"}};
  EXPECT_EQ(validate(cfg), "stepper parameters (launch file): key 'order': 'c' is not a participant of this run (key 'participants')");
  cfg.order = {{"a"}, {"b", "a"}};
  EXPECT_EQ(validate(cfg), "stepper parameters (launch file): key 'order': 'a' appears twice");
  cfg.order = {{"a"}, {}};
  EXPECT_EQ(validate(cfg), "stepper parameters (launch file): key 'order': group 2 is empty");
  cfg.order = {{"a"}, {"b"}};
  EXPECT_EQ(validate(cfg), "");
  cfg.dt_s = 0.0;
  EXPECT_EQ(validate(cfg), "stepper parameters (launch file): key 'dt_s': macro step must be in [1e-4, 1] s");
  // a participant in no group: known only after ANNOUNCE (observers may be left out)
  Bus bus;
  addPair(bus);
  bus.addRecorder({"/a/out"});
  auto c2 = config({"a", "b", "recorder"}, 1.0);
  c2.order = {{"a"}};
  bus.run(c2);
  EXPECT_TRUE(bus.stepper->aborted());
  EXPECT_EQ(bus.stepper->reason(), "stepper parameters (launch file): key 'order': participant 'b' is in no group");
  EXPECT_TRUE(bus.get("a").steps.empty());
}

TEST(CosimCore, TopicPublishedTwiceRejected) {
  Bus bus;
  bus.add("a", {}, {"/x"});
  bus.add("b", {}, {"/x"});
  bus.run(config({"a", "b"}, 1.0));
  EXPECT_TRUE(bus.stepper->aborted());
  EXPECT_EQ(bus.stepper->reason(), "topic /x is published by both a and b");
}

TEST(CosimCore, ArrivalOrderDoesNotMatter) {
  // multi-rate + groups + recorder; topic messages delivered in shuffled orders, interleaved
  // with commands and statuses: every participant reads the same stamps, the recorder (waiting
  // for the outputs at t_end before it closes) writes the same records
  int close_waits = 0;
  auto once = [&close_waits](unsigned seed) {
    Bus bus;
    bus.seed = seed;
    bus.add("fast", {"/slow/out", "/mid/out"}, {"/fast/out"});
    auto& mid = bus.add("mid", {"/fast/out", "/slow/out"}, {"/mid/out"});
    auto& slow = bus.add("slow", {"/fast/out", "/mid/out"}, {"/slow/out"});
    requestPeriod(mid, 0.02);
    requestPeriod(slow, 0.05);
    bus.addRecorder({"/fast/out", "/mid/out", "/slow/out"}, 0.03);
    auto cfg = config({"fast", "mid", "slow", "recorder"}, 0.31);
    cfg.order = {{"mid"}, {"fast", "slow"}};
    bus.run(cfg);
    EXPECT_TRUE(bus.completed);
    EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
    std::vector<std::vector<std::map<std::string, Nanos>>> reads;
    for (const auto& p : bus.parts) {
      reads.emplace_back();
      for (const auto& l : (p->observer ? p->records : p->steps)) reads.back().push_back(l.read);
      EXPECT_EQ(p->closed_at, std::vector<Nanos>{310 * MS}) << p->core.name();
      close_waits += p->close_waits;
    }
    return reads;
  };
  const auto ref = once(0);
  ASSERT_EQ(ref[0].size(), 31u);  // fast
  ASSERT_EQ(ref[3].size(), 12u);  // recorder: 0, 30, ..., 300 ms and t_end = 310 ms
  EXPECT_EQ(ref[1][3].at("/fast/out"), 60 * MS);  // mid (group 1) at 60 ms: fast (group 2), Jacobi
  EXPECT_EQ(ref[0][3].at("/mid/out"), 40 * MS);   // fast at 30 ms: mid's fresh value (20..40 ms)
  EXPECT_EQ(ref[2][1].at("/mid/out"), 60 * MS);   // slow at 50 ms: mid's fresh value (40..60 ms)
  for (unsigned seed = 1; seed <= 20; ++seed) EXPECT_EQ(once(seed), ref) << "seed " << seed;
  EXPECT_GT(close_waits, 0) << "the recorder's CLOSED wait for late outputs was exercised";
}

TEST(CosimCore, RunsAreDeterministic) {
  std::vector<std::vector<StepLog>> logs;
  for (int i = 0; i < 2; ++i) {
    Bus bus;
    addPair(bus);
    bus.run(config({"a", "b"}, 0.2));
    logs.push_back(bus.get("b").steps);
  }
  ASSERT_EQ(logs[0].size(), 20u);
  for (std::size_t k = 0; k < 20; ++k) EXPECT_EQ(logs[0][k].read, logs[1][k].read);
}

TEST(CosimCore, OutputsSentOnlyWhereReadAndTheEndStateKept) {
  // fast (every 10 ms) is read by slow (every 50 ms) and the recorder (every 50 ms) only: it sends
  // the stamps they read, keeps the others back, and at FINISH sends the one the recorder reads
  // at t_end = 70 ms (fast finishes after its step at 60 ms) -- which nobody reads while stepping
  auto run = [](double record_period_s) {
    auto bus = std::make_unique<Bus>();
    Faults ff;
    ff.finish_at_s = 0.07;
    bus->add("fast", {}, {"/fast/out"}, ff);
    requestPeriod(bus->add("slow", {"/fast/out"}, {"/slow/out"}), 0.05);
    bus->addRecorder({"/fast/out", "/slow/out"}, record_period_s);
    bus->run(config({"fast", "slow", "recorder"}, 0.0));
    return bus;
  };
  auto bus = run(0.05);
  ASSERT_TRUE(bus->completed);
  EXPECT_FALSE(bus->stepper->aborted()) << bus->stepper->reason();
  EXPECT_EQ(bus->stepper->time(), 70 * MS);
  const auto& fast = bus->get("fast");
  EXPECT_EQ(fast.published.size(), 8u);  // 0 .. 70 ms: built at every step
  EXPECT_EQ(fast.sent.at("/fast/out"), (std::vector<Nanos>{0, 50 * MS}));
  EXPECT_EQ(fast.sent_lane.at("/fast/out"), (std::vector<Nanos>{0, 50 * MS, 70 * MS}));  // + t_end
  const auto& r = bus->get("recorder");
  ASSERT_EQ(r.records.size(), 3u);
  EXPECT_EQ(r.records[2].t, 70 * MS);
  EXPECT_EQ(r.records[2].read.at("/fast/out"), 70 * MS);
  EXPECT_EQ(r.records[2].read.at("/slow/out"), 50 * MS);
  EXPECT_EQ(fast.core.sent(), 2u + 3u);  // topic + lane
  EXPECT_EQ(fast.core.deferred(), 6u);   // 10, 20, 30, 40, 60, 70 ms kept back; 70 sent at FINISH
  // a recorder at every base step reads every stamp: everything is sent
  auto all = run(0.0);
  ASSERT_TRUE(all->completed);
  EXPECT_EQ(all->get("fast").sent.at("/fast/out").size(), 8u);
  EXPECT_EQ(all->get("fast").sent_lane.at("/fast/out").size(), 8u);
  EXPECT_EQ(all->get("recorder").records.size(), 8u);
}

TEST(CosimCore, ErrorInAStepAfterTheEndIsIgnored) {
  // b has no input: it runs ahead of a to its grant and fails at step 5; a finishes after its
  // step 2 (t_end = 30 ms): the old lock-step would never have run b's step 5, so the run ends
  // normally, with a warning, whatever arrives first
  for (unsigned seed = 0; seed < 8; ++seed) {
    Bus bus;
    bus.seed = seed;
    Faults fa, fb;
    fa.finish_at_s = 0.03;
    fb.throw_at_step = 5;
    bus.add("a", {"/b/out"}, {"/a/out"}, fa);
    bus.add("b", {}, {"/b/out"}, fb);
    bus.addRecorder({"/a/out", "/b/out"});
    bus.run(config({"a", "b", "recorder"}, 0.0));
    ASSERT_TRUE(bus.completed);
    EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
    EXPECT_EQ(bus.stepper->reason(), "end of mission");
    EXPECT_EQ(bus.stepper->time(), 30 * MS);
    ASSERT_EQ(bus.warnings.size(), 1u);
    EXPECT_EQ(bus.warnings[0], "stepper: ignored, in a step at or after the end of the run (t = 0.030 s): "
                               "b: step 5 (t = 0.050000 s) failed: boom");
    EXPECT_EQ(bus.get("recorder").records.back().t, 30 * MS);
  }
  // the same error before the end aborts the run at that step
  Bus bus;
  Faults fa, fb;
  fa.finish_at_s = 0.08;
  fb.throw_at_step = 5;
  bus.add("a", {"/b/out"}, {"/a/out"}, fa);
  bus.add("b", {}, {"/b/out"}, fb);
  bus.run(config({"a", "b"}, 0.0));
  EXPECT_TRUE(bus.stepper->aborted());
  EXPECT_EQ(bus.stepper->time(), 50 * MS);
  EXPECT_EQ(bus.get("a").steps.size(), 5u);  // a reached the failed step without b's step 5
}

TEST(CosimCore, TheReportWindowChangesNeitherReadsNorRecordsOnlyTheCommands) {
  // the same multi-rate, ordered run with windows of 1, 3, 10 and 1000 base steps: identical
  // reads, records and end; the number of grants falls with the window (about 2 per window)
  std::vector<std::vector<std::vector<std::map<std::string, Nanos>>>> all;
  std::vector<uint64_t> grants;
  for (uint32_t w : {1u, 3u, 10u, 1000u}) {
    Bus bus;
    bus.add("fast", {"/slow/out", "/mid/out"}, {"/fast/out"});
    requestPeriod(bus.add("mid", {"/fast/out", "/slow/out"}, {"/mid/out"}), 0.02);
    requestPeriod(bus.add("slow", {"/fast/out", "/mid/out"}, {"/slow/out"}), 0.05);
    bus.addRecorder({"/fast/out", "/mid/out", "/slow/out"}, 0.03);
    auto cfg = config({"fast", "mid", "slow", "recorder"}, 1.0);
    cfg.order = {{"mid"}, {"fast", "slow"}};
    cfg.window_steps = w;
    bus.run(cfg);
    ASSERT_TRUE(bus.completed);
    EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
    all.emplace_back();
    for (const auto& p : bus.parts) {
      all.back().emplace_back();
      for (const auto& l : (p->observer ? p->records : p->steps)) all.back().back().push_back(l.read);
    }
    grants.push_back(bus.stepper->grants());
  }
  for (std::size_t i = 1; i < all.size(); ++i) EXPECT_EQ(all[i], all[0]) << i;
  EXPECT_EQ(all[0][0].size(), 100u);
  EXPECT_GT(grants[0], 100u);      // W = 1: about one per base step
  EXPECT_LE(grants[2], 2u * 10u + 2u);  // W = 10: about two per window
  EXPECT_LE(grants[3], 3u);
}

TEST(CosimCore, TheRecorderGetsOnlyItsStampsOnTheObserverLane) {
  // a and b read each other at every 10 ms step; the recorder every 50 ms: the topics carry every
  // stamp (to the other participant), the lanes every fifth and t_end -- the recorder receives
  // nothing else, and records exactly what a recorder reading the topics would
  Bus bus;
  addPair(bus);
  bus.addRecorder({"/a/out", "/b/out"}, 0.05);
  bus.run(config({"a", "b", "recorder"}, 0.23));
  ASSERT_TRUE(bus.completed);
  EXPECT_FALSE(bus.stepper->aborted()) << bus.stepper->reason();
  const auto& a = bus.get("a");
  EXPECT_EQ(a.sent.at("/a/out").size(), 24u);  // 0 .. 230 ms
  EXPECT_EQ(a.sent_lane.at("/a/out"), (std::vector<Nanos>{0, 50 * MS, 100 * MS, 150 * MS, 200 * MS, 230 * MS}));
  const auto& r = bus.get("recorder");
  ASSERT_EQ(r.records.size(), 6u);
  for (const auto& rec : r.records) {
    EXPECT_EQ(rec.read.at("/a/out"), rec.t);
    EXPECT_EQ(rec.read.at("/b/out"), rec.t);
  }
}
