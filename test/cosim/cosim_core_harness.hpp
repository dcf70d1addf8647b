// In-process harness for the ROS-free protocol core: a StepperCore and several ParticipantCores
// wired by a FIFO "bus" (commands, statuses and topic messages are queued and delivered in order)
// under a simulated wall clock (50 ms stepper ticks, 100 ms participant ticks). Each fake participant
// publishes, on each output topic, the stamp itself as value, so a consumer's log shows exactly
// which stamp it read at each step. Faults are switched on per participant.
#pragma once
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cosim/core/participant_core.hpp"
#include "cosim/core/stepper_core.hpp"

namespace hbt::cosim::core::testing {

class Bus;

class FakeInput : public InputPort {
 public:
  FakeInput(std::string topic, std::function<void()> arrived)
      : topic_(std::move(topic)), arrived_(std::move(arrived)) {}
  std::string resolvedTopic() const override { return topic_; }
  bool hasStamp(Nanos s) const override { return buf_.count(s) > 0; }
  void dropStampsBefore(Nanos s) override { buf_.erase(buf_.begin(), buf_.lower_bound(s)); }
  void deliver(Nanos stamp, Nanos value) {
    buf_[stamp] = value;
    arrived_();
  }
  /// Value read for a step starting at t (the stamp published = value).
  Nanos at(Nanos t) const { return buf_.at(stampFor(t)); }

 private:
  std::string topic_;
  std::function<void()> arrived_;
  std::map<Nanos, Nanos> buf_;
};

struct Faults {
  bool configure_throws = false;
  bool never_announce = false;        // never starts: no ANNOUNCE, no answers
  std::string missing_links;          // answered to every SYNC (links never ready)
  int64_t throw_at_step = -1;         // step() throws at this k
  int64_t silent_from_step = -1;      // steps nothing from this base step k on, answers nothing (hung)
  double step_wall_s = 0.0;           // every step() takes this long [s of the simulated wall]
  double finish_at_s = -1.0;          // finished() once t >= this
  bool never_ready_to_close = false;  // readyToClose() false forever
  double runs_until_s = -1.0;         // runEndKnown() throws for an end later than this [s] (< 0: never)
};

struct StepLog {
  Nanos t;
  double dt_s;
  std::map<std::string, Nanos> read;  // topic -> stamp read
};

class FakeParticipant : public ParticipantHooks {
 public:
  /// An observer (the recorder) subscribes to the observer lanes of its topics ("lane:" + topic).
  FakeParticipant(Bus& bus, std::string name, std::vector<std::string> inputs,
                  std::vector<std::string> outputs, Faults f, bool observer = false);
  ParticipantCore core;
  std::vector<std::unique_ptr<FakeInput>> inputs;
  std::vector<std::string> outputs;
  Faults faults;
  std::vector<StepLog> steps;
  std::vector<Nanos> published;     // stamps of publishOutputs
  std::map<std::string, std::vector<Nanos>> sent;  // topic -> stamps sent on the topic
  std::map<std::string, std::vector<Nanos>> sent_lane;  // topic -> stamps sent on its observer lane
  std::vector<Nanos> closed_at;     // close(t_end)
  std::vector<bool> closed_aborted;
  std::vector<StepLog> records;     // observer: what was written (step or close)
  std::function<void(ParticipantCore&)> on_configure;
  bool observer = false;
  bool hung = false;
  mutable int close_waits = 0;  // readyToClose() answered false

