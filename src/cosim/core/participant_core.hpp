// Participant side of the step protocol as a plain C++ state machine (no ROS). The ROS base class
// cosim::Participant (../participant.hpp) owns one and only translates messages into calls.
//
//   start()          configure() through the hooks, then validate the macro step request
//                    (errors -> ERROR status "name: ..." naming file and key)
//   onAnnounceTick() every 100 ms wall until START: ANNOUNCE(outputs, observer, mission duration),
//                    or ERROR again while failed
//   SYNC r           checks the period against the base step (must be an integer multiple), asks
//                    the hooks for missing links: READY(r, step_multiple) or WAITING(r, links)
//   START            takes the table: own group, each input's held-value rule (HeldRule, from its
//                    producer's period and group); publishes the outputs stamped t_0
//   STEP k, group g  ignored unless g is this participant's group and k % multiple == 0; then waits
//                    (event driven: onArrival) until every input has the message stamped
//                    rule.stampFor(t_k), calls step(t_k, period), publishes outputs stamped
//                    t_k + period, drops messages older than stampFor(t_k + base step) and answers
//                    DONE(k) (FINISHED(k) if finished())
//   FINISH           close(t_end, false) once readyToClose(t_end); CLOSED
//   ABORT            close(t_end, true) at once; CLOSED
// Any exception of the model becomes ERROR "name: step k (t = ...) failed: what".
#pragma once
#include <string>
#include <vector>

#include "cosim/core/protocol.hpp"

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
  /// At each SYNC, before the link check: every output topic and every participant of the run
  /// (all have announced). An observer may add inputs here (the recorder recording everything).
  virtual void topicsAnnounced(const std::vector<std::string>& topics,
                               const std::vector<std::string>& participants) {}
  virtual void sendStatus(const Status& s) = 0;
  virtual void logError(const std::string& msg) = 0;
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
  ParticipantCore(std::string name, ParticipantHooks& hooks) : name_(std::move(name)), h_(hooks) {}

  // --- declarations, during configure() ---
  void addInput(InputPort* in) { inputs_.push_back(in); }
  void addOutput(const std::string& resolved_topic) { outputs_.push_back(resolved_topic); }
  void requestPeriod(PeriodRequest r) {
    period_req_ = std::move(r);
    period_given_ = true;
  }
  void setObserver(bool o) { observer_ = o; }
  void setMissionDuration(double s) { mission_duration_s_ = s; }

  // --- events ---
  void start();
  /// Returns false once announcing is over (STARTed or closed): the caller may stop its timer.
  bool onAnnounceTick();
  void onCommand(const Command& c);
  void onArrival();

  const std::string& name() const { return name_; }
  bool failed() const { return failed_; }
  bool configured() const { return configured_; }  ///< configure() succeeded
  bool closed() const { return closed_; }
  bool started() const { return started_; }
  uint32_t multiple() const { return multiple_; }
  uint32_t group() const { return group_; }
  double computeSeconds() const { return compute_s_; }  // in configure() and step() [s, steady clock]
  const std::vector<InputPort*>& inputs() const { return inputs_; }

 private:
  void fail(const std::string& what);
  void report(St status, uint64_t step, Nanos t, const std::string& msg = "");
  bool checkPeriod(double base_dt_s);
  void applyTable(const Table& table);
  void tryStep();
  void tryClose();

  std::string name_;
  ParticipantHooks& h_;
  std::vector<InputPort*> inputs_;
  std::vector<std::string> outputs_;
  PeriodRequest period_req_;
  bool observer_ = false;
  double mission_duration_s_ = 0.0;

  bool configured_ = false, failed_ = false, started_ = false, closed_ = false;
  bool pending_ = false, closing_ = false, period_given_ = false;
  uint32_t multiple_ = 1, group_ = 0;
  double base_dt_s_ = 0.0, dt_s_ = 0.0;  // base step, own macro step [s]
  Nanos base_ns_ = 0, period_ns_ = 0;
  Nanos t_pending_ = 0, t_close_ = 0;
  uint64_t k_pending_ = 0, k_close_ = 0;
  double compute_s_ = 0.0;
  std::string error_;
};

}  // namespace hbt::cosim::core
