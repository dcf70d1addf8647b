#include "cosim/recorder.hpp"

#include <algorithm>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include <ros/master.h>
#include <ros/names.h>

#include "common/errors.hpp"
#include "cosim/core/process_cpu.hpp"
#include "cosim/core/status_file.hpp"
#include "cosim/stepper.hpp"

namespace hbt::cosim {

void Recorder::configure() {
  std::string& bag_file = bag_file_;
  const std::string where = "recorder parameters (launch file)";
  if (!pnh_.getParam("bag_file", bag_file) || bag_file.empty())
    throw InputError(where, "bag_file", "missing");
  pnh_.param<std::string>("status_file", status_file_, "");
  record_all_ = !pnh_.hasParam("topics");
  if (!record_all_ && (!pnh_.getParam("topics", listed_) || listed_.empty()))
    throw InputError(where, "topics", "not a list of topic names, or empty (leave it out to record every output)");
  double period_s = 0.0;
  pnh_.param("record_period_s", period_s, 0.0);
  if (!(period_s >= 0.0 && period_s <= 3600.0))
    throw InputError(where, "record_period_s", "must be in [0, 3600] s");
  period_ns_ = static_cast<uint64_t>(core::toNanos(period_s));
  // Stepped only at the record period when it is a multiple of the base step (else at every
  // base step, writing the multiples of the period); reads each topic's held value.
  setObserver(true);
  if (period_ns_ > 0) setMacroStep(period_s, where, "record_period_s", true);
  try {
    bag_ = std::make_unique<AsyncBagWriter>(bag_file);
  } catch (const std::exception& e) {
    throw InputError(where, "bag_file", std::string("cannot open '") + bag_file + "': " + e.what());
  }
  std::string diag_file;
  if (pnh_.getParam("diagnostics_bag_file", diag_file) && !diag_file.empty()) {
    std::vector<std::string> from;
    diag_from_param_ = pnh_.getParam("diagnostics_from", from);  // else: the run's participants (SYNC)
    for (const auto& n : from)
      if (n != name()) diag_waiting_.insert(n);
    pnh_.param("diagnostics_wait_s", diag_wait_s_, 2.0);
    if (!(diag_wait_s_ >= 0.0 && diag_wait_s_ <= 60.0))
      throw InputError(where, "diagnostics_wait_s", "must be in [0, 60] s");
    diag_file_ = diag_file;
    try {
      diag_bag_ = std::make_unique<BagFileWriter>(diag_file);
    } catch (const std::exception& e) {
      throw InputError(where, "diagnostics_bag_file", "cannot open '" + diag_file + "': " + e.what());
    }
    diag_sub_ = nh_.subscribe<diagnostic_msgs::DiagnosticArray>("/diagnostics", 1000,
                                                               &Recorder::onDiagnostics, this);
    auto arrive = arrivalCallback();
    diag_timer_ = nh_.createWallTimer(ros::WallDuration(0.2), [this, arrive](const ros::WallTimerEvent&) {
      if (diag_wait_since_ >= 0.0) arrive();
    });
  }
}

void Recorder::addTopic(const std::string& topic, const std::string& datatype, const std::string& subscribe_to) {
  std::unique_ptr<InputBase> in;
  topics_.push_back(makeRecordedTopic(datatype, nh_, topic, arrivalCallback(), subscribe_to, in));
  addCustomInput(std::move(in));
  // written in a fixed order, whatever the order of discovery: sorted by name
  std::sort(topics_.begin(), topics_.end(), [](const auto& a, const auto& b) { return a->topic() < b->topic(); });
}

void Recorder::topicsAnnounced(const std::vector<std::string>& topics,
                               const std::vector<std::string>& participants) {
  if (diag_bag_ && !diag_from_param_ && !diag_from_table_) {  // wait for every participant's final status
    for (const auto& n : participants)
      if (n != name()) diag_waiting_.insert(n);
    diag_from_table_ = true;
  }
  // the topics to record: every announced output, or the list given; subscribed here (the
  // first SYNC), where it is known which are participants' outputs: those are read from their
  // observer lane (output.hpp), anything else from the topic itself
  std::vector<std::pair<std::string, std::string>> missing;  // topic, resolved name
  for (const auto& t : record_all_ ? topics : listed_) {
    const std::string resolved = ros::names::resolve(nh_.getNamespace(), t);
    if (std::none_of(topics_.begin(), topics_.end(),
                     [&](const auto& r) { return r->input()->resolvedTopic() == resolved; }))
      missing.emplace_back(t, resolved);
  }
  if (missing.empty()) return;  // later SYNC rounds: nothing to ask the master
  ros::master::V_TopicInfo advertised;  // every announced topic is advertised: its type is known
  ros::master::getTopics(advertised);
  for (const auto& [t, resolved] : missing) {
    std::string datatype;
    for (const auto& info : advertised)
      if (info.name == resolved) datatype = info.datatype;
    const bool output = std::find(topics.begin(), topics.end(), resolved) != topics.end() ||
                        std::find(topics.begin(), topics.end(), t) != topics.end();
    addTopic(t, datatype, output ? observerLane(resolved) : "");
  }
}

void Recorder::writeDiagnostics(const diagnostic_msgs::DiagnosticArray& m) {
  if (!diag_error_.empty()) return;  // failed before: the run is stopping on it
  // bag times start at ros::TIME_MIN (1 ns): rosbag::Bag refuses 0, so the first status is at 1 ns
  const ros::Time t = m.header.stamp.isZero() ? ros::Time(0, 1) : m.header.stamp;
  try {
    diag_bag_->write("/diagnostics", t, m);
  } catch (const std::exception& e) {  // (in a callback: remembered, raised by the next step)
    diag_error_ = describeWriteFailure(diag_file_, e.what());
  }
}

void Recorder::onDiagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
  if (!diag_bag_) return;
  bool own_final = false, final_arrived = false;
  for (const auto& s : m->status) {
    bool final = false;
    for (const auto& kv : s.values)
      if (kv.key == "final") final = kv.value == "true";
    if (final && s.name == name()) own_final = true;  // written by close() itself
    if (final && diag_waiting_.erase(s.name)) final_arrived = true;
  }
  if (!own_final) writeDiagnostics(*m);
  if (final_arrived) arrivalCallback()();
}

