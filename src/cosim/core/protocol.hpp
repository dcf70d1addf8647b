// The lock-step step protocol as plain data (no ROS): the commands of the master stepper, the
// statuses of the participants, the held-value rule and the reader rule. The ROS messages
// StepCommand/StepStatus (msg/) carry exactly these fields; src/cosim/stepper.cpp and
// participant.cpp only translate.
//
// Sequence (see stepper_core.hpp and participant_core.hpp for each side):
//   participant: ANNOUNCE(outputs, inputs, observer, mission_duration_s) every 100 ms until STARTed
//   stepper:     SYNC round r (dt, t = the run's end as known: until_s or the longest mission
//                announced, the earlier of both; 0 = unknown)
//                participant: READY(r, step_multiple, inputs) | WAITING(r, links) | ERROR (it
//                cannot run to that end)
//   stepper:     START (table: topic -> producer multiple and group; participant -> multiple and
//                group; who reads which topic; the report window W)
//                every participant publishes its outputs stamped t_0 = 0
//   stepper:     GRANT(K, K_obs, L): every participant may step each of its due base steps
//                k < K (observers: k < K_obs) as soon as the inputs its held-value rule names for
//                t_k have arrived (data-driven, in any order); it reports DONE(n) at every
//                multiple of W it passes, when it has done everything granted, and at least every
//                `report_wall_s` [s wall]; FINISHED(n) once it reached the end of its input
//   stepper:     FINISH (end committed: a FINISHED or until_s, every participant done through
//                the end) | ABORT (ERROR, timeout)  -> everyone CLOSED
//   stepper:     QUERY when no participant progressed for timeout_s / 2: every participant that
//                can answers WAITING(n, what it waits for); the silent ones are named at the abort
//   stepper:     its latest GRANT again whenever it sent no command for a report period
//                (report_wall_s = timeout_s / 4): the stepper's heartbeat. A started participant
//                that heard nothing from it for kStepperSilenceReportPeriods report periods (counted
//                from its own last step, so a long step of its own is no silence) takes the
//                stepper as died or hung and closes as at an ABORT (the recorder also records the
//                run's status and ends the stepper's process: recorder.hpp)
//
// Time is simulated time in integer nanoseconds (`Nanos`), so every participant agrees exactly;
// base-step indices are integers (t_k = k * dt).
#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace hbt::cosim::core {

using Nanos = int64_t;

/// Silence of the stepper [report periods] after which a participant takes it as died or hung:
/// 8 x report_wall_s = 2 timeout_s (the stepper's own limit for a silent participant is 1 x).
constexpr double kStepperSilenceReportPeriods = 8.0;

/// Values match msg/StepCommand.msg.
enum class Cmd : uint8_t { Grant = 0, Finish = 1, Abort = 2, Sync = 3, Start = 4, Query = 5 };
/// Values match msg/StepStatus.msg.
enum class St : uint8_t { Ready = 0, Done = 1, Finished = 2, Error = 3, Closed = 4, Waiting = 5, Announce = 6 };

/// START table: who produces which topic, at which rate, in which group; who reads it.
struct Table {
  std::vector<std::string> topics;
  std::vector<uint32_t> topic_multiple, topic_group;
  std::vector<std::string> participants;
  std::vector<uint32_t> participant_multiple, participant_group;
  /// Readers (parallel): topic index, the reader's macro step multiple, fresh (Gauss-Seidel)
  /// read, observer (the recorder: reads the producer's observer lane, see participant_core.hpp).
  std::vector<uint32_t> reader_topic, reader_multiple;
  std::vector<uint8_t> reader_fresh, reader_observer;
  uint32_t window = 1;        ///< W: report at every multiple of W base steps
  double report_wall_s = 0.25;  ///< and at least this often [s wall] while stepping
};

