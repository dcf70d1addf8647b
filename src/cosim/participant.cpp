// ROS transport of core::ParticipantCore: StepCommand -> core events, core statuses -> StepStatus,
// the announce timer, link checks against the master, and the calls into the subclass's model.
#include "cosim/participant.hpp"
#include <boost/make_shared.hpp>

#include <ros/master.h>
#include <unistd.h>

#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "common/errors.hpp"
#include "cosim/param_loader.hpp"
#include "cosim/participant_main.hpp"

namespace hbt::cosim {

using hybrid_bus_twin::StepCommand;
using hybrid_bus_twin::StepStatus;

namespace {

int64_t dtNs(double dt_s) { return core::toNanos(dt_s); }

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

std::string defaultName(const std::string& name, const ros::NodeHandle& pnh) {
  if (!name.empty()) return name;
  const std::string& ns = pnh.getNamespace();  // the node (or nodelet) name
  return ns.substr(ns.find_last_of('/') + 1);
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

/// The core's view of this participant: model calls and the status transport.
class Participant::Hooks : public core::ParticipantHooks {
 public:
  explicit Hooks(Participant& p) : p_(p) {}
  void configure() override {
    p_.readMacroStep();
    p_.readDiagnosticsParams();
    ParamCapture capture;  // every parameter the model binds, as resolved
    p_.configure();
    p_.writeResolvedConfig(capture.params());
  }
  void publishOutputs(core::Nanos t) override {
    p_.publishOutputs(fromNanos(t));
    p_.diagnose(t, false);
  }
  void step(core::Nanos t, double dt_s) override {
    const auto w0 = std::chrono::steady_clock::now();
    p_.step(fromNanos(t), dt_s);
    p_.diag_.addStepTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count());
  }
  bool finished() const override { return p_.finished(); }
  void close(core::Nanos t, bool aborted) override {
    try {
      p_.diagnose(t, true);
    } catch (const std::exception& e) {
      ROS_ERROR_STREAM(p_.name_ << ": final diagnostics failed: " << e.what());
    }
    p_.close(fromNanos(t), aborted);
  }
  bool readyToClose(core::Nanos t) const override { return p_.readyToClose(fromNanos(t)); }
  void logError(const std::string& m) override { ROS_ERROR_STREAM(m); }
  void stepperLost(core::Nanos t, const std::string& message) override { p_.stepperLost(fromNanos(t), message); }
  std::string missingLinks() const override {
    std::ostringstream os;
    for (const auto& in : p_.inputs_)
      if (in->numPublishers() == 0) os << " input " << in->topic() << " has no publisher;";
    const auto subs = masterSubscribers();
    for (const auto& pub : p_.outputs_) {
      const auto it = subs.find(pub.getTopic());
      const std::size_t want = it == subs.end() ? 0 : it->second.size();
      if (pub.getNumSubscribers() < want)
        os << " output " << pub.getTopic() << " has " << pub.getNumSubscribers() << "/" << want
           << " subscribers connected;";
    }
    const auto d = subs.find(p_.diag_pub_.getTopic());  // /diagnostics: the recorder, viewers
    if (d != subs.end() && p_.diag_pub_.getNumSubscribers() < d->second.size())
      os << " output " << p_.diag_pub_.getTopic() << " has " << p_.diag_pub_.getNumSubscribers()
         << "/" << d->second.size() << " subscribers connected;";
    if (p_.cmd_sub_.getNumPublishers() == 0) os << " /sim/step not connected;";
    return os.str();
  }
  void runEndKnown(core::Nanos t_end) override { p_.checkRunEnd(core::toSec(t_end)); }
  void topicsAnnounced(const std::vector<std::string>& topics,
                       const std::vector<std::string>& participants) override {
    p_.topicsAnnounced(topics, participants);
  }
  void sendStatus(const core::Status& c) override {
    StepStatus s;
    s.header.stamp = fromNanos(c.t);
    s.node = c.node;
    s.status = static_cast<uint8_t>(c.status);
    s.step = c.step;
    s.compute_time_s = c.compute_time_s;
    s.process_cpu_s = c.process_cpu_s;
    s.process = c.process;
    s.message = c.message;
    s.outputs = c.outputs;
    s.inputs = c.inputs;
    s.observer = c.observer;
    s.mission_duration_s = c.mission_duration_s;
    s.step_multiple = c.step_multiple;
    p_.status_pub_.publish(boost::make_shared<StepStatus>(s));
  }

 private:
  Participant& p_;
};

Participant::Participant(ros::NodeHandle nh, ros::NodeHandle pnh, std::string name)
    : nh_(std::move(nh)),
      pnh_(std::move(pnh)),
      name_(defaultName(name, pnh_)),
      hooks_(std::make_unique<Hooks>(*this)),
      core_(name_, *hooks_) {}

Participant::~Participant() {
  // no timer or command callback may run beside (or after) this: mode:=nodelets unloads from
  // another thread than the one the callbacks run on (stop/shutdown wait for one in progress)
  tick_timer_.stop();
  cmd_sub_.shutdown();
}

void Participant::readDiagnosticsParams() {
  std::string file = "/scenario/diagnostics (rosparam)";
  // a scenario names its diagnostics file (config/diagnostics.yaml): then every key is required;
  // a bare protocol set-up (test harnesses, probes) without one runs on the declared thresholds
  const bool scenario_file = nh_.getParam("/scenario/diagnostics_file", file);
  ParamSet ps;
  diag_params_.declare(ps);
  const ParamSource src = loadParamSource(nh_, "/scenario/diagnostics", file);
  applyParams(ps, src);
  if (scenario_file) requireKeys(ps, src);  // after: a misspelt key is named as unknown first
  diag_.setPeriod(core::toNanos(diag_params_.period_s));
}

void Participant::readWarningThresholds(const std::function<void(ParamSet&)>& declare) {
  static const std::string kSection = "diagnostics/";
  const std::string file = configFile();
  ParamSet ps;
  ps.setPrefix(kSection);
  declare(ps);
  ps.setPrefix("");
  const ParamSource all = loadParamSource(pnh_, "", file);
  ParamSource own;  // the section only: the model's keys are checked by the model's ParamSet
  own.file = all.file;
  for (const auto& kv : all.values)
    if (kv.first.rfind(kSection, 0) == 0) own.values.insert(kv);
  applyParams(ps, own);
  if (pnh_.hasParam("config_file")) requireKeys(ps, own);  // a scenario: the file holds them all
}

void Participant::diagnose(core::Nanos t, bool final) {
  if (!final) {
    checkWarnings(t);
    if (!diag_.due(t)) return;
  }
  core::DiagStatus st = diag_.status(t, final, core_.computeSeconds());
  if (core_.configured()) diagnosticValues(t, st.values);  // not on a half-built model
  auto arr = boost::make_shared<diagnostic_msgs::DiagnosticArray>();
  arr->header.stamp = fromNanos(t);
  arr->status.resize(1);
  diagnostic_msgs::DiagnosticStatus& s = arr->status[0];
  s.level = st.level;
  s.name = name_;
  s.message = st.message;
  s.hardware_id = host_;
  s.values.resize(st.values.size());
  for (std::size_t i = 0; i < st.values.size(); ++i) {
    s.values[i].key = st.values[i].key;
    s.values[i].value = st.values[i].value;
  }
  if (final) final_diag_ = *arr;
  diag_pub_.publish(arr);
}

std::string Participant::configFile() const {
  std::string f;
  pnh_.param<std::string>("config_file", f, pnh_.getNamespace() + " (rosparam)");
  return f;
}

void Participant::writeResolvedConfig(const std::vector<ResolvedParam>& params) const {
  std::string out;
  if (params.empty() || !nh_.getParam("/scenario/out_dir", out) || out.empty()) return;  // no model / not a scenario run
  const std::string dir = out + "/resolved_config";
  const std::string path = dir + "/" + name_ + ".csv";
  ::mkdir(dir.c_str(), 0755);  // exists already when another participant made it first
  std::ofstream f(path);
  f << "# parameters of participant '" << name_ << "' as its model was configured: file, key, value,\n"
    << "# unit, source (file = set by the file, default = the model's default)\n"
    << "file,key,value,unit,source\n";
  auto csv = [](const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  for (const auto& p : params)
    f << csv(p.file) << "," << csv(p.key) << "," << csv(p.value) << "," << csv(p.unit) << ","
      << (p.from_file ? "file" : "default") << "\n";
  if (!f) throw InputError(path, "", "cannot write the resolved configuration");
}

void Participant::readMacroStep() {
  XmlRpc::XmlRpcValue th;  // nodelets: the callback thread (participant_main.hpp); checked here
  if (pnh_.getParam("cosim/thread", th) && (th.getType() != XmlRpc::XmlRpcValue::TypeString ||
                                            !LockstepQueue::validThreadName(std::string(th))))
    throw InputError(configFile(), "cosim/thread",
                     "must be a thread name (letters, digits, _; at most 64 characters)");
  const std::string key = "cosim/macro_step_s";
  XmlRpc::XmlRpcValue v;
  if (!pnh_.getParam(key, v)) return;  // absent: the stepper's base step
  double s = 0.0;
  if (v.getType() == XmlRpc::XmlRpcValue::TypeDouble) s = static_cast<double>(v);
  else if (v.getType() == XmlRpc::XmlRpcValue::TypeInt) s = static_cast<int>(v);
  else {
    // PyYAML (YAML 1.1) reads 1e-1 as a string: take a string that is entirely a number
    const std::string str = v.getType() == XmlRpc::XmlRpcValue::TypeString ? std::string(v) : "";
    char* end = nullptr;
    s = str.empty() ? 0.0 : std::strtod(str.c_str(), &end);
    if (str.empty() || *end != '\0') throw InputError(configFile(), key, "must be a number [s]");
  }
  core_.requestPeriod({s, configFile(), key, false});
}

void Participant::start() {
  std::lock_guard<std::recursive_mutex> lock(mutex_);
  status_pub_ = nh_.advertise<StepStatus>("/sim/status", 100);
  diag_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 100);
  char host[256] = {0};
  host_ = gethostname(host, sizeof host - 1) == 0 ? host : "localhost";
  cmd_sub_ = nh_.subscribe<StepCommand>("/sim/step", 100, &Participant::onCommand, this,
                                        ros::TransportHints().tcpNoDelay());
  core_.start();
  tick_timer_ = nh_.createWallTimer(ros::WallDuration(0.1), &Participant::onTickTimer, this);
}

void Participant::onTickTimer(const ros::WallTimerEvent&) {
  std::lock_guard<std::recursive_mutex> lock(mutex_);
  if (!core_.onTick()) tick_timer_.stop();
}

void Participant::onArrival() {
  std::lock_guard<std::recursive_mutex> lock(mutex_);
  core_.onArrival();
}

void Participant::onCommand(const StepCommand::ConstPtr& m) {
  std::lock_guard<std::recursive_mutex> lock(mutex_);
  core::Command c;
  c.command = static_cast<core::Cmd>(m->command);
  if (m->command > StepCommand::QUERY) return;  // unknown command
  c.step = m->step;
  c.observer_step = m->observer_step;
  c.confirmed = m->confirmed;
  c.t = static_cast<core::Nanos>(m->header.stamp.toNSec());
  c.dt_s = m->dt_s;
  c.reason = m->reason;
  if (m->command == StepCommand::START || m->command == StepCommand::SYNC) {  // SYNC: the table so far
    c.table.topics = m->topics;
    c.table.topic_multiple = m->topic_multiple;
    c.table.topic_group = m->topic_group;
    c.table.participants = m->participants;
    c.table.participant_multiple = m->participant_multiple;
    c.table.participant_group = m->participant_group;
    c.table.reader_topic = m->reader_topic;
    c.table.reader_multiple = m->reader_multiple;
    c.table.reader_fresh = m->reader_fresh;
    c.table.reader_observer = m->reader_observer;
    c.table.window = m->window;
    c.table.report_wall_s = m->report_wall_s;
  }
  core_.onCommand(c);
}

}  // namespace hbt::cosim
