// Participant side of the step protocol as a plain C++ state machine (no ROS). The ROS base class
// cosim::Participant (../participant.hpp) owns one and only translates messages into calls.
//
//   start()          configure() through the hooks, then validate the macro step request
//                    (errors -> ERROR status "name: ..." naming file and key)
//   onTick()         every 100 ms wall. Until START: ANNOUNCE(outputs, inputs, observer, mission
//                    duration), or ERROR again while failed
//   SYNC r           checks the period against the base step (must be an integer multiple), hands
//                    the run's end as known to the hooks (runEndKnown: an exception is ERROR, the
//                    run ends before step 0), asks the hooks for missing links:
//                    READY(r, step_multiple, inputs) or WAITING(r, links)
//   START            takes the table: own group, each input's held-value rule (HeldRule, from its
//                    producer's period and group), each output's readers, the report window W;
//                    publishes the outputs stamped t_0
//   GRANT K          steps, data-driven, every due base step n < K (n % multiple == 0; observers
//                    use their own horizon): as soon as every input has the message stamped
//                    rule.stampFor(t_n) it calls step(t_n, period), publishes outputs stamped
//                    t_n + period, drops messages older than stampFor(t_n + base step) and moves
//                    on to n + multiple. It reports DONE(n) when it passed a multiple of W, when it
//                    did all it was granted, or when report_wall_s passed since its last report;
//                    FINISHED(n) when finished() says it reached the end of its input (then it
//                    steps no more).
//   QUERY            WAITING(n, what it waits for: which input at which stamp, or the grant)
//   (silence)        onTick() while started: no command for kStepperSilenceReportPeriods report
//                    periods since the later of the last command and its own last step -> the
//                    stepper died or hung: close(t_n, true), then stepperLost(t_n, message). A gap
//                    of more than a report period between two ticks (its own thread did not run:
//                    starved, or blocked by another participant's step) starts the count afresh.
//   FINISH k_end     publishes the deferred outputs an observer reads at t_end, then
//                    close(t_end, false) once readyToClose(t_end); CLOSED
//   ABORT            close(t_end, true) at once; CLOSED
// Outputs: publish(output, stamp, send, send_to_observers) sends a message only if some
// participant of the run reads that stamp (readsStamp() over the output's readers from the
// START table). With an observer lane (send_to_observers: a second topic that only the
// observers -- the recorder -- subscribe to) the observers get only their own stamps there, and
// the output's topic carries the stamps anyone reads (observers included, for tools outside the
// run); without one, the topic carries them all. The observers' state at t_end is kept until the
// end of the run can no longer be at its stamp (GRANT's L).
// Any exception of the model becomes ERROR "name: step k (t = ...) failed: what".
#pragma once
#include <deque>
#include <functional>
#include <string>
#include <vector>

#include "cosim/core/protocol.hpp"
#include "cosim/core/step_watch.hpp"

namespace hbt::cosim::core {

/// One input of a participant: a buffer of messages by stamp (the transport fills it).
class InputPort {
 public:
  virtual ~InputPort() = default;
  virtual std::string resolvedTopic() const = 0;
  virtual bool hasStamp(Nanos stamp) const = 0;
  virtual void dropStampsBefore(Nanos stamp) = 0;
  void setRule(HeldRule r) { rule_ = r; }
  const HeldRule& rule() const { return rule_; }
  /// Stamp of the message read for a step starting at t (identity until START).
  Nanos stampFor(Nanos t) const { return rule_.stampFor(t); }
  bool readyFor(Nanos t) const { return hasStamp(stampFor(t)); }

 private:
  HeldRule rule_;
};

/// What the state machine needs from its participant and transport.
class ParticipantHooks {
 public:
  virtual ~ParticipantHooks() = default;
  virtual void configure() = 0;
  virtual void publishOutputs(Nanos t) = 0;
  virtual void step(Nanos t, double dt_s) = 0;
  virtual bool finished() const = 0;
  virtual void close(Nanos t_end, bool aborted) = 0;
  virtual bool readyToClose(Nanos t_end) const = 0;
  /// Links (inputs without publisher, outputs short of subscribers) not connected; "" = all.
  virtual std::string missingLinks() const = 0;
  /// At each SYNC, first: the end of the run as the stepper knows it once everyone announced
  /// (until_s, or the longest mission announced, the earlier of both; 0 = unknown). A
  /// participant that cannot run that far throws (its message names why): ERROR before step 0.
  virtual void runEndKnown(Nanos t_end) {}
  /// At each SYNC, before the link check: every output topic and every participant of the run
  /// (all have announced). An observer may add inputs here (the recorder recording everything).
  virtual void topicsAnnounced(const std::vector<std::string>& topics,
                               const std::vector<std::string>& participants) {}
  virtual void sendStatus(const Status& s) = 0;
  virtual void logError(const std::string& msg) = 0;
  /// Wall clock [s] for the report period (tests drive a simulated one).
  virtual double wallNow() const;
  /// The stepper fell silent (died or hung) while stepping; this participant has closed as at an
  /// ABORT at t_n. `message` says so (seconds of silence, t_n).
  virtual void stepperLost(Nanos t, const std::string& message) {}
};

/// Requested macro step: 0 = the base step. `where`/`key` name its source for errors.
/// `fallback` (the recorder): a period that is not a multiple of the base step runs at the
/// base step instead of failing.
struct PeriodRequest {
  double period_s = 0.0;
  std::string where, key;
  bool fallback = false;
};

class ParticipantCore {
 public:
  ParticipantCore(std::string name, ParticipantHooks& hooks)
      : name_(std::move(name)), h_(hooks), watch_(name_) {}

