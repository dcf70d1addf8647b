// ROS transport of core::StepperCore (see stepper.hpp).
#include "cosim/stepper.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/StepCommand.h>
#include <rosgraph_msgs/Clock.h>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "cosim/core/process_cpu.hpp"
#include "cosim/core/step_watch.hpp"
#include "cosim/core/status_file.hpp"
#include "cosim/input_buffer.hpp"
#include "cosim/wiring.hpp"

namespace hbt::cosim {

using hybrid_bus_twin::StepCommand;
using hybrid_bus_twin::StepStatus;
using Clock = std::chrono::steady_clock;

Stepper::Stepper(ros::NodeHandle nh, ros::NodeHandle pnh) : nh_(std::move(nh)), pnh_(std::move(pnh)) {}

double Stepper::wallNow() const { return std::chrono::duration<double>(Clock::now() - epoch_).count(); }

std::string Stepper::readParams(core::StepperConfig& cfg) {
  pnh_.param("dt_s", cfg.dt_s, 0.01);
  pnh_.param("until_s", cfg.until_s, 0.0);
  pnh_.param("timeout_s", cfg.timeout_s, 1.0);
  pnh_.param("startup_timeout_s", cfg.startup_timeout_s, 60.0);
  pnh_.param("clock_period_s", cfg.clock_period_s, 0.1);  // /clock for observers: 10 Hz of sim time
  pnh_.param("clock_wall_period_s", cfg.clock_wall_period_s, 0.05);  // and at most 20 Hz of wall time
  XmlRpc::XmlRpcValue window;
  if (pnh_.getParam("window_steps", window)) {  // absent: the default (50 base steps)
    if (window.getType() != XmlRpc::XmlRpcValue::TypeInt)
      return cfg.where + ": key 'window_steps': must be an integer number of base steps";
    const int w = static_cast<int>(window);
    cfg.window_steps = w < 1 ? 0u : static_cast<uint32_t>(w);  // 0: rejected by validate()
  }
  // participants: the private list if given (hand-written test launches), else the registry
  // /twin/participants/<name> that every participant's launch include writes (one place per
  // participant: launch/include/participant.launch, core.launch for the recorder)
  if (!pnh_.getParam("participants", cfg.participants)) {
    XmlRpc::XmlRpcValue reg;
    if (nh_.getParam(kParticipantRegistry, reg)) {
      if (reg.getType() != XmlRpc::XmlRpcValue::TypeStruct)
        return cfg.where + ": parameter " + kParticipantRegistry + ": expected a map name -> true";
      for (auto it = reg.begin(); it != reg.end(); ++it) cfg.participants.push_back(it->first);  // sorted by name
    }
  }
  const std::string bad_order = cfg.where + ": key 'order': expected a list of groups, each a list of participant names";
  XmlRpc::XmlRpcValue order;
  if (pnh_.getParam("order", order)) {
    using X = XmlRpc::XmlRpcValue;
    if (order.getType() != X::TypeArray) return bad_order;
    for (int g = 0; g < order.size(); ++g) {
      std::vector<std::string> group;
      if (order[g].getType() == X::TypeString) group.push_back(std::string(order[g]));
      else if (order[g].getType() == X::TypeArray)
        for (int i = 0; i < order[g].size(); ++i) {
          if (order[g][i].getType() != X::TypeString) return bad_order;
          group.push_back(std::string(order[g][i]));
        }
      else return bad_order;
      cfg.order.push_back(group);
    }
  }
  return core::validate(cfg);
}

bool Stepper::start() {
  epoch_ = last_print_ = Clock::now();
  pnh_.param<std::string>("status_file", status_file_, "");
  if (!status_file_.empty()) core::reserveStatusSpace(status_file_);
  ros::param::set(kStepperProcessParam, core::processName());  // for the recorder (recorder.hpp)
  pnh_.param("progress", progress_, true);
  core::StepperConfig cfg;
  const std::string error = readParams(cfg);
  if (!error.empty()) {
    ROS_FATAL_STREAM(error);
    writeStatus("error", error, 0.0, 0, 0.0);
    ros::requestShutdown();
    return false;
  }
  core_ = std::make_unique<core::StepperCore>(cfg, *this);
  clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  cmd_pub_ = nh_.advertise<StepCommand>("/sim/step", 100);
  status_sub_ = nh_.subscribe<StepStatus>("/sim/status", 1000, &Stepper::onStatus, this,
                                          ros::TransportHints().tcpNoDelay());
  timer_ = nh_.createWallTimer(ros::WallDuration(0.05), &Stepper::onTimer, this);
  core_->begin(wallNow());
  return true;
}

void Stepper::onStatus(const StepStatus::ConstPtr& m) {
  core::Status s;
  s.node = m->node;
  s.status = static_cast<core::St>(m->status);
  s.step = m->step;
  s.t = static_cast<core::Nanos>(m->header.stamp.toNSec());
  s.compute_time_s = m->compute_time_s;
  s.process_cpu_s = m->process_cpu_s;
  s.process = m->process;
  s.message = m->message;
  s.outputs = m->outputs;
  s.inputs = m->inputs;
  s.observer = m->observer;
  s.mission_duration_s = m->mission_duration_s;
  s.step_multiple = m->step_multiple;
  core_->onStatus(s, wallNow());
}

void Stepper::onTimer(const ros::WallTimerEvent&) { core_->onTick(wallNow()); }

void Stepper::sendCommand(const core::Command& c) {
  if (c.command == core::Cmd::Start) cpu_at_start_s_ = core::processCpuSeconds();
  StepCommand m;
  m.header.stamp = fromNanos(c.t);
  m.command = static_cast<uint8_t>(c.command);
  m.step = c.step;
  m.observer_step = c.observer_step;
  m.confirmed = c.confirmed;
  m.dt_s = c.dt_s;
  m.reason = c.reason;
  m.topics = c.table.topics;
  m.topic_multiple = c.table.topic_multiple;
  m.topic_group = c.table.topic_group;
  m.participants = c.table.participants;
  m.participant_multiple = c.table.participant_multiple;
  m.participant_group = c.table.participant_group;
  m.reader_topic = c.table.reader_topic;
  m.reader_multiple = c.table.reader_multiple;
  m.reader_fresh = c.table.reader_fresh;
  m.reader_observer = c.table.reader_observer;
  m.window = c.table.window;
  m.report_wall_s = c.table.report_wall_s;
  cmd_pub_.publish(boost::make_shared<StepCommand>(m));
}

void Stepper::publishClock(core::Nanos t) {
  rosgraph_msgs::Clock c;
  c.clock = fromNanos(t);
  clock_pub_.publish(boost::make_shared<rosgraph_msgs::Clock>(c));
}

void Stepper::progress(bool force) {
  if (!progress_) return;
  if (!force && std::chrono::duration<double>(Clock::now() - last_print_).count() < 0.5) return;
  last_print_ = Clock::now();
  const double sim = core::toSec(core_->time()), wall = wallNow() - core_->wallStart_s();
  const double total = core_->until_s() > 0.0 ? core_->until_s() : core_->missionDuration_s();
  const double ratio = sim > 0 ? wall / sim : 0.0;
  char buf[200];
  if (total > 0)
    std::snprintf(buf, sizeof buf, "\rt = %8.1f s  %5.1f %% of %.0f s  wall/sim = %.3f  ETA %6.0f s ",
                  sim, 100.0 * sim / total, total, ratio, ratio * (total - sim));
  else
    std::snprintf(buf, sizeof buf, "\rt = %8.1f s  wall/sim = %.3f ", sim, ratio);
  std::fputs(buf, stderr);
  std::fflush(stderr);
}

void Stepper::runEnded(bool aborted, const std::string& reason) {
  if (progress_) std::fprintf(stderr, "\n");
  if (aborted) ROS_ERROR_STREAM("run aborted: " << reason);
  else ROS_INFO_STREAM("run finished: " << reason << " at t = " << core::toSec(core_->time()) << " s");
}

core::TaskState Stepper::taskState(const std::string& name, const std::string& process) {
  const auto [host, pid] = core::splitProcessName(process);
  const auto [own_host, own_pid] = core::splitProcessName(core::processName());
  if (pid == 0 || host != own_host) return {};  // another host: cannot tell
  if (pid != own_pid) return core::readTaskState(pid);
  const long tid = core::StepWatch::threadOf(name);  // a nodelet of this manager: its thread
  return tid > 0 ? core::readTaskState(pid, tid) : core::TaskState{};
}

void Stepper::complete() {
  timer_.stop();
  writeStatus(core_->aborted() ? "error" : "ok", core_->reason(), core::toSec(core_->time()),
              core_->step(), wallNow() - core_->wallStart_s());
  const std::string stuck = core::StepWatch::describe(core::steadyNow_s());
  if (end_process_if_stuck_ && !stuck.empty()) {
    ROS_ERROR_STREAM("stepper: " << stuck << ": it never returns, and the process cannot shut down "
                     "around it: ending the process (status written, bag closed)");
    std::fflush(nullptr);
    std::_Exit(1);
  }
  ros::requestShutdown();
}

Stepper::~Stepper() {
  // no callback may run beside (or after) this: mode:=nodelets unloads from another thread
  timer_.stop();
  status_sub_.shutdown();
  if (!core_ || status_written_) return;
  const double t_s = core::toSec(core_->time());
  std::ostringstream msg;
  msg << "interrupted at t = " << t_s << " s (the run was stopped from outside: SIGINT/SIGTERM)";
  if (progress_) std::fprintf(stderr, "\n");
  std::fprintf(stderr, "stepper: %s\n", msg.str().c_str());
  writeStatus("interrupted", msg.str(), t_s, core_->step(), wallNow() - core_->wallStart_s());
}

void Stepper::writeStatus(const std::string& status, const std::string& message, double sim_s,
                          uint64_t steps, double wall_s) {
  status_written_ = true;
  if (status_file_.empty()) return;
  core::RunStatus st;
  st.status = status;
  st.message = message;
  st.sim_time_s = sim_s;
  st.wall_time_s = wall_s;
  st.steps = steps;
  st.macro_step_s = 0.01;
  if (core_) st.macro_step_s = core_->dt_s();  // (no parameter server call: also at shutdown)
  else pnh_.param("dt_s", st.macro_step_s, 0.01);
  // CPU time per process (user + system) [s]: the participants' processes and the stepper's own
  std::map<std::string, core::CpuReport> reports;
  if (core_)
    for (const auto& kv : core_->peers()) {
      st.compute_time_s[kv.first] = kv.second.compute_s;
      reports[kv.first] = kv.second.cpu;
    }
  reports["stepper"] = {core::processName(), core::processCpuSeconds(), cpu_at_start_s_};
  st.process_cpu = core::cpuByProcess(reports);
  const std::string failure = core::writeStatusFile(status_file_, st);
  if (!failure.empty()) ROS_ERROR_STREAM("stepper: cannot write the status file " << status_file_ << ": " << failure);
}

}  // namespace hbt::cosim