bool Recorder::diagnosticsComplete() const {
  if (!diag_bag_ || diag_waiting_.empty()) return true;
  const double now = ros::WallTime::now().toSec();
  if (diag_wait_since_ < 0.0) diag_wait_since_ = now;
  return now - diag_wait_since_ > diag_wait_s_;
}

void Recorder::step(const ros::Time& t, double) {
  if (!diag_error_.empty()) throw std::runtime_error(diag_error_);
  if (period_ns_ == 0 || t.toNSec() % period_ns_ == 0) writeAt(t);
}

void Recorder::writeAt(const ros::Time& t) {
  const ros::Time bag_t = t.isZero() ? ros::Time(0, 1) : t;  // rosbag refuses time 0
  for (const auto& r : topics_) r->write(*bag_, bag_t, t);
  last_written_ = t;
  wrote_any_ = true;
}

void Recorder::diagnosticValues(core::Nanos, std::vector<core::KeyValue>& kv) {
  if (!bag_) return;  // closed: the final status is built before close()
  const BagQueueStats q = bag_->queueStats();
  kv.push_back({"bag_queue_high_water_kib", core::formatNumber(q.high_water_bytes / 1024.0)});
  kv.push_back({"bag_queue_high_water_messages", std::to_string(q.high_water_messages)});
  kv.push_back({"bag_queue_producer_waits", std::to_string(q.producer_waits)});
}

bool Recorder::readyToClose(const ros::Time& t_end) const {
  for (const auto& r : topics_)
    if (!r->input()->readyFor(t_end.toNSec())) return false;
  return diagnosticsComplete();
}

void Recorder::close(const ros::Time& t_end, bool aborted) {
  std::string run_bag_error;
  if (bag_) {
    bool ready = true;
    for (const auto& r : topics_) ready = ready && r->input()->readyFor(t_end.toNSec());
    if (!aborted && (!wrote_any_ || last_written_ < t_end) && ready) writeAt(t_end);
    std::unique_ptr<AsyncBagWriter> bag = std::move(bag_);
    try {
      bag->close();  // drains the queue; a write error fails the run naming the file
    } catch (const std::exception& e) {
      run_bag_error = e.what();  // thrown after the diagnostics bag is closed too
    }
  }
  if (diag_bag_) {
    if (!aborted && !diag_waiting_.empty()) {
      std::string missing;
      for (const auto& n : diag_waiting_) missing += " " + n;
      ROS_WARN_STREAM(name() << ": no final diagnostics from" << missing << " within "
                             << diag_wait_s_ << " s; diagnostics.bag has their last periodic status");
    }
    writeDiagnostics(finalDiagnostics());
    diag_timer_.stop();
    try {
      diag_bag_->close();
    } catch (const std::exception& e) {
      if (diag_error_.empty()) diag_error_ = describeWriteFailure(diag_file_, e.what());
    }
    diag_bag_.reset();
  }
  if (!run_bag_error.empty()) throw std::runtime_error(run_bag_error);
  if (!diag_error_.empty()) throw std::runtime_error(diag_error_);
}

void Recorder::stepperLost(const ros::Time& t, const std::string& message) {
  std::string stepper;
  ros::param::get(kStepperProcessParam, stepper);
  const std::string text = "stepper (" + (stepper.empty() ? std::string("process unknown") : stepper) +
                           "): " + message + "; the recorder closed " + bag_file_ +
                           " there and ends the stepper's process";
  ROS_ERROR_STREAM(name() << ": " << text);
  if (!status_file_.empty() && !core::statusWritten(status_file_)) {
    core::RunStatus st;
    st.status = "error";
    st.message = text;
    st.sim_time_s = t.toSec();
    const std::string failure = core::writeStatusFile(status_file_, st);
    if (!failure.empty()) ROS_ERROR_STREAM(name() << ": cannot write " << status_file_ << ": " << failure);
  }
  ROS_ERROR_STREAM(name() << ": " << endStepper());
}

std::string Recorder::endStepper() const {
  std::string stepper;
  if (!ros::param::get(kStepperProcessParam, stepper))
    return "the stepper's process is unknown (" + std::string(kStepperProcessParam) + " not set): end the launch by hand";
  const std::string self = core::processName();
  const auto host_of = [](const std::string& p) { return p.substr(0, p.rfind(':')); };
  if (host_of(stepper) != host_of(self))
    return "the stepper (" + stepper + ") runs on another host: end the launch by hand";
  const long pid = std::strtol(stepper.substr(stepper.rfind(':') + 1).c_str(), nullptr, 10);
  if (pid <= 0 || pid == static_cast<long>(::getpid())) return "the stepper shares this process: not ended";
  if (::kill(static_cast<pid_t>(pid), SIGKILL) != 0)
    return "could not end the stepper (pid " + std::to_string(pid) + "): " + std::strerror(errno);
  return "ended the stepper (pid " + std::to_string(pid) + ", SIGKILL) so that the launch stops";
}

}  // namespace hbt::cosim
