#include "cosim/stepper.hpp"

#include <rosgraph_msgs/Clock.h>

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "cosim/participant.hpp"

namespace hbt::cosim {

using hybrid_bus_twin::StepCommand;
using hybrid_bus_twin::StepStatus;
using Clock = std::chrono::steady_clock;

namespace {
std::string jsonEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '"' || c == '\\') { o += '\\'; o += c; }
    else if (c == '\n') o += "\\n";
    else if (static_cast<unsigned char>(c) < 0x20) o += ' ';
    else o += c;
  }
  return o;
}
double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}
}  // namespace

Stepper::Stepper(ros::NodeHandle nh, ros::NodeHandle pnh) : nh_(std::move(nh)), pnh_(std::move(pnh)) {}

double Stepper::wallSeconds() const { return secondsSince(wall0_); }

bool Stepper::start() {
  wall0_ = phase_since_ = last_print_ = Clock::now();
  pnh_.param<std::string>("status_file", status_file_, "");
  pnh_.param("dt_s", dt_s_, 0.01);
  pnh_.param("until_s", until_s_, 0.0);
  pnh_.param("timeout_s", timeout_s_, 1.0);
  pnh_.param("startup_timeout_s", startup_timeout_s_, 60.0);
  pnh_.param("progress", progress_, true);
  const std::string where = "stepper parameters (launch file)";
  std::string error;
  if (!pnh_.getParam("participants", names_) || names_.empty())
    error = where + ": key 'participants': missing or empty list of participant names";
  else if (!(dt_s_ >= 1e-4 && dt_s_ <= 1.0))
    error = where + ": key 'dt_s': macro step must be in [1e-4, 1] s";
  else if (!(timeout_s_ > 0.0) || !(startup_timeout_s_ > 0.0))
    error = where + ": key 'timeout_s': must be > 0";
  else if (!(until_s_ >= 0.0 || until_s_ < 0.0))
    error = where + ": key 'until_s': NaN";
  if (!error.empty()) {
    ROS_FATAL_STREAM(error);
    writeStatus("error", error);
    ros::requestShutdown();
    return false;
  }
  for (const auto& n : names_) peers_[n] = Peer{};
  clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
  cmd_pub_ = nh_.advertise<StepCommand>("/sim/step", 100);
  status_sub_ = nh_.subscribe<StepStatus>("/sim/status", 1000, &Stepper::onStatus, this,
                                          ros::TransportHints().tcpNoDelay());
  timer_ = nh_.createWallTimer(ros::WallDuration(0.05), &Stepper::onTimer, this);
  rosgraph_msgs::Clock c;
  clock_pub_.publish(c);
  return true;
}

std::string Stepper::missing(bool (*pred)(const Peer&)) const {
  std::string out;
  for (const auto& n : names_)
    if (!pred(peers_.at(n))) out += (out.empty() ? "" : ", ") + n;
  return out;
}

void Stepper::onStatus(const StepStatus::ConstPtr& s) {
  auto it = peers_.find(s->node);
  if (it == peers_.end()) return;  // not a participant of this run
  Peer& p = it->second;
  p.cpu_s = s->cpu_time_s;
  if (s->status == StepStatus::ERROR) {
    if (phase_ != Phase::Closing && phase_ != Phase::Done) finish(true, s->message);
    return;
  }
  switch (phase_) {
    case Phase::Announce:
    case Phase::Sync:
      p.announced = true;
      if (s->status == StepStatus::READY || s->status == StepStatus::WAITING) {
        p.last_status = s->status;
        p.last_step = s->step;
        p.waiting_for = s->message;
      }
      return;
    case Phase::Stepping:
      if ((s->status == StepStatus::DONE || s->status == StepStatus::FINISHED) && s->step == k_) {
        p.done = true;
        p.last_status = s->status;
        for (const auto& n : names_)
          if (!peers_[n].done) return;
        bool fin = false;
        for (const auto& n : names_) fin = fin || peers_[n].last_status == StepStatus::FINISHED;
        t_ = addStep(t_, dt_s_);
        ++k_;
        printProgress(false);
        if (fin || (until_s_ > 0.0 && t_.toSec() >= until_s_ - 1e-9)) {
          finish(false, fin ? "end of mission" : "until_s reached");
        } else {
          sendStep();
        }
      }
      return;
    case Phase::Closing:
      if (s->status == StepStatus::CLOSED) {
        p.closed = true;
        for (const auto& n : names_)
          if (!peers_[n].closed) return;
        complete();
      }
      return;
    case Phase::Done:
      return;
  }
}

void Stepper::sendSync() {
  ++sync_round_;
  StepCommand c;
  c.command = StepCommand::SYNC;
  c.step = sync_round_;
  c.dt_s = dt_s_;
  cmd_pub_.publish(c);
}

void Stepper::sendStep() {
  for (auto& kv : peers_) kv.second.done = false;
  rosgraph_msgs::Clock c;
  c.clock = t_;
  clock_pub_.publish(c);
  StepCommand cmd;
  cmd.header.stamp = t_;
  cmd.command = StepCommand::STEP;
  cmd.step = k_;
  cmd.dt_s = dt_s_;
  step_sent_ = Clock::now();
  cmd_pub_.publish(cmd);
}

