// The lock-step step protocol as plain data (no ROS): the commands of the master stepper, the
// statuses of the participants and the held-value rule. The ROS messages StepCommand/StepStatus
// (msg/) carry exactly these fields; src/cosim/stepper.cpp and participant.cpp only translate.
//
// Sequence (see stepper_core.hpp and participant_core.hpp for each side):
//   participant: ANNOUNCE(outputs, observer, mission_duration_s) every 100 ms until STARTed
//   stepper:     SYNC round r (dt) ...  participant: READY(r, step_multiple) | WAITING(r, links)
//   stepper:     START (table: topic -> producer multiple and group; participant -> multiple, group)
//                every participant publishes its outputs stamped t_0 = 0
//   stepper:     for k = 0, 1, ...: for each group g in order: STEP(k, t_k, g) to the participants
//                of g with k % multiple == 0; wait for all their DONE(k) / FINISHED(k)
//   stepper:     FINISH (a FINISHED or until_s) | ABORT (ERROR, timeout)  -> everyone CLOSED
//
// Time is simulated time in integer nanoseconds (`Nanos`), so every participant agrees exactly.
#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace hbt::cosim::core {

using Nanos = int64_t;

/// Values match msg/StepCommand.msg.
enum class Cmd : uint8_t { Step = 0, Finish = 1, Abort = 2, Sync = 3, Start = 4 };
/// Values match msg/StepStatus.msg.
enum class St : uint8_t { Ready = 0, Done = 1, Finished = 2, Error = 3, Closed = 4, Waiting = 5, Announce = 6 };

/// START table: who produces which topic, at which rate, in which group.
struct Table {
  std::vector<std::string> topics;
  std::vector<uint32_t> topic_multiple, topic_group;
  std::vector<std::string> participants;
  std::vector<uint32_t> participant_multiple, participant_group;
};

struct Command {
  Cmd command = Cmd::Step;
  uint64_t step = 0;   // k (STEP, FINISH, ABORT) or SYNC round
  Nanos t = 0;         // t_k (STEP), t_end (FINISH, ABORT)
  double dt_s = 0.0;   // base step [s]
  uint32_t group = 0;  // STEP: the group commanded
  std::string reason;  // ABORT / FINISH
  Table table;         // START only
};

struct Status {
  std::string node;
  St status = St::Announce;
  uint64_t step = 0;   // k of the step done, or the SYNC round answered
  Nanos t = 0;         // DONE: t_k + period (stamp of the outputs published)
  double compute_time_s = 0.0;  // in the model so far [s, steady clock] (participant_core.cpp)
  std::string message;
  // ANNOUNCE
  std::vector<std::string> outputs;   // resolved output topics
  bool observer = false;              // reads, never produces (the recorder): stepped last, Jacobi
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

/// Sim time in ns of a duration in seconds (rounded), as every participant computes it.
inline Nanos toNanos(double s) { return static_cast<Nanos>(std::llround(s * 1e9)); }

/// Seconds of a sim time, computed as ros::Time::toSec() does (same bits).
inline double toSec(Nanos t) {
  return static_cast<double>(t / 1000000000) + 1e-9 * static_cast<double>(t % 1000000000);
}

}  // namespace hbt::cosim::core