struct Command {
  Cmd command = Cmd::Grant;
  uint64_t step = 0;           // GRANT: horizon K (steps k < K); FINISH, ABORT: k_end; SYNC: round
  uint64_t observer_step = 0;  // GRANT: horizon of the observers
  uint64_t confirmed = 0;      // GRANT: lower bound L of the run's end step (deferred outputs)
  Nanos t = 0;                 // t_K (GRANT), t_end (FINISH, ABORT), the run's end as known (SYNC; 0 = unknown)
  double dt_s = 0.0;           // base step [s]
  std::string reason;          // ABORT / FINISH
  Table table;                 // START (final), SYNC (topics final)
};

struct Status {
  std::string node;
  St status = St::Announce;
  /// DONE, FINISHED, WAITING after QUERY: n = every due step below n is done (the state is at t_n);
  /// ERROR while stepping: the step that failed; READY, WAITING at start-up: the SYNC round.
  uint64_t step = 0;
  Nanos t = 0;                  // DONE, FINISHED: t_n (stamp of the last outputs published)
  double compute_time_s = 0.0;  // in the model so far [s, steady clock] (participant_core.cpp)
  /// CPU time (user + system: the transport's system calls count) of the participant's process so
  /// far [s], and that process as "host:pid" -- the nodelets of one manager share both.
  double process_cpu_s = 0.0;
  std::string process;
  std::string message;
  // ANNOUNCE, READY
  std::vector<std::string> outputs;   // resolved output topics (ANNOUNCE)
  std::vector<std::string> inputs;    // resolved input topics (ANNOUNCE; READY: final list)
  bool observer = false;              // reads, never produces (the recorder): last group, Jacobi
  double mission_duration_s = 0.0;    // 0 = unknown (progress line only)
  // READY
  uint32_t step_multiple = 1;         // macro step / base step
};

/// Held-value rule of one input: the stamp of the producer's message a consumer reads for its
/// step starting at t. P = producer period (0 = unknown producer: the exact stamp t).
///   Jacobi (producer in the same or a later group, and always for observers): floor(t/P)·P
///   Gauss-Seidel (producer in an earlier group): floor(t/P)·P + P  (its fresh value)
struct HeldRule {
  Nanos period = 0;
  bool fresh = false;
  Nanos stampFor(Nanos t) const {
    if (period <= 0) return t;
    const Nanos held = (t / period) * period;
    return fresh ? held + period : held;
  }
};

/// Reader rule, the held-value rule seen from the producer: does a reader stepping every
/// `reader_multiple` base steps (fresh or Jacobi) ever read the output a producer of multiple
/// `producer_multiple` publishes stamped at base step s (a multiple of producer_multiple)?
/// The reader's step k (k % m_c == 0) reads s = floor(k / m_p)·m_p (+ m_p fresh), so s is read
/// iff a multiple of m_c lies in [s0, s0 + m_p) with s0 = s - (fresh ? m_p : 0).
inline bool readsStamp(uint64_t producer_multiple, uint64_t reader_multiple, bool fresh, uint64_t s) {
  const uint64_t mp = producer_multiple < 1 ? 1 : producer_multiple;
  const uint64_t mc = reader_multiple < 1 ? 1 : reader_multiple;
  if (fresh && s < mp) return false;
  const uint64_t s0 = fresh ? s - mp : s;
  const uint64_t first = (s0 + mc - 1) / mc * mc;  // first reader step at or after s0
  return first < s0 + mp;
}

/// Nanoseconds in a second: the sim-time unit.
inline constexpr Nanos kNanosPerSecond = 1000000000;

/// Sim time in ns of a duration in seconds (rounded), as every participant computes it.
inline Nanos toNanos(double s) { return static_cast<Nanos>(std::llround(s * static_cast<double>(kNanosPerSecond))); }

/// Seconds of a sim time, computed as ros::Time::toSec() does (same bits).
inline double toSec(Nanos t) {
  return static_cast<double>(t / kNanosPerSecond) + 1e-9 * static_cast<double>(t % kNanosPerSecond);
}

}  // namespace hbt::cosim::core
