// Diagnostics of one lock-step participant as plain C++ (no ROS): the statistics of its step
// compute time, its named warnings and the cadence of its statuses. The ROS base class
// cosim::Participant (../participant.hpp) owns one, feeds it and publishes each Status as a
// diagnostic_msgs/DiagnosticStatus on /diagnostics (docs/diagnostics.md).
//
// Warnings are judged from the model state only (never from wall time), at the stamp of every
// state the participant publishes, so they are the same in every run of a scenario:
//   Warning::update(t, condition)  condition true without a break for on_delay (persistence) ->
//                                  raised at that t (first raise latched: first_time, message);
//                                  the warning clears as soon as the condition is false.
//   Hysteresis                     a two-level switch for conditions on a noisy signal (on above
//                                  on_level, off again only below off_level).
// Statuses are due at the first state at or after every multiple of the period in simulated time
// (t = 0 included), plus one final status at the end of the run (close()).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "cosim/core/protocol.hpp"

namespace hbt::cosim::core {

struct KeyValue {
  std::string key, value;
};

/// Count, mean and maximum of a quantity (e.g. the wall compute time of step() [ms]) over the
/// current window (since the last closeWindow()) and over the whole run.
class WindowStats {
 public:
  void add(double x);
  void closeWindow();
  uint64_t count() const { return n_; }
  double mean() const { return n_ ? sum_ / static_cast<double>(n_) : 0.0; }
  double max() const { return n_ ? max_ : 0.0; }
  uint64_t totalCount() const { return total_n_; }
  double totalMean() const { return total_n_ ? total_sum_ / static_cast<double>(total_n_) : 0.0; }
  double totalMax() const { return total_n_ ? total_max_ : 0.0; }

 private:
  uint64_t n_ = 0, total_n_ = 0;
  double sum_ = 0.0, max_ = 0.0, total_sum_ = 0.0, total_max_ = 0.0;
};

/// Two-level switch: turns on when x > on_level, turns off only when x < off_level
/// (off_level <= on_level; equal levels = a plain threshold). Starts off.
class Hysteresis {
 public:
  Hysteresis(double on_level, double off_level);
  bool update(double x);
  bool on() const { return on_; }

 private:
  double on_level_, off_level_;
  bool on_ = false;
};

/// A named warning of a participant (see the header comment for the rule).
class Warning {
 public:
  Warning(std::string name, Nanos on_delay);
  /// The condition at state time t (non-decreasing). Returns true when the warning is raised by
  /// this call (the caller may then describe it with setMessage()).
  bool update(Nanos t, bool condition);
  /// Describes the current raise; the first raise's text is kept as firstMessage().
  void setMessage(const std::string& message);

  const std::string& name() const { return name_; }
  Nanos onDelay() const { return on_delay_; }
  bool active() const { return active_; }
  uint64_t raised() const { return raised_; }    ///< times raised so far
  Nanos firstTime() const { return first_t_; }   ///< state time of the first raise (-1: never)
  Nanos activeTime() const { return active_ns_; }  ///< time spent raised (between state times)
  const std::string& firstMessage() const { return first_msg_; }
  const std::string& message() const { return msg_; }

 private:
  std::string name_;
  Nanos on_delay_;
  bool cond_ = false, active_ = false, seen_ = false;
  Nanos since_ = 0, last_t_ = 0, first_t_ = -1, active_ns_ = 0;
  uint64_t raised_ = 0;
  std::string first_msg_, msg_;
};

/// One status of a participant: level (Level values = diagnostic_msgs/DiagnosticStatus), text
/// and key/values (the base keys of Diagnostics::status, then the participant's own).
struct DiagStatus {
  enum Level : uint8_t { Ok = 0, Warn = 1 };
  uint8_t level = Ok;
  std::string message;
  std::vector<KeyValue> values;
};

class Diagnostics {
 public:
  /// Status period in simulated time [ns] (> 0).
  void setPeriod(Nanos period);
  Nanos period() const { return period_; }
  /// Declares a warning (names unique per participant); the reference stays valid.
  Warning& addWarning(const std::string& name, double on_delay_s);
  const std::vector<std::unique_ptr<Warning>>& warnings() const { return warnings_; }
  /// Wall compute time of one step() [s].
  void addStepTime(double wall_s) { step_ms_.add(1e3 * wall_s); }
  const WindowStats& stepTimes() const { return step_ms_; }
  /// True if a status is due for the state at t (the first state at or after each multiple of
  /// the period); advances the next due time.
  bool due(Nanos t);
  /// The status of the state at t and closes the compute-time window. Keys (README
  /// "Diagnostics"): sim_time_s, final, steps_window, step_compute_ms_mean, step_compute_ms_max,
  /// steps_total, step_compute_ms_mean_run, step_compute_ms_max_run, compute_time_s, warnings_checked,
  /// and for every warning raised so far warning/<name>/{first_time_s, raised, active, active_s,
  /// message}. Level Warn while a warning is active.
  DiagStatus status(Nanos t, bool final, double compute_time_s);

 private:
  Nanos period_ = 1000000000, next_due_ = 0;
  WindowStats step_ms_;
  std::vector<std::unique_ptr<Warning>> warnings_;
};

/// Seconds of a time in ns with all 9 decimals ("30.000000000"): exact, parses back to the
/// nearest double of t.
std::string formatSeconds(Nanos t);
/// A number as "%.6g".
std::string formatNumber(double x);
/// printf into a std::string (warning messages).
std::string formatText(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

}  // namespace hbt::cosim::core
