// Lock-step co-simulation participant: the one implementation of the step protocol used by every
// node of the twin (as a process or as a nodelet). The protocol itself is the ROS-free state
// machine core::ParticipantCore (core/participant_core.hpp, tested in-process); this class only
// translates StepCommand/StepStatus messages, timers and topics into its events.
//
// Protocol (the master stepper drives it, see stepper.hpp and core/stepper_core.hpp):
//  1. start-up: configure() reads and validates parameters (hbt::InputError -> ERROR status naming
//     file and key) and declares inputs and outputs; the participant ANNOUNCEs itself every
//     100 ms (wall) with its output and input topics, until START. On each SYNC round r it checks
//     its links -- every input has a connected publisher and every output has as many connected
//     subscribers as the master lists -- and answers READY(r) or WAITING(r). After one round in
//     which everyone answered READY the stepper sends START with the table of producers (topic ->
//     macro step, group) and readers; every participant then publishes its outputs stamped
//     t_0 = 0, so nothing of t = 0 is lost.
//  2. Rates. The stepper's base step is dt (launch `step`). A participant's macro step P is
//     `cosim/macro_step_s` in its private namespace (its YAML; absent = dt). P must be an
//     integer multiple m of dt (checked before step 0: not a multiple, <= 0, NaN, not a number ->
//     ERROR naming the file and the key). It steps only at base steps k with k % m == 0:
//     step(t_k, P) advances t_k -> t_k + P and its outputs are stamped t_k + P; they hold (are
//     what every consumer reads) until its next step. `cosim/thread` [name, default lockstep]:
//     as a nodelet, the callback thread it runs on (participant_main.hpp; a slow participant
//     that exchanges rarely computes beside the torque loop; no effect on results, none as a node).
//  3. Held values. For its step at t_k the participant waits (event driven) until every input
//     has the message its rule names, then calls step(t_k, P); Input::at(t_k) returns it. For a
//     producer of macro step P_p:
//        Jacobi (producer in the same or a later group):  stamped floor(t_k / P_p) * P_p
//        Gauss-Seidel (producer in an earlier group):      stamped floor(t_k / P_p) * P_p + P_p
//     i.e. at one rate and one group (the default) exactly the message stamped t_k (one macro step
//     of delay, Jacobi), and for an earlier group its fresh value stamped t_{k+1}. Deterministic,
//     independent of arrival order. The recorder (an observer) always reads by the Jacobi rule.
//     A slow participant sees point samples of faster producers (no averaging over its step):
//     where the mean over the step matters, use a cumulative output of the producer (e.g.
//     fuel_mass_kg, nox_mass_kg, heat_to_coolant_j) and take the difference between two steps.
//  4. Stepping is data-driven: the stepper GRANTs a horizon (at most 2 W base steps ahead of the
//     slowest participant, W = `window_steps`), and every participant steps each of its due
//     steps below it as soon as its inputs are there -- so a Gauss-Seidel chain (stepper param
//     `order`, e.g. vehicle -> EMS -> engine) runs in its order by its data alone, with no
//     command per group or base step. Outputs are sent only at the stamps some participant
//     reads (output.hpp).
//  5. The participant reports DONE(n) (every due step below n done) at every multiple of W, when
//     it did all it was granted and at least every timeout / 4 of wall time; FINISHED when
//     finished() says it reached the end of its input -- the only end-of-mission signal (the
//     mission duration, for the progress line only, travels in ANNOUNCE: setMissionDuration()).
//     It steps no more after FINISHED; others may have stepped a little past the end (their
//     later states reach no one: the end, t_end, is the step after the FINISHED one).
//  6. FINISH / ABORT: close() flushes files (FINISH waits for readyToClose()); answers CLOSED.
// Any exception thrown by the model is reported as ERROR with the participant's name and the
// message; the stepper then aborts the run.
//
// Diagnostics (docs/diagnostics.md; ROS-free part core/diagnostics.hpp): every participant
// publishes a diagnostic_msgs/DiagnosticArray with one DiagnosticStatus (name = participant name,
// hardware_id = host) on /diagnostics at the first state at or after every `period_s` of
// simulated time and a final one at close() (key final = true): the wall compute time of its
// step() calls (mean/max over the window and over the run), its CPU time, the subclass's own
// key/values (diagnosticValues()) and its warnings (addWarning() in configure(), judged in
// checkWarnings() after every step and at t_0) with the simulated time of their first raise.
// /diagnostics is an output of the link check (every subscriber connected before START) but no
// lock-step topic: nothing steps on it and it is not in run.bag (the recorder writes it to
// diagnostics.bag). Parameters: the status period /scenario/diagnostics/period_s
// (config/diagnostics.yaml, file named by /scenario/diagnostics_file; absent = the default); the
// thresholds of the participant's own warnings in the `diagnostics:` section of its YAML
// (readWarningThresholds).
#pragma once
#include <diagnostic_msgs/DiagnosticArray.h>
#include <hybrid_bus_twin/StepCommand.h>
#include <hybrid_bus_twin/StepStatus.h>
#include <ros/ros.h>