  // --- declarations, during configure() ---
  void addInput(InputPort* in) { inputs_.push_back(in); }
  /// Declares an output topic; returns its index for publish().
  std::size_t addOutput(const std::string& resolved_topic);
  void requestPeriod(PeriodRequest r) {
    period_req_ = std::move(r);
    period_given_ = true;
  }
  void setObserver(bool o) { observer_ = o; }
  void setMissionDuration(double s) { mission_duration_s_ = s; }

  // --- publishing (from publishOutputs) ---
  /// Sends output `index` stamped `stamp` (see the header comment): send() on its topic if any
  /// reader reads that stamp; send_to_observers() (if given: the observer lane) if an observer
  /// does. What the observers may still read at t_end is kept until the end is known.
  void publish(std::size_t index, Nanos stamp, std::function<void()> send,
               std::function<void()> send_to_observers = {});
  /// True if a reader of the run reads output `index` stamped `stamp` (always true before START);
  /// observers: only readers that are observers (false: only the others).
  bool outputRead(std::size_t index, Nanos stamp) const;
  bool outputRead(std::size_t index, Nanos stamp, bool observers) const;

  // --- events ---
  void start();
  /// Every 100 ms wall: announces until START, then watches the stepper's heartbeat. Returns
  /// false once closed (or closing): the caller may stop its timer.
  bool onTick();
  void onCommand(const Command& c);
  void onArrival();

  const std::string& name() const { return name_; }
  bool failed() const { return failed_; }
  bool configured() const { return configured_; }  ///< configure() succeeded
  bool closed() const { return closed_; }
  bool started() const { return started_; }
  uint32_t multiple() const { return multiple_; }
  uint32_t group() const { return group_; }
  /// n: every due base step below it is done.
  uint64_t next() const { return n_; }
  double computeSeconds() const { return compute_s_; }  // in configure() and step() [s, steady clock]
  const std::vector<InputPort*>& inputs() const { return inputs_; }
  /// Messages published / kept back (deferred) so far, over all outputs.
  uint64_t sent() const { return sent_; }
  uint64_t deferred() const { return deferred_; }

 private:
  struct Reader {
    uint32_t multiple = 1;
    bool fresh = false, observer = false;
  };
  struct Kept {
    uint64_t s;  // base step of the stamp
    std::function<void()> send;
  };
  struct Output {
    std::string topic;
    std::vector<Reader> readers;
    std::deque<Kept> kept;
  };

  void fail(const std::string& what);
  void report(St status, uint64_t step, Nanos t, const std::string& msg = "");
  void reportProgress(bool force);
  bool checkPeriod(double base_dt_s);
  void applyTable(const Table& table);
  void tryStep();
  void stepWhileReady();
  void tryClose();
  void trimKept(uint64_t confirmed);
  void sendKeptAt(uint64_t k_end);
  std::string describeWait() const;
  void watchStepper();

  std::string name_;
  ParticipantHooks& h_;
  StepWatch watch_;  // inside its model step: seen by the stepper of this process
  std::vector<InputPort*> inputs_;
  std::vector<Output> outputs_;
  PeriodRequest period_req_;
  bool observer_ = false;
  double mission_duration_s_ = 0.0;

  bool configured_ = false, failed_ = false, started_ = false, closed_ = false;
  bool closing_ = false, finished_ = false, period_given_ = false;
  uint32_t multiple_ = 1, group_ = 0, window_ = 1;
  double base_dt_s_ = 0.0, dt_s_ = 0.0;  // base step, own macro step [s]
  double report_wall_s_ = 0.25, last_report_wall_ = 0.0;
  double last_heard_wall_ = 0.0;  // the later of the last command and the end of its last step [s]
  double last_tick_wall_ = 0.0;   // its previous onTick() [s]
  Nanos base_ns_ = 0, period_ns_ = 0;
  uint64_t n_ = 0, horizon_ = 0, reported_ = 0;
  Nanos t_close_ = 0;
  uint64_t k_close_ = 0;
  uint64_t sent_ = 0, deferred_ = 0;
  double compute_s_ = 0.0;
  std::string error_;
};

}  // namespace hbt::cosim::core
