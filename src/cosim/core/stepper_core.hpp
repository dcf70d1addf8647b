// Master stepper side of the step protocol as a plain C++ state machine (no ROS). The ROS node
// cosim::Stepper (../stepper.hpp) owns one and only translates messages, timers and files.
//
// Phases: Announce -> Sync -> Stepping -> Closing -> Done.
//  Announce  waits for an ANNOUNCE of every participant (outputs, inputs, observer flag, mission
//            duration); then builds the groups from `order` (default: one group = Jacobi);
//            observers (the recorder) always go into the last group. A participant missing from
//            `order` or a topic published by two participants ABORTs the run here, before step 0.
//  Sync      SYNC rounds until one round in which every participant answered READY (with its
//            step multiple and final inputs). Each SYNC also carries the end of the run as known
//            once everyone announced (runEnd(): until_s or the longest mission announced, the
//            earlier of both; 0 = unknown), so that a participant that cannot run that far (an
//            FMU's stop time) refuses before step 0 with an ERROR; then START with the table (topic -> producer
//            multiple and group, participant -> multiple and group, readers of each topic, the
//            report window W) and the first GRANT. Each SYNC carries the table as known so far:
//            its topics are final (everyone has announced), so an observer that records
//            "everything" (the recorder without a topic list) subscribes from it and answers
//            WAITING until connected; multiples, groups and readers are final only in START.
//  Stepping  The stepper is not in the loop of every base step: it GRANTs horizons and the
//            participants step on their data (participant_core.hpp). Let n_p be what p reported
//            done (every due step below n_p), D = min n_p over the non-observers, E the end as
//            known so far: min(E_until = first k with t_k >= until_s, k_f + 1 for the first
//            FINISHED after step k_f, k_e for the first ERROR in step k_e). Grants:
//              K     = min(floor(min_all n / W)·W + 2W, E)   non-observers (at most 2W ahead
//                                                            of the slowest, the recorder included)
//              K_obs = min(D + 1, E)                         observers: never beyond a step that
//                                                            may lie past the end
//              L     = min(D, E)                             the end is never before L
//            A grant may shrink (a FINISHED or an ERROR lowers E). The end is committed when every
//            participant reported n_p >= E -- nobody can still report a FINISHED or an ERROR
//            below E, since each participant's statuses arrive in order -- then FINISH at t_E, or
//            ABORT when E is an error's step (an ERROR in a step at or after the end of the run,
//            which the old lock-step would never have run, is a warning). So the run ends at the
//            same step, with the same states, whatever the timing; every participant can reach
//            E without the failed one (its outputs up to t_{k_e} were published).
//  Closing   FINISH/ABORT sent; waits for CLOSED from all (0.7 s wall after ABORT, 5 s after
//            FINISH; participants silent at a step timeout are not waited for), then Done.
//            Heartbeat: whenever it sent no command for a report period (timeout_s / 4, the
//            participants' report_wall_s) it sends its latest GRANT again, so that participants
//            can tell a silent stepper (died or hung) from a slow run (protocol.hpp).
// Abort paths: an ERROR status (Announce/Sync: at once; Stepping: at its step, see above),
// start-up timeout (someone never announces or links never ready within startup_timeout_s), step
// timeout (no participant reported progress for timeout_s: at timeout_s / 2 a QUERY asks everyone
// what it waits for; the ones that did not answer are named as died or hung). Starved is not
// dead: when every silent one is runnable (or waiting for a disk) yet got less than
// kStarvedCpuShare of the wall time as CPU since the last probe (transport's taskState), the
// timeout waits another timeout_s / 2, up to kMaxStarvedWait_timeouts in all, and says so. A
// gap of more than timeout_s / 4 between two ticks (the stepper itself did not run) moves every
// timer on by that gap: statuses that arrived meanwhile are read before anyone is judged.
// Wall time comes from the caller (onStatus/onTick arguments), so tests drive a simulated wall
// clock.
#pragma once
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "cosim/core/process_cpu.hpp"
#include "cosim/core/protocol.hpp"

