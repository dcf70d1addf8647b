// Lock-step co-simulation participant: the one implementation of the step protocol, used by every
// node of the twin (as a process or as a nodelet).
//
// Protocol (the master stepper drives it, see stepper.hpp):
//  1. start-up: configure() reads and validates parameters (hbt::InputError -> ERROR status naming
//     file and key); the participant ANNOUNCEs itself every 100 ms (wall) until the first SYNC.
//     On each SYNC round r it checks its links -- every input has a connected publisher and every
//     output has as many connected subscribers as the master lists -- and answers READY(r) or
//     WAITING(r). Step 0 starts only after one round in which everyone answered READY, so no
//     message of t = 0 is lost and the recorder is subscribed before time starts.
//  2. STEP k (stamp t_k): at k = 0 the participant first publishes its outputs at t_0. It then
//     waits (event driven, no blocking) until every input has a message stamped exactly t_k,
//     calls step(t_k, dt), publishes its outputs stamped t_k + dt and answers DONE(k)
//     (FINISHED(k) when finished() says the participant has reached the end of its input).
//     All couplings are thus explicit (Jacobi) with one macro step of delay: deterministic.
//  3. FINISH / ABORT: close() flushes files; the participant answers CLOSED.
// Any exception thrown by the model is reported as ERROR with the participant's name and the
// message; the stepper then aborts the run.
#pragma once
#include <hybrid_bus_twin/StepCommand.h>
#include <hybrid_bus_twin/StepStatus.h>
#include <ros/ros.h>

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "cosim/input_buffer.hpp"

namespace hbt::cosim {

class Participant {
 public:
  /// `name` identifies the participant to the stepper; empty = the node/nodelet name.
  Participant(ros::NodeHandle nh, ros::NodeHandle pnh, std::string name = "");
  virtual ~Participant() = default;
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  /// Configures the model and joins the protocol. Never throws: errors become ERROR statuses.
  void start();
  const std::string& name() const { return name_; }
  bool failed() const { return failed_; }

 protected:
  /// Reads parameters (private namespace) and builds the model; declare inputs/outputs here.
  virtual void configure() = 0;
  /// Publishes the outputs describing the current state, stamped t.
  virtual void publishOutputs(const ros::Time& t) = 0;
  /// Advances the model from t to t + dt_s; inputs stamped t are available via Input::at(t).
  virtual void step(const ros::Time& t, double dt_s) = 0;
  /// True once this participant reached the end of its input (e.g. end of the mission).
  virtual bool finished() const { return false; }
  /// Flush and close files (FINISH or ABORT). `t_end` is the time of the last state.
  virtual void close(const ros::Time& t_end, bool aborted) {}
  /// At FINISH, close() is delayed until this returns true (e.g. the recorder waits for the
  /// outputs stamped t_end); ABORT closes at once.
  virtual bool readyToClose(const ros::Time& t_end) const { return true; }
  /// For inputs that are not typed messages (the recorder's raw topics).
  InputBase& addCustomInput(std::unique_ptr<InputBase> in) {
    inputs_.push_back(std::move(in));
    return *inputs_.back();
  }
  std::function<void()> arrivalCallback() { return [this] { tryStep(); }; }
  const std::vector<std::unique_ptr<InputBase>>& inputs() const { return inputs_; }

  template <class M>
  Input<M>& addInput(const std::string& topic) {
    auto in = std::make_unique<Input<M>>(nh_, topic, [this] { tryStep(); });
    Input<M>& ref = *in;
    inputs_.push_back(std::move(in));
    return ref;
  }
  template <class M>
  ros::Publisher addOutput(const std::string& topic) {
    ros::Publisher p = nh_.advertise<M>(topic, 1000);
    outputs_.push_back(p);
    return p;
  }
  /// The YAML file the parameters of this participant came from (param `config_file`).
  std::string configFile() const;

  ros::NodeHandle nh_, pnh_;

 private:
  void onCommand(const hybrid_bus_twin::StepCommand::ConstPtr& cmd);
  void onAnnounceTimer(const ros::WallTimerEvent&);
  void tryStep();
  void tryClose();
  void report(uint8_t status, uint64_t step, const ros::Time& stamp, const std::string& msg = "");
  std::string missingLinks() const;
  void fail(const std::string& what);

  std::string name_;
  std::vector<std::unique_ptr<InputBase>> inputs_;
  std::vector<ros::Publisher> outputs_;
  ros::Publisher status_pub_;
  ros::Subscriber cmd_sub_;
  ros::WallTimer announce_timer_;
  std::recursive_mutex mutex_;
  bool configured_ = false, failed_ = false, synced_ = false, closed_ = false;
  bool pending_ = false, published_initial_ = false, closing_ = false;
  ros::Time t_close_;
  uint64_t k_close_ = 0;
  ros::Time t_pending_;
  uint64_t k_pending_ = 0;
  double dt_pending_s_ = 0.0;
  double cpu_s_ = 0.0;
  std::string error_;
};

/// Simulated time of step k, computed in integer nanoseconds so that every node agrees exactly.
ros::Time stepTime(uint64_t k, double dt_s);
/// Adds dt_s to t exactly (dt rounded to whole nanoseconds).
ros::Time addStep(const ros::Time& t, double dt_s);

}  // namespace hbt::cosim