void Stepper::onTimer(const ros::WallTimerEvent&) {
  switch (phase_) {
    case Phase::Announce:
    case Phase::Sync: {
      if (secondsSince(phase_since_) > startup_timeout_s_) {
        const std::string m = missing([](const Peer& p) { return p.announced; });
        std::string links;
        for (const auto& n : names_)
          if (!peers_[n].waiting_for.empty()) links += " " + n + ":" + peers_[n].waiting_for;
        finish(true, "start-up timed out after " + std::to_string(startup_timeout_s_) + " s; " +
                         (m.empty() ? "links not connected:" + links : "no answer from: " + m));
        return;
      }
      if (phase_ == Phase::Announce) {
        if (!missing([](const Peer& p) { return p.announced; }).empty()) return;
        phase_ = Phase::Sync;
        sendSync();
        return;
      }
      // (answering round r proves the participant hears /sim/step; subscriber counts cannot be
      // used: in one nodelet manager all participants share one subscription per topic)
      bool all_ready = true;
      for (const auto& n : names_) {
        const Peer& p = peers_[n];
        all_ready = all_ready && p.last_status == StepStatus::READY && p.last_step == sync_round_;
      }
      if (all_ready) {
        nh_.param("/sim/mission_duration_s", mission_duration_s_, 0.0);
        phase_ = Phase::Stepping;
        wall0_ = Clock::now();
        k_ = 0;
        t_ = ros::Time(0);
        sendStep();
      } else {
        sendSync();
      }
      return;
    }
    case Phase::Stepping:
      if (secondsSince(step_sent_) > timeout_s_) {
        const std::string m = missing([](const Peer& p) { return p.done; });
        for (auto& kv : peers_)  // silent participants will not close anything: do not wait
          if (!kv.second.done) kv.second.closed = true;
        std::ostringstream os;
        os << "participant(s) " << m << " did not answer step " << k_ << " (t = " << std::fixed
           << std::setprecision(3) << t_.toSec() << " s) within " << timeout_s_
           << " s: node died or hung";
        finish(true, os.str());
      }
      return;
    case Phase::Closing:
      if (secondsSince(phase_since_) > (aborted_ ? 0.7 : 5.0)) {
        ROS_WARN_STREAM("stepper: no CLOSED from " << missing([](const Peer& p) { return p.closed; }));
        complete();
      }
      return;
    case Phase::Done:
      return;
  }
}

void Stepper::finish(bool aborted, const std::string& reason) {
  if (phase_ == Phase::Closing || phase_ == Phase::Done) return;
  aborted_ = aborted;
  abort_reason_ = reason;
  printProgress(true);
  if (progress_) std::fprintf(stderr, "\n");
  if (aborted) ROS_ERROR_STREAM("run aborted: " << reason);
  else ROS_INFO_STREAM("run finished: " << reason << " at t = " << t_.toSec() << " s");
  phase_ = Phase::Closing;
  phase_since_ = Clock::now();
  StepCommand cmd;
  cmd.header.stamp = t_;
  cmd.command = aborted ? StepCommand::ABORT : StepCommand::FINISH;
  cmd.step = k_;
  cmd.dt_s = dt_s_;
  cmd.reason = reason;
  cmd_pub_.publish(cmd);
  if (missing([](const Peer& p) { return p.closed; }).empty()) complete();
}

void Stepper::complete() {
  if (phase_ == Phase::Done) return;
  phase_ = Phase::Done;
  timer_.stop();
  writeStatus(aborted_ ? "error" : "ok", abort_reason_);
  ros::requestShutdown();
}

void Stepper::printProgress(bool force) {
  if (!progress_) return;
  if (!force && secondsSince(last_print_) < 0.5) return;
  last_print_ = Clock::now();
  const double sim = t_.toSec(), wall = wallSeconds();
  const double total = until_s_ > 0.0 ? until_s_ : mission_duration_s_;
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

void Stepper::writeStatus(const std::string& status, const std::string& message) {
  if (status_file_.empty()) return;
  std::ofstream f(status_file_);
  f << std::setprecision(17);
  f << "{\n  \"status\": \"" << status << "\",\n  \"message\": \"" << jsonEscape(message)
    << "\",\n  \"sim_time_s\": " << t_.toSec() << ",\n  \"wall_time_s\": "
    << (phase_ == Phase::Announce || phase_ == Phase::Sync ? 0.0 : wallSeconds())
    << ",\n  \"steps\": " << k_ << ",\n  \"macro_step_s\": " << dt_s_ << ",\n  \"cpu_time_s\": {";
  bool first = true;
  for (const auto& kv : peers_) {
    f << (first ? "" : ",") << "\n    \"" << kv.first << "\": " << kv.second.cpu_s;
    first = false;
  }
  f << "\n  }\n}\n";
}

}  // namespace hbt::cosim
