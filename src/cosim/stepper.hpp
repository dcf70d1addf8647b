// Master stepper: owns simulated time. Publishes /clock and /sim/step at the macro step and
// advances only when every participant has reported its step done (see participant.hpp for the
// protocol). Stops the run at the end of the mission (a participant reports FINISHED) or at
// `until_s`, on an ERROR status, or when a participant does not answer within `timeout_s`
// (wall clock): then it names the participant(s), ABORTs so files are closed, writes
// `status_file` (JSON: status, message, sim_time_s, wall_time_s, steps, cpu_time_s per node) and
// shuts ROS down. The exit status of a run is read from that file by scripts/twin.
//
// Parameters (private): participants [list of names], dt_s [s], until_s [s] (<= 0: mission end),
// timeout_s [s wall], startup_timeout_s [s wall], status_file [path], progress [bool].
#pragma once
#include <hybrid_bus_twin/StepCommand.h>
#include <hybrid_bus_twin/StepStatus.h>
#include <ros/ros.h>

#include <chrono>
#include <map>
#include <string>
#include <vector>

namespace hbt::cosim {

class Stepper {
 public:
  Stepper(ros::NodeHandle nh, ros::NodeHandle pnh);
  /// Reads parameters; returns false (after writing the status file) on bad parameters.
  bool start();

 private:
  enum class Phase { Announce, Sync, Stepping, Closing, Done };
  struct Peer {
    uint8_t last_status = 255;
    uint64_t last_step = 0;
    bool announced = false, done = false, closed = false;
    double cpu_s = 0.0;
    std::string waiting_for;  // last WAITING message (links not yet connected)
  };
  void onStatus(const hybrid_bus_twin::StepStatus::ConstPtr& s);
  void onTimer(const ros::WallTimerEvent&);
  void sendSync();
  void sendStep();
  void finish(bool aborted, const std::string& reason);
  void complete();
  void printProgress(bool force);
  void writeStatus(const std::string& status, const std::string& message);
  double wallSeconds() const;
  std::string missing(bool (*pred)(const Peer&)) const;

  ros::NodeHandle nh_, pnh_;
  ros::Publisher clock_pub_, cmd_pub_;
  ros::Subscriber status_sub_;
  ros::WallTimer timer_;
  std::vector<std::string> names_;
  std::map<std::string, Peer> peers_;
  Phase phase_ = Phase::Announce;
  double dt_s_ = 0.01, until_s_ = 0.0, timeout_s_ = 1.0, startup_timeout_s_ = 60.0;
  double mission_duration_s_ = 0.0;
  bool progress_ = true, aborted_ = false;
  std::string status_file_, abort_reason_;
  uint64_t k_ = 0, sync_round_ = 0;
  ros::Time t_;
  std::chrono::steady_clock::time_point wall0_, step_sent_, phase_since_, last_print_;
};

}  // namespace hbt::cosim