#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "common/params.hpp"
#include "cosim/core/diagnostics.hpp"
#include "cosim/core/diagnostics_params.hpp"
#include "cosim/core/participant_core.hpp"
#include "cosim/input_buffer.hpp"
#include "cosim/output.hpp"
#include "cosim/wiring.hpp"

namespace hbt::cosim {

class Participant {
 public:
  /// `name` identifies the participant to the stepper; empty = the node/nodelet name.
  Participant(ros::NodeHandle nh, ros::NodeHandle pnh, std::string name = "");
  virtual ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  /// Configures the model and joins the protocol. Never throws: errors become ERROR statuses.
  void start();
  const std::string& name() const { return name_; }
  bool failed() const { return core_.failed(); }

 protected:
  /// Reads parameters (private namespace) and builds the model; declare inputs/outputs here.
  virtual void configure() = 0;
  /// Publishes the outputs describing the current state, stamped t.
  virtual void publishOutputs(const ros::Time& t) = 0;
  /// Advances the model from t to t + dt_s (dt_s = this participant's macro step); the inputs
  /// held at t are available via Input::at(t).
  virtual void step(const ros::Time& t, double dt_s) = 0;
  /// True once this participant reached the end of its input (e.g. end of the mission).
  virtual bool finished() const { return false; }
  /// Flush and close files (FINISH or ABORT). `t_end` is the time of the last state.
  virtual void close(const ros::Time& t_end, bool aborted) {}
  /// At FINISH, close() is delayed until this returns true (e.g. the recorder waits for the
  /// outputs held at t_end); ABORT closes at once.
  virtual bool readyToClose(const ros::Time& t_end) const { return true; }
  /// The stepper fell silent while stepping (died or hung: core/protocol.hpp); close(t, true) has
  /// run. `message` says how long it was silent and at which t this participant closed.
  virtual void stepperLost(const ros::Time& t, const std::string& message) {}
  /// At each SYNC before step 0: the end of the run as known [s] (until, or the longest mission
  /// a participant announced, the earlier of both; 0 = unknown). Throw (hbt::ModelDivergence,
  /// hbt::InputError, ...) when this participant cannot run that far: the run ends before step 0.
  virtual void checkRunEnd(double end_s) {}
  /// At each SYNC before step 0: every output topic of the run (all participants announced).
  /// An observer may add inputs here (the recorder without a topic list records them all).
  virtual void topicsAnnounced(const std::vector<std::string>& topics,
                               const std::vector<std::string>& participants) {}
  /// For inputs that are not typed messages (the recorder's raw topics).
  InputBase& addCustomInput(std::unique_ptr<InputBase> in) {
    inputs_.push_back(std::move(in));
    core_.addInput(inputs_.back().get());
    return *inputs_.back();
  }
  std::function<void()> arrivalCallback() { return [this] { onArrival(); }; }
  const std::vector<std::unique_ptr<InputBase>>& inputs() const { return inputs_; }