  void configure() override;
  void publishOutputs(Nanos t) override;
  void step(Nanos t, double dt_s) override;
  bool finished() const override;
  void close(Nanos t_end, bool aborted) override;
  bool readyToClose(Nanos t_end) const override;
  std::string missingLinks() const override { return faults.missing_links; }
  /// record_all (a recorder without a topic list): subscribes to every announced topic.
  void topicsAnnounced(const std::vector<std::string>& topics,
                       const std::vector<std::string>& participants) override;
  bool record_all = false;
  std::vector<std::vector<std::string>> announced_tables;  // topics of each SYNC seen
  void runEndKnown(Nanos t_end) override;
  std::vector<Nanos> run_ends;  // the end each SYNC carried
  void sendStatus(const Status& s) override;
  void logError(const std::string&) override {}
  double wallNow() const override;
  void stepperLost(Nanos t, const std::string& message) override {
    stepper_lost.push_back({t, message});
    stepper_lost_wall.push_back(wallNow());
  }
  std::vector<std::pair<Nanos, std::string>> stepper_lost;  // (t, message) of each stepperLost
  std::vector<double> stepper_lost_wall;
  void command(const Command& c);

 private:
  Bus& bus_;
  Nanos t_ = 0;
  StepLog readAll(Nanos t) const;
};

class Bus : public StepperTransport {
 public:
  double wall = 0.0;
  std::deque<std::function<void()>> queue;
  /// Topic messages: delivered in order (seed 0) or, seed > 0, in a pseudo-random order
  /// interleaved with commands and statuses (arrival order must not matter).
  std::vector<std::function<void()>> topic_pool;
  unsigned seed = 0;
  std::unique_ptr<StepperCore> stepper;
  std::vector<std::unique_ptr<FakeParticipant>> parts;
  std::map<std::string, std::vector<FakeInput*>> subscribers;
  std::vector<Command> commands;
  std::vector<Nanos> clocks;
  std::vector<std::string> warnings;
  bool completed = false;
  double completed_wall = -1.0;
  /// The stepper hangs from this wall time on [s] (< 0: never): no ticks, statuses not read.
  double stepper_hung_from_wall = -1.0;
  bool stepperHung() const { return stepper_hung_from_wall >= 0.0 && wall >= stepper_hung_from_wall; }

  FakeParticipant& add(const std::string& name, std::vector<std::string> in,
                       std::vector<std::string> out, Faults f = {}, bool observer = false);
  /// A recorder-like observer of `topics`, period request `period_s` (0 = base) with fallback.
  FakeParticipant& addRecorder(std::vector<std::string> topics, double period_s = 0.0);
  FakeParticipant& get(const std::string& name);
  void run(StepperConfig cfg, double max_wall_s = 120.0);

  void sendCommand(const Command& c) override;
  void publishClock(Nanos t) override {
    clocks.push_back(t);
    clock_walls.push_back(wall);
  }
  std::vector<double> clock_walls;  // wall time of each /clock
  void warn(const std::string& m) override { warnings.push_back(m); }
  void complete() override {
    completed = true;
    completed_wall = wall;
  }
  void post(std::function<void()> f) { queue.push_back(std::move(f)); }
  void postTopic(std::function<void()> f);
  void pump();
};

constexpr Nanos MS = 1000000;  // one millisecond [ns]

/// A stepper configuration for `names`, base step dt_s [s], end until_s [s] (<= 0: none) and a
/// 2 s start-up timeout.
inline StepperConfig config(std::vector<std::string> names, double until_s, double dt_s = 0.01) {
  StepperConfig c;
  c.participants = std::move(names);
  c.dt_s = dt_s;
  c.until_s = until_s;
  c.startup_timeout_s = 2.0;
  return c;
}

/// Two participants a <-> b coupled both ways (the oscillator layout).
inline void addPair(Bus& bus, Faults fa = {}, Faults fb = {}) {
  bus.add("a", {"/b/out"}, {"/a/out"}, fa);
  bus.add("b", {"/a/out"}, {"/b/out"}, fb);
}

/// p asks for a macro step of s [s] in configure(), as a participant's YAML key would.
inline void requestPeriod(FakeParticipant& p, double s) {
  p.on_configure = [s](ParticipantCore& c) { c.requestPeriod({s, "slow.yaml", "cosim/macro_step_s"}); };
}

}  // namespace hbt::cosim::core::testing