namespace hbt::cosim::core {

struct StepperConfig {
  std::vector<std::string> participants;
  std::vector<std::vector<std::string>> order;  // empty: all in one group
  double dt_s = 0.01, until_s = 0.0, timeout_s = 1.0, startup_timeout_s = 60.0;
  /// /clock at t = 0, then at most once per this simulated period [s] (0 = every base step) and
  /// per clock_wall_period_s of wall time, and at t_end: it is for observers only (rviz, log
  /// stamps, rosbag tools), nothing of the protocol reads it, and every ROS process with
  /// use_sim_time receives each message (a wake-up each: at 7,000 base steps/s a 0.1 s sim period
  /// alone meant 700 per second and process).
  double clock_period_s = 0.0;
  double clock_wall_period_s = 0.0;
  /// W [base steps]: participants report at every multiple of W; grants reach 2W ahead.
  uint32_t window_steps = 50;
  std::string where = "stepper parameters (launch file)";
};

/// "" if valid, else the error naming `where` and the key (participants, dt_s, timeout_s,
/// until_s, clock_period_s, window_steps, order: unknown name, duplicate, empty group).
std::string validate(const StepperConfig& c);

class StepperTransport {
 public:
  virtual ~StepperTransport() = default;
  virtual void sendCommand(const Command& c) = 0;
  virtual void publishClock(Nanos t) = 0;
  /// After progress (force = false) and once when the run ends (force = true).
  virtual void progress(bool force) {}
  virtual void runEnded(bool aborted, const std::string& reason) {}
  virtual void warn(const std::string& msg) {}
  /// Everything is over (status can be written, the process may shut down).
  virtual void complete() = 0;
  /// The kernel's view of participant `name` (its thread, or its process "host:pid" when on this
  /// host): to tell one starved of CPU from one that died or hangs. Default: unknown.
  virtual TaskState taskState(const std::string& name, const std::string& process) { return {}; }
};

enum class Phase { Announce, Sync, Stepping, Closing, Done };

class StepperCore {
 public:
  static constexpr uint64_t kNever = std::numeric_limits<uint64_t>::max();
  /// Longest wait for starved participants, in timeouts (a machine that starves a runnable
  /// thread for 10 s is not one to run on).
  static constexpr double kMaxStarvedWait_timeouts = 10.0;
  /// Starved: less CPU than this share of the wall time since the last probe.
  static constexpr double kStarvedCpuShare = 0.25;
  struct Peer {
    St last_status = St::Announce;
    bool has_status = false, announced = false, observer = false;
    bool closed = false, failed = false;
    bool answered = false;      // answered the current QUERY
    uint64_t last_step = 0;     // start-up: SYNC round answered
    uint64_t next = 0;          // n: every due step below it is done
    uint32_t multiple = 1, group = 0;
    double compute_s = 0.0, mission_duration_s = 0.0;
    CpuReport cpu;               // of its process (Status::process_cpu_s): last report, at READY
    TaskState probed;            // its thread or process at the last probe (QUERY, each wait)
    double probed_wall = 0.0;    // [s]
    std::vector<std::string> outputs, inputs;
    std::string waiting_for;    // start-up: links; stepping: the answer to the last QUERY
    std::string error;          // its ERROR message (stepping)
  };

  StepperCore(StepperConfig cfg, StepperTransport& tr);
  void begin(double wall_s);
  void onStatus(const Status& s, double wall_s);
  void onTick(double wall_s);

  Phase phase() const { return phase_; }
  /// While stepping: the base step every participant is done through; at the end: k_end.
  uint64_t step() const { return k_; }
  Nanos time() const { return t_; }
  double dt_s() const { return cfg_.dt_s; }
  double until_s() const { return cfg_.until_s; }
  bool aborted() const { return aborted_; }
  const std::string& reason() const { return reason_; }
  /// Longest mission duration announced (0 = unknown).
  double missionDuration_s() const;
  /// The end of the run as known before step 0 [ns]: until_s, or the longest mission announced,
  /// the earlier of both when both are known; 0 = unknown (SYNC carries it).
  Nanos runEnd() const;
  /// Wall time of begin(), then of the start of step 0.
  double wallStart_s() const { return wall0_; }
  const std::map<std::string, Peer>& peers() const { return peers_; }
  const std::vector<std::vector<std::string>>& groups() const { return groups_; }
  /// Number of GRANT commands sent (heartbeats not counted).
  uint64_t grants() const { return grants_; }
  /// Number of heartbeats (the latest GRANT sent again).
  uint64_t heartbeats() const { return heartbeats_; }
  /// Report period of the participants and heartbeat period of the stepper [s wall].
  double heartbeatPeriod_s() const { return cfg_.timeout_s / 4.0; }

 private:
  std::string buildGroups();
  std::string missing(bool (*pred)(const Peer&)) const;
  void sendSync();
  void sendStart();
  void fillTable(Table& t, bool readers) const;
  void update(double wall_s);
  void timeout(double wall_s);
  void heartbeat(double wall_s);
  /// Probes every peer (taskState) and keeps the result as the baseline for starved().
  void probePeers(double wall_s);
  /// True if every participant that did not answer is starved of CPU (see above).
  bool starved(double wall_s);
  void finish(bool aborted, const std::string& reason, double wall_s);
  void complete();
  void clockAt(Nanos t, double wall_s);
  uint64_t endStep() const;

  StepperConfig cfg_;
  StepperTransport& tr_;
  std::map<std::string, Peer> peers_;
  std::vector<std::vector<std::string>> groups_;
  Phase phase_ = Phase::Announce;
  Nanos dt_ns_ = 0, t_ = 0;
  Nanos clock_period_ns_ = 0, last_clock_ = -1;  // /clock sample period, last sent (-1: none)
  double last_clock_wall_ = 0.0;                 // wall time of the last /clock [s]
  uint64_t k_ = 0, sync_round_ = 0, grants_ = 0;
  uint64_t end_until_ = kNever, end_finished_ = kNever, end_error_ = kNever;
  uint64_t horizon_ = 0, horizon_obs_ = 0, confirmed_ = 0;
  Command last_grant_;           // the latest GRANT (sent again as the heartbeat)
  double last_sent_wall_ = 0.0;  // wall time of the latest GRANT or QUERY [s]
  uint64_t heartbeats_ = 0;
  double last_tick_wall_ = -1.0;  // the previous onTick [s]; -1: none yet
  double starved_wait_s_ = 0.0;  // wait beyond timeout_s granted to starved participants [s]
  std::string starved_names_;    // who was starved (for the message)
  std::string error_reason_, finished_by_;
  bool aborted_ = false, query_sent_ = false;
  std::string reason_;
  double wall0_ = 0.0, phase_since_ = 0.0, last_progress_ = 0.0;
};

}  // namespace hbt::cosim::core
