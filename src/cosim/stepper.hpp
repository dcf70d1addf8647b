// Master stepper (ROS node/nodelet): owns simulated time. The protocol is the ROS-free state
// machine core::StepperCore (core/stepper_core.hpp, tested in-process); this class reads the
// parameters, translates StepStatus -> core events and core commands -> StepCommand and /clock,
// drives the core's wall-clock timeouts with a 50 ms wall timer, prints the progress line, writes
// `status_file` (JSON: status, message, sim_time_s, wall_time_s, steps, macro_step_s, compute_time_s
// per node, process_cpu_s per process: core/process_cpu.hpp) and shuts ROS down. The run ends at the end of the mission (a participant reports
// FINISHED), at `until_s`, on an ERROR status (at the step that failed), or when no participant
// progressed within `timeout_s` (wall clock; the silent ones are named). The exit status of a run is read from the status file by scripts/twin.
//
// Participants: the private list `participants` if given, else the names registered under
// /twin/participants/<name> (each participant's launch include registers itself; sorted by name).
// Parameters (private): participants [list of names, optional], dt_s [s] (base step), until_s [s] (<= 0:
// mission end), timeout_s [s wall], startup_timeout_s [s wall], status_file [path],
// progress [bool], order [list of groups, each a list of names (or one name); optional]:
// Gauss-Seidel groups, e.g. [[vehicle], [engine]]: a participant reads the fresh value of a
// producer in an earlier group (so within a base step the groups step one after the other, by
// their data); absent = all in one group (Jacobi). Every participant except the recorder must be
// in exactly one group; the recorder is always in the last one.
// clock_period_s [s sim, default 0.1; 0 = every base step], clock_wall_period_s [s wall, default
// 0.05]: /clock is published at t = 0, then (with the time every participant is done through) at
// most once per this simulated period and per this wall period, and at t_end (observers only:
// nothing of the protocol reads it; every process with use_sim_time wakes for each one).
// window_steps [base steps, default 50, 1..100000]: the report window W (core/stepper_core.hpp):
// participants report at every multiple of W and the grants reach 2 W ahead of the slowest.
#pragma once
#include <hybrid_bus_twin/StepStatus.h>
#include <ros/ros.h>

#include <chrono>
#include <memory>
#include <string>

#include "cosim/core/stepper_core.hpp"

namespace hbt::cosim {

/// ROS parameter where the stepper leaves its process ("host:pid") at its start: the recorder
/// ends a stepper that fell silent (died or hung, core/protocol.hpp) so that roslaunch stops.
inline constexpr char kStepperProcessParam[] = "/twin/stepper_process";

class Stepper : public core::StepperTransport {
 public:
  Stepper(ros::NodeHandle nh, ros::NodeHandle pnh);
  /// A run stopped from outside before it completed (SIGINT/SIGTERM: roslaunch shuts the nodes
  /// down, Ctrl-C on `twin run`) leaves status "interrupted", message "interrupted at t = ... s"
  /// (the time every participant was done through: what the bag holds).
  ~Stepper() override;
  /// mode:=nodelets: at the run's end, a participant of this process still inside its model step
  /// (it blocks its thread for good, and the manager could never shut down) ends the process
  /// (exit status 1) once the status is written; roslaunch then stops the run (the manager is
  /// required). The bag is closed already: the recorder runs on a thread of its own.
  void endProcessIfStuck(bool on) { end_process_if_stuck_ = on; }
  /// Reads parameters; returns false (after writing the status file) on bad parameters.
  bool start();

 private:
  void onStatus(const hybrid_bus_twin::StepStatus::ConstPtr& s);
  void onTimer(const ros::WallTimerEvent&);
  double wallNow() const;
  std::string readParams(core::StepperConfig& cfg);
  void writeStatus(const std::string& status, const std::string& message, double sim_s,
                   uint64_t steps, double wall_s);
  // core::StepperTransport
  void sendCommand(const core::Command& c) override;
  void publishClock(core::Nanos t) override;
  void progress(bool force) override;
  void runEnded(bool aborted, const std::string& reason) override;
  void warn(const std::string& msg) override { ROS_WARN_STREAM(msg); }
  void complete() override;
  /// Its thread (mode:=nodelets: this process, StepWatch) or its process on this host.
  core::TaskState taskState(const std::string& name, const std::string& process) override;

  ros::NodeHandle nh_, pnh_;
  ros::Publisher clock_pub_, cmd_pub_;
  ros::Subscriber status_sub_;
  ros::WallTimer timer_;
  std::unique_ptr<core::StepperCore> core_;
  bool progress_ = true;
  std::string status_file_;
  bool status_written_ = false;  // the run's end (ok, error) is on record
  bool end_process_if_stuck_ = false;
  double cpu_at_start_s_ = 0.0;  // this process's CPU time when START was sent [s]
  std::chrono::steady_clock::time_point epoch_, last_print_;
};

}  // namespace hbt::cosim
