// Which participant of this process is inside its model step, and since when (ROS-free). In
// mode:=nodelets the participants of a manager share one thread (cosim/participant_main.hpp), so
// one stuck in its step (an endless loop, a dead lock in a partner's model) blocks every other
// participant on that thread, and none of them answers the stepper. The stepper runs on a thread
// of its own and, at its step timeout, names the one that is inside its step instead of everyone
// who is waiting behind it; at the run's end it ends a process whose participant never came back.
// It also knows each participant's thread, whose state the stepper reads to tell a participant
// starved of CPU from a dead one (stepper.cpp). Cost: three relaxed atomic stores per step.
#pragma once
#include <atomic>
#include <string>
#include <vector>

#include "cosim/core/process_cpu.hpp"
#include "cosim/core/protocol.hpp"

namespace hbt::cosim::core {

class StepWatch {
 public:
  explicit StepWatch(std::string participant);  ///< registers it in this process
  ~StepWatch();                                 ///< unregisters it
  StepWatch(const StepWatch&) = delete;
  StepWatch& operator=(const StepWatch&) = delete;

  /// Around the model's step from t [ns]; now_s: steady clock [s] (the caller reads it anyway).
  void enter(Nanos t, double now_s) {
    since_s_.store(now_s, std::memory_order_relaxed);
    tid_.store(currentThreadId(), std::memory_order_relaxed);
    t_.store(t, std::memory_order_release);
  }
  void leave() { t_.store(kIdle, std::memory_order_release); }

  struct InStep {
    std::string participant;
    Nanos t = 0;          ///< the step's start [ns]
    double for_s = 0.0;   ///< how long it has been inside [s]
  };
  /// Every participant of this process that is inside its step now (now_s: steady clock [s]).
  static std::vector<InStep> inStep(double now_s);
  /// "" if none is, else "in the stepper's process, X has been inside its model step (from
  /// t = ... s) for ... s" (for the timeout message).
  static std::string describe(double now_s);
  /// The kernel id of the thread `participant` of this process steps on (0: unknown, not stepped yet).
  static long threadOf(const std::string& participant);

 private:
  static constexpr Nanos kIdle = -1;
  std::string participant_;
  std::atomic<Nanos> t_{kIdle};
  std::atomic<double> since_s_{0.0};
  std::atomic<long> tid_{0};
};

/// The steady clock [s] StepWatch and the participants' compute times use.
double steadyNow_s();

}  // namespace hbt::cosim::core
