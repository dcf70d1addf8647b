#include "cosim/participant.hpp"

#include <ros/master.h>

#include <cmath>
#include <ctime>
#include <exception>
#include <set>
#include <sstream>

namespace hbt::cosim {

using hybrid_bus_twin::StepCommand;
using hybrid_bus_twin::StepStatus;

namespace {

double cpuNow() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

int64_t dtNs(double dt_s) { return std::llround(dt_s * 1e9); }

/// Subscriber nodes registered at the master for each topic.
std::map<std::string, std::set<std::string>> masterSubscribers() {
  std::map<std::string, std::set<std::string>> out;
  XmlRpc::XmlRpcValue req, res, payload;
  req[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", req, res, payload, false)) return out;
  XmlRpc::XmlRpcValue subs = payload[1];
  for (int i = 0; i < subs.size(); ++i) {
    const std::string topic = subs[i][0];
    for (int j = 0; j < subs[i][1].size(); ++j) out[topic].insert(std::string(subs[i][1][j]));
  }
  return out;
}

}  // namespace

ros::Time stepTime(uint64_t k, double dt_s) {
  ros::Time t;
  t.fromNSec(static_cast<uint64_t>(k) * static_cast<uint64_t>(dtNs(dt_s)));
  return t;
}

ros::Time addStep(const ros::Time& t, double dt_s) {
  ros::Time r;
  r.fromNSec(t.toNSec() + static_cast<uint64_t>(dtNs(dt_s)));
  return r;
}

Participant::Participant(ros::NodeHandle nh, ros::NodeHandle pnh, std::string name)
    : nh_(std::move(nh)), pnh_(std::move(pnh)), name_(std::move(name)) {
  if (name_.empty()) {  // the node (or nodelet) name: last component of the private namespace
    const std::string& ns = pnh_.getNamespace();
    name_ = ns.substr(ns.find_last_of('/') + 1);
  }
}

std::string Participant::configFile() const {
  std::string f;
  pnh_.param<std::string>("config_file", f, pnh_.getNamespace() + " (rosparam)");
  return f;
}

void Participant::start() {
  std::lock_guard<std::recursive_mutex> lock(mutex_);
  status_pub_ = nh_.advertise<StepStatus>("/sim/status", 100);
  cmd_sub_ = nh_.subscribe<StepCommand>("/sim/step", 100, &Participant::onCommand, this,
                                        ros::TransportHints().tcpNoDelay());
  try {
    const double c0 = cpuNow();
    configure();
    cpu_s_ += cpuNow() - c0;
    configured_ = true;
  } catch (const std::exception& e) {
    fail(std::string("configuration failed: ") + e.what());
  }
  announce_timer_ = nh_.createWallTimer(ros::WallDuration(0.1), &Participant::onAnnounceTimer, this);
}

void Participant::fail(const std::string& what) {
  failed_ = true;
  error_ = name_ + ": " + what;
  ROS_ERROR_STREAM(error_);
  report(StepStatus::ERROR, k_pending_, t_pending_, error_);
}

void Participant::report(uint8_t status, uint64_t step, const ros::Time& stamp,
                         const std::string& msg) {
  StepStatus s;
  s.header.stamp = stamp;
  s.node = name_;
  s.status = status;
  s.step = step;
  s.cpu_time_s = cpu_s_;
  s.message = msg;
  status_pub_.publish(s);
}

void Participant::onAnnounceTimer(const ros::WallTimerEvent&) {
  std::lock_guard<std::recursive_mutex> lock(mutex_);
  if (failed_) { report(StepStatus::ERROR, k_pending_, t_pending_, error_); return; }
  if (synced_) { announce_timer_.stop(); return; }
  report(StepStatus::ANNOUNCE, 0, ros::Time(0));
}

std::string Participant::missingLinks() const {
  std::ostringstream os;
  for (const auto& in : inputs_)
    if (in->numPublishers() == 0) os << " input " << in->topic() << " has no publisher;";
  const auto subs = masterSubscribers();
  for (const auto& p : outputs_) {
    const auto it = subs.find(p.getTopic());
    const std::size_t want = it == subs.end() ? 0 : it->second.size();
    if (p.getNumSubscribers() < want)
      os << " output " << p.getTopic() << " has " << p.getNumSubscribers() << "/" << want
         << " subscribers connected;";
  }
  if (cmd_sub_.getNumPublishers() == 0) os << " /sim/step not connected;";
  return os.str();
}

void Participant::onCommand(const StepCommand::ConstPtr& cmd) {
  std::lock_guard<std::recursive_mutex> lock(mutex_);
  if (closed_) return;
  switch (cmd->command) {
    case StepCommand::SYNC: {
      if (failed_) { report(StepStatus::ERROR, cmd->step, ros::Time(0), error_); return; }
      if (!configured_) return;
      const std::string missing = missingLinks();
      report(missing.empty() ? StepStatus::READY : StepStatus::WAITING, cmd->step, ros::Time(0),
             missing);
      return;
    }
    case StepCommand::STEP:
      if (failed_) { report(StepStatus::ERROR, cmd->step, cmd->header.stamp, error_); return; }
      synced_ = true;
      pending_ = true;
      k_pending_ = cmd->step;
      t_pending_ = cmd->header.stamp;
      dt_pending_s_ = cmd->dt_s;
      tryStep();
      return;
    case StepCommand::FINISH:
      pending_ = false;
      closing_ = true;
      t_close_ = cmd->header.stamp;
      k_close_ = cmd->step;
      tryClose();
      return;
    case StepCommand::ABORT:
      try {
        close(cmd->header.stamp, true);
      } catch (const std::exception& e) {
        ROS_ERROR_STREAM(name_ << ": closing failed: " << e.what());
      }
      closed_ = true;
      pending_ = false;
      report(StepStatus::CLOSED, cmd->step, cmd->header.stamp, cmd->reason);
      return;
    default:
      return;
  }
}

void Participant::tryClose() {
  if (!closing_ || closed_ || !readyToClose(t_close_)) return;
  try {
    close(t_close_, false);
  } catch (const std::exception& e) {
    ROS_ERROR_STREAM(name_ << ": closing failed: " << e.what());
  }
  closed_ = true;
  closing_ = false;
  report(StepStatus::CLOSED, k_close_, t_close_);
}

void Participant::tryStep() {
  std::lock_guard<std::recursive_mutex> lock(mutex_);
  if (closing_) { tryClose(); return; }
  if (!pending_ || failed_ || closed_) return;
  const ros::Time t = t_pending_;
  if (!published_initial_) {
    publishOutputs(t);
    published_initial_ = true;
  }
  for (const auto& in : inputs_)
    if (!in->has(t)) return;  // wait for the inputs stamped t_k
  pending_ = false;
  const ros::Time t_next = addStep(t, dt_pending_s_);
  try {
    const double c0 = cpuNow();
    step(t, dt_pending_s_);
    cpu_s_ += cpuNow() - c0;
    publishOutputs(t_next);
  } catch (const std::exception& e) {
    fail(std::string("step ") + std::to_string(k_pending_) + " (t = " +
         std::to_string(t.toSec()) + " s) failed: " + e.what());
    return;
  }
  for (const auto& in : inputs_) in->dropBefore(t_next);
  report(finished() ? StepStatus::FINISHED : StepStatus::DONE, k_pending_, t_next);
}

}  // namespace hbt::cosim
