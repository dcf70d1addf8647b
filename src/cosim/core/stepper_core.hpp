// Master stepper side of the step protocol as a plain C++ state machine (no ROS). The ROS node
// cosim::Stepper (../stepper.hpp) owns one and only translates messages, timers and files.
//
// Phases: Announce -> Sync -> Stepping -> Closing -> Done.
//  Announce  waits for an ANNOUNCE of every participant (outputs, observer flag, mission duration);
//            then builds the groups from `order` (default: one group = Jacobi); observers (the
//            recorder) always go into the last group. A participant missing from `order` or a
//            topic published by two participants ABORTs the run here, before step 0.
//  Sync      SYNC rounds until one round in which every participant answered READY (with its
//            step multiple); then START with the table (topic -> producer multiple and group,
//            participant -> multiple and group) and step 0. Each SYNC carries the table as
//            known so far: its topics are final (everyone has announced), so an observer that
//            records "everything" (the recorder without a topic list) subscribes from it and
//            answers WAITING until connected; multiples and groups are final only in START.
//  Stepping  base step k (t_k = k * dt): /clock t_k, then for each group in order the STEP(k, g)
//            to its participants due at k (k % multiple == 0), waiting for all their DONE(k) or
//            FINISHED(k) before the next group. After the last group: t_{k+1}; the run ends with
//            FINISH when someone reported FINISHED in step k (the only end-of-mission signal) or
//            t_{k+1} >= until_s (> 0).
//  Closing   FINISH/ABORT sent; waits for CLOSED from all (0.7 s wall after ABORT, 5 s after
//            FINISH; silent participants of a step timeout are not waited for), then Done.
// Abort paths: an ERROR status (any phase before Closing), start-up timeout (someone never
// announces or links never ready within startup_timeout_s), step timeout (a participant due in
// the current group does not answer within timeout_s). Wall time comes from the caller
// (onStatus/onTick arguments), so tests drive a simulated wall clock.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "cosim/core/protocol.hpp"

namespace hbt::cosim::core {

struct StepperConfig {
  std::vector<std::string> participants;
  std::vector<std::vector<std::string>> order;  // empty: all in one group
  double dt_s = 0.01, until_s = 0.0, timeout_s = 1.0, startup_timeout_s = 60.0;
  /// /clock at t = 0, then at most once per this simulated period [s] (0 = every base step): it
  /// is for observers only (rviz, log stamps, rosbag tools), nothing of the protocol reads it,
  /// and every ROS process with use_sim_time receives each message.
  double clock_period_s = 0.0;
  std::string where = "stepper parameters (launch file)";
};

/// "" if valid, else the error naming `where` and the key (participants, dt_s, timeout_s,
/// until_s, order: unknown name, duplicate, empty group).
std::string validate(const StepperConfig& c);

class StepperTransport {
 public:
  virtual ~StepperTransport() = default;
  virtual void sendCommand(const Command& c) = 0;
  virtual void publishClock(Nanos t) = 0;
  /// After each base step (force = false) and once when the run ends (force = true).
  virtual void progress(bool force) {}
  virtual void runEnded(bool aborted, const std::string& reason) {}
  virtual void warn(const std::string& msg) {}
  /// Everything is over (status can be written, the process may shut down).
  virtual void complete() = 0;
};

enum class Phase { Announce, Sync, Stepping, Closing, Done };

class StepperCore {
 public:
  struct Peer {
    St last_status = St::Announce;
    bool has_status = false, announced = false, observer = false;
    bool due = false, done = false, closed = false;
    uint64_t last_step = 0;
    uint32_t multiple = 1, group = 0;
    double compute_s = 0.0, mission_duration_s = 0.0;
    std::vector<std::string> outputs;
    std::string waiting_for;
  };

  StepperCore(StepperConfig cfg, StepperTransport& tr);
  void begin(double wall_s);
  void onStatus(const Status& s, double wall_s);
  void onTick(double wall_s);

  Phase phase() const { return phase_; }
  uint64_t step() const { return k_; }
  Nanos time() const { return t_; }
  double dt_s() const { return cfg_.dt_s; }
  double until_s() const { return cfg_.until_s; }
  bool aborted() const { return aborted_; }
  const std::string& reason() const { return reason_; }
  /// Longest mission duration announced (0 = unknown).
  double missionDuration_s() const;
  /// Wall time of begin(), then of the start of step 0.
  double wallStart_s() const { return wall0_; }
  const std::map<std::string, Peer>& peers() const { return peers_; }
  const std::vector<std::vector<std::string>>& groups() const { return groups_; }
  /// Number of STEP commands sent (one per due group per base step).
  uint64_t stepCommands() const { return step_commands_; }

 private:
  std::string buildGroups();
  std::string missing(bool (*pred)(const Peer&)) const;
  void sendSync();
  void sendStart();
  void fillTable(Table& t) const;
  void beginStep(double wall_s);
  void commandNextGroup(double wall_s);
  void finish(bool aborted, const std::string& reason, double wall_s);
  void complete();

  StepperConfig cfg_;
  StepperTransport& tr_;
  std::map<std::string, Peer> peers_;
  std::vector<std::vector<std::string>> groups_;
  Phase phase_ = Phase::Announce;
  Nanos dt_ns_ = 0, t_ = 0;
  Nanos clock_period_ns_ = 0, last_clock_ = -1;  // /clock sample period, last sent (-1: none)
  void clockAt(Nanos t);
  uint64_t k_ = 0, sync_round_ = 0, step_commands_ = 0;
  std::size_t group_ = 0;
  bool finished_seen_ = false, aborted_ = false;
  std::string reason_;
  double wall0_ = 0.0, phase_since_ = 0.0, step_sent_ = 0.0;
};

}  // namespace hbt::cosim::core