  template <class M>
  Input<M>& addInput(const std::string& topic) {
    auto in = std::make_unique<Input<M>>(nh_, topic, arrivalCallback());
    Input<M>& ref = *in;
    addCustomInput(std::move(in));
    return ref;
  }
  /// An output topic and its observer lane (output.hpp: sent only at the stamps some
  /// participant reads).
  template <class M>
  Output addOutput(const std::string& topic) {
    ros::Publisher p = nh_.advertise<M>(topic, 1000);
    ros::Publisher lane = nh_.advertise<M>(observerLane(p.getTopic()), 1000);
    outputs_.push_back(p);
    outputs_.push_back(lane);
    return Output(p, lane, &core_, core_.addOutput(p.getTopic()), ros::message_traits::datatype<M>());
  }
  /// Wired topics (wiring.hpp): `producer`'s output `key` as declared in its topics.yaml; this
  /// participant's own output `key`, likewise. Throw hbt::InputError when undeclared, of another
  /// type, or (an input) when the producer does not run in this scenario.
  template <class M>
  Input<M>& addInputFrom(const std::string& producer, const std::string& key) {
    return addInput<M>(inputTopic(nh_, producer, key, ros::message_traits::datatype<M>(), name_));
  }
  template <class M>
  Output addOwnOutput(const std::string& key) {
    return addOutput<M>(outputTopic(nh_, name_, key, ros::message_traits::datatype<M>()));
  }
  /// True when `participant` runs in this scenario (its loops close only then).
  bool inScenario(const std::string& participant) const { return cosim::inScenario(nh_, participant); }
  /// The YAML file the parameters of this participant came from (param `config_file`).
  std::string configFile() const;
  /// End of this participant's input [s] (e.g. the mission), announced for the progress line.
  void setMissionDuration(double s) { core_.setMissionDuration(s); }
  /// Overrides `cosim/macro_step_s` (e.g. the recorder's record period). `fallback`: a period
  /// that is not a multiple of the base step runs at the base step instead of failing.
  void setMacroStep(double s, const std::string& where, const std::string& key, bool fallback) {
    core_.requestPeriod({s, where, key, fallback});
  }
  /// Reads only, publishes nothing that others step on (the recorder): Jacobi reads, last group.
  void setObserver(bool o) { core_.setObserver(o); }

  // --- diagnostics (see the header comment) ---
  /// Reads this participant's warning thresholds (in configure()): the `diagnostics:` section of
  /// its own YAML (configFile()), the keys `w.declare(ps, declare_args...)` declares (e.g.
  /// CoolingWarnings). In a scenario (config_file set) every key is required; an unknown key,
  /// NaN or a value out of range is an InputError naming the file and the key.
  template <class W, class... Args>
  void readWarningThresholds(W& w, Args&&... declare_args) {
    readWarningThresholds([&](ParamSet& ps) { w.declare(ps, std::forward<Args>(declare_args)...); });
  }
  void readWarningThresholds(const std::function<void(ParamSet&)>& declare);
  /// Declares a warning (in configure()): raised when its condition held for on_delay_s [s].
  core::Warning& addWarning(const std::string& name, double on_delay_s) {
    return diag_.addWarning(name, on_delay_s);
  }
  /// Judges the warnings from the state just published, stamped t (after every step and at t_0):
  /// `if (w.update(t_ns, condition)) w.setMessage(...)`. Model state only (deterministic).
  virtual void checkWarnings(core::Nanos t) {}
  /// Adds this participant's key/values (solver sub-steps, temperatures ...) to a status of the
  /// state stamped t (called only when a status is published, and only once configure() succeeded:
  /// the final status of a participant that failed to configure has the base keys only).
  virtual void diagnosticValues(core::Nanos t, std::vector<core::KeyValue>& kv) {}
  /// The final status, built and published at FINISH/ABORT just before close() is called.
  const diagnostic_msgs::DiagnosticArray& finalDiagnostics() const { return final_diag_; }

  ros::NodeHandle nh_, pnh_;

 private:
  class Hooks;
  void onCommand(const hybrid_bus_twin::StepCommand::ConstPtr& cmd);
  void onTickTimer(const ros::WallTimerEvent&);
  void onArrival();
  void readMacroStep();
  /// <out_dir>/resolved_config/<name>.csv: every parameter its configure() bound (file, key,
  /// value, unit, set by the file or default); nothing outside a scenario (no /scenario/out_dir).
  void writeResolvedConfig(const std::vector<ResolvedParam>& params) const;
  void readDiagnosticsParams();
  /// After the state stamped t was published: warnings, then a status if one is due (or final).
  void diagnose(core::Nanos t, bool final);

  std::recursive_mutex mutex_;  // first: destroyed last, after every member a callback touches
  std::string name_;
  std::unique_ptr<Hooks> hooks_;
  core::ParticipantCore core_;
  std::vector<std::unique_ptr<InputBase>> inputs_;
  std::vector<ros::Publisher> outputs_;
  ros::Publisher status_pub_, diag_pub_;
  ros::Subscriber cmd_sub_;
  core::DiagnosticsParams diag_params_;
  core::Diagnostics diag_;
  diagnostic_msgs::DiagnosticArray final_diag_;
  std::string host_;
  ros::WallTimer tick_timer_;
};

/// Simulated time of step k, computed in integer nanoseconds so that every node agrees exactly.
ros::Time stepTime(uint64_t k, double dt_s);
/// Adds dt_s to t exactly (dt rounded to whole nanoseconds).
ros::Time addStep(const ros::Time& t, double dt_s);

}  // namespace hbt::cosim
