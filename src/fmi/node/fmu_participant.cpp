#include "fmi/node/fmu_participant.hpp"

#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>

#include "common/errors.hpp"
#include "cosim/wiring.hpp"
#include "fmi/fmu_error.hpp"

namespace hbt::fmi {
namespace {

using XmlRpc::XmlRpcValue;

bool isNumber(const XmlRpcValue& v) {
  return v.getType() == XmlRpcValue::TypeDouble || v.getType() == XmlRpcValue::TypeInt;
}
double number(XmlRpcValue& v) {
  return v.getType() == XmlRpcValue::TypeInt ? static_cast<double>(static_cast<int>(v)) : static_cast<double>(v);
}

/// The mapping file's keys (rosparams under fmu_map/) into a MappingSpec; InputError naming the
/// file and key for anything unknown or mistyped.
class SpecReader {
 public:
  SpecReader(const std::string& file, XmlRpcValue root) : file_(file), root_(std::move(root)) {}

  MappingSpec read() {
    MappingSpec s;
    s.file = file_;
    if (root_.getType() != XmlRpcValue::TypeStruct) fail("", "expected a mapping of keys");
    static const std::set<std::string> known = {"interface", "model_exchange", "inputs", "outputs", "not_provided", "parameters"};
    for (auto& kv : root_)
      if (!known.count(kv.first)) fail(kv.first, "unknown key (known: interface, model_exchange, inputs, outputs, not_provided, parameters)");
    if (root_.hasMember("interface")) {
      const std::string i = str(root_["interface"], "interface");
      if (i != "cs" && i != "me") fail("interface", "must be cs (Co-Simulation) or me (Model Exchange)");
      s.interface = i == "cs" ? InterfaceType::kCoSimulation : InterfaceType::kModelExchange;
    }
    if (root_.hasMember("model_exchange")) readMe(root_["model_exchange"], s);
    s.inputs = links("inputs");
    s.outputs = links("outputs");
    for (auto& e : list("not_provided")) {
      MappingSpec::Fixed f;
      f.field = str(e["field"], "not_provided/field");
      f.value = num(e["value"], "not_provided/" + f.field + "/value");
      f.reason = str(e["reason"], "not_provided/" + f.field + "/reason");
      s.not_provided.push_back(f);
    }
    for (auto& e : list("parameters")) {
      MappingSpec::Param p;
      p.variable = str(e["variable"], "parameters/variable");
      XmlRpcValue& v = e["value"];
      const std::string key = "parameters/" + p.variable + "/value";
      if (v.getType() == XmlRpcValue::TypeBoolean) p.type = VarType::kBoolean, p.value = static_cast<bool>(v) ? 1.0 : 0.0;
      else if (v.getType() == XmlRpcValue::TypeInt) p.type = VarType::kInteger, p.value = static_cast<int>(v);
      else p.value = num(v, key);
      s.parameters.push_back(p);
    }
    return s;
  }

 private:
  [[noreturn]] void fail(const std::string& key, const std::string& what) const { throw InputError(file_, key, what); }
  std::string str(XmlRpcValue& v, const std::string& key) const {
    if (v.getType() != XmlRpcValue::TypeString || std::string(v).empty()) fail(key, "must be a non-empty string");
    return v;
  }
  double num(XmlRpcValue& v, const std::string& key) const {
    if (!isNumber(v)) fail(key, "must be a number");
    const double x = number(v);
    if (!std::isfinite(x)) fail(key, "must be finite");
    return x;
  }
  void readMe(XmlRpcValue& me, MappingSpec& s) const {
    if (me.getType() != XmlRpcValue::TypeStruct) fail("model_exchange", "expected rtol, atol, max_steps");
    for (auto& kv : me)
      if (kv.first != "rtol" && kv.first != "atol" && kv.first != "max_steps") fail("model_exchange/" + kv.first, "unknown key");
    if (me.hasMember("rtol")) s.me_rtol = num(me["rtol"], "model_exchange/rtol");
    if (me.hasMember("atol")) s.me_atol = num(me["atol"], "model_exchange/atol");
    if (me.hasMember("max_steps")) {
      if (me["max_steps"].getType() != XmlRpcValue::TypeInt) fail("model_exchange/max_steps", "must be an integer");
      s.me_max_steps = static_cast<int>(me["max_steps"]);
    }
    if (s.me_rtol && !(*s.me_rtol > 0.0 && *s.me_rtol < 1.0)) fail("model_exchange/rtol", "must be in (0, 1)");
    if (s.me_atol && !(*s.me_atol > 0.0)) fail("model_exchange/atol", "must be > 0");
    if (s.me_max_steps && *s.me_max_steps < 1) fail("model_exchange/max_steps", "must be >= 1");
  }
  std::vector<XmlRpcValue> list(const std::string& key) {
    std::vector<XmlRpcValue> out;
    if (!root_.hasMember(key)) return out;
    XmlRpcValue& l = root_[key];
    if (l.getType() != XmlRpcValue::TypeArray) fail(key, "must be a list of entries");
    for (int i = 0; i < l.size(); ++i) {
      if (l[i].getType() != XmlRpcValue::TypeStruct) fail(key, "entry " + std::to_string(i) + " is not a mapping");
      out.push_back(l[i]);
    }
    return out;
  }
  std::vector<MappingSpec::Link> links(const std::string& key) {
    std::vector<MappingSpec::Link> out;
    for (auto& e : list(key)) {
      for (auto& kv : e)
        if (kv.first != "field" && kv.first != "variable" && kv.first != "unit") fail(key + "/" + kv.first, "unknown key (field, variable, unit)");
      MappingSpec::Link l;
      l.field = str(e["field"], key + "/field");
      l.variable = str(e["variable"], key + "/" + l.field + "/variable");
      if (e.hasMember("unit")) l.unit = str(e["unit"], key + "/" + l.field + "/unit");
      out.push_back(l);
    }
    return out;
  }
  std::string file_;
  XmlRpcValue root_;
};

}  // namespace

MappingSpec FmuParticipant::readSpec() const {
  std::string file;
  pnh_.param<std::string>("fmu_map_file", file, "");
  XmlRpcValue root;
  if (file.empty()) {
    if (pnh_.hasParam("fmu_map")) throw InputError(configFile(), "fmu_map", "given without fmu_map_file");
    return MappingSpec{};
  }
  if (!pnh_.getParam("fmu_map", root)) throw InputError(file, "", "empty mapping file");
  return SpecReader(file, root).read();
}

MappingContext FmuParticipant::readContext() const {
  MappingContext ctx;
  ctx.participant = name();
  const std::string own = std::string(cosim::kWiringNamespace) + "/" + name();
  std::string decl_file = own + " (rosparam)";
  nh_.getParam(own + "/file", decl_file);
  std::map<std::string, std::string> pubs;
  if (!nh_.getParam(own + "/publishes", pubs))
    throw InputError(decl_file, "publishes", "missing: what participant " + name() + " publishes (its topics.yaml)");
  for (const auto& [key, type] : pubs) ctx.publishes.emplace(key, PortFactory::layoutOf(type, decl_file, "publishes/" + key));
  ros::NodeHandle nh = nh_;
  ctx.produced = [nh](const std::string& producer, const std::string& key) -> std::optional<MessageLayout> {
    std::string type;
    if (!cosim::inScenario(nh, producer) ||
        !nh.getParam(std::string(cosim::kWiringNamespace) + "/" + producer + "/publishes/" + key, type) ||
        !PortFactory::known(type))
      return std::nullopt;
    return PortFactory::layoutOf(type, "", "");
  };
  XmlRpcValue sc;
  if (nh_.getParam("/scenario", sc) && sc.getType() == XmlRpcValue::TypeStruct)
    for (auto& kv : sc)
      if (isNumber(kv.second)) ctx.scenario[kv.first] = number(kv.second);
  return ctx;
}

void FmuParticipant::loadFmu(const std::string& out_dir) {
  if (!pnh_.getParam("fmu_file", fmu_file_) || fmu_file_.empty())
    throw InputError(configFile(), "fmu_file", "missing: the FMU this participant runs");
  const std::string dir = out_dir + "/fmu";
  ::mkdir(dir.c_str(), 0755);
  // the interface type decides which binary functions are required: the mapping's, else the FMU's
  const FmuArchive archive(fmu_file_);
  const MappingSpec spec = readSpec();
  const ModelDescription& md = archive.modelDescription();
  map_ = resolveMapping(spec, md, readContext());
  fmu_ = LoadedFmu::load(fmu_file_, dir + "/" + name(), map_.interface);
}

void FmuParticipant::checkRunEnd(double end_s) {
  const auto& stop = fmu_->modelDescription().defaultExperiment().stop_time_s;
  if (!stop || !(end_s > 0.0) || *stop >= end_s) return;
  double until_s = 0.0;
  nh_.getParam("/stepper/until_s", until_s);
  const bool by_until = until_s > 0.0 && until_s <= end_s;  // else the mission ends first
  char what[160];
  std::snprintf(what, sizeof what, "DefaultExperiment stopTime %g s is before the end of this run (%s %g s)", *stop,
                by_until ? "until" : "the mission's end at", end_s);
  throw FmuError(fmu_file_, what);
}

void FmuParticipant::onLog(const std::string& instance, fmi2Status status, const std::string& category,
                           const std::string& message) {
  const std::string line = "FMU " + fmu_file_ + " (" + instance + ", " + category + ", " + statusName(status) + "): " + message;
  if (status == fmi2OK) {
    ROS_INFO_STREAM(name() << ": " << line);
  } else if (status == fmi2Warning || status == fmi2Discard) {
    ++log_warnings_;
    ROS_WARN_STREAM(name() << ": " << line);
  } else {
    ++log_errors_;
    ROS_ERROR_STREAM(name() << ": " << line);
  }
  last_log_ = line;
  step_log_ = message;  // the FMU's own text (the warning message names the FMU)
}

void FmuParticipant::instantiate() {
  auto sink = [this](const std::string& i, fmi2Status s, const std::string& c, const std::string& m) { onLog(i, s, c, m); };
  if (map_.interface == InterfaceType::kCoSimulation) {
    auto cs = std::make_unique<CsInstance>(fmu_, name(), sink);
    cs_ = cs.get();
    inst_ = std::move(cs);
  } else {
    auto me = std::make_unique<MeInstance>(fmu_, name(), sink, map_.me_rtol, map_.me_atol, map_.me_max_steps);
    me_ = me.get();
    inst_ = std::move(me);
  }
  for (const auto& b : map_.inputs) in_refs_.push_back(inst_->settable(b.variable, b.type));
  for (const auto& b : map_.outputs) out_refs_.push_back(inst_->gettable(b.variable, b.type));
  const auto& ex = fmu_->modelDescription().defaultExperiment();
  const std::optional<double> tol = me_ ? std::optional<double>(map_.me_rtol) : ex.tolerance;
  inst_->setupExperiment(tol, 0.0, ex.stop_time_s);
  inst_->enterInitializationMode();
  for (const auto& p : map_.parameters) {
    const VariableRef r = inst_->settable(p.variable, p.type);
    if (p.type == VarType::kReal) inst_->setReal(r, p.value_fmu);
    else if (p.type == VarType::kInteger) inst_->setInteger(r, static_cast<int>(p.value_fmu));
    else inst_->setBoolean(r, p.value_fmu != 0.0);
  }
  inst_->exitInitializationMode();
}

void FmuParticipant::makePorts() {
  const std::string own = std::string(cosim::kWiringNamespace) + "/" + name() + "/publishes/";
  for (const auto& key_layout : readContext().publishes) {
    const std::string& key = key_layout.first;
    std::string type;
    nh_.getParam(own + key, type);
    auto port = PortFactory::output(type, *this, cosim::outputTopic(nh_, name(), key, type));
    const auto& fields = port->layout().fields();
    for (std::size_t i = 0; i < fields.size(); ++i)
      if (fields[i].kind == FieldKind::kFloat64Array) port->resize(i, map_.array_sizes.count(key) ? map_.array_sizes.at(key) : 0);
    out_ports_.emplace(key, std::move(port));
  }
  for (const auto& f : map_.not_provided) out_ports_.at(f.key)->set(f.field, -1, f.value);
  for (const auto& b : map_.outputs) {
    const OutPort& port = *out_ports_.at(b.key);
    if (port.layout().fields()[b.field].name == "mission_finished") mission_finished_output_ = static_cast<int>(out_port_of_.size());
    out_port_of_.push_back(out_ports_.at(b.key).get());
  }
  for (const auto& b : map_.inputs) {
    const std::string topic = cosim::topicName(b.participant, b.key);
    auto it = in_ports_.find(topic);
    if (it == in_ports_.end()) {
      std::string type;
      nh_.getParam(std::string(cosim::kWiringNamespace) + "/" + b.participant + "/publishes/" + b.key, type);
      const std::string checked = cosim::inputTopic(nh_, b.participant, b.key, type, name());
      it = in_ports_.emplace(topic, PortFactory::input(type, *this, checked)).first;
    }
    in_port_of_.push_back(it->second.get());
  }
}

void FmuParticipant::writeResolved(const std::string& out_dir) const {
  const std::string dir = out_dir + "/resolved_config";
  ::mkdir(dir.c_str(), 0755);
  const std::string path = dir + "/" + name() + "_fmu.csv";
  std::ofstream f(path);
  map_.writeCsv(f, fmu_file_);
  if (!f) throw InputError(path, "", "cannot write the resolved FMU mapping");
}

void FmuParticipant::configure() {
  std::string out_dir;
  if (!nh_.getParam("/scenario/out_dir", out_dir) || out_dir.empty())
    throw InputError("/scenario/out_dir (rosparam)", "out_dir", "missing: the FMU is extracted beside the bag");
  loadFmu(out_dir);
  instantiate();
  makePorts();
  exchange_ = std::make_unique<FmuExchange>(map_, in_port_of_, out_port_of_, in_refs_, out_refs_, *inst_);
  writeResolved(out_dir);
  declareWarnings();
  readOutputs();
}

void FmuParticipant::declareWarnings() {
  for (const auto& w : warningOutputs(fmu_->modelDescription(), name()))
    // no on-delay: the FMU holds the persistence itself
    warnings_.push_back({w, inst_->gettable(w.variable, VarType::kBoolean), &addWarning(w.name, 0.0)});
}

void FmuParticipant::checkWarnings(cosim::core::Nanos t) {
  for (auto& w : warnings_)
    if (w.warning->update(t, inst_->getBoolean(w.ref))) w.warning->setMessage(warningMessage(fmu_file_, w.output, step_log_));
  step_log_.clear();
}

void FmuParticipant::readOutputs() {
  exchange_->getOutputs();
  if (mission_finished_output_ >= 0) mission_finished_ = exchange_->output(static_cast<std::size_t>(mission_finished_output_)) != 0.0;
}

void FmuParticipant::step(const ros::Time& t, double dt_s) {
  using Clock = std::chrono::steady_clock;
  const auto w0 = Clock::now();
  exchange_->setInputs(t);
  const auto w1 = Clock::now();
  if (cs_) cs_->doStep(dt_s);
  else me_->doStep(dt_s);
  const auto w2 = Clock::now();
  readOutputs();
  const std::chrono::duration<double> fmu = w2 - w1, rest = (w1 - w0) + (Clock::now() - w2);
  do_step_timing_.add(fmu.count());
  overhead_timing_.add(rest.count());
}

void FmuParticipant::publishOutputs(const ros::Time& t) {
  for (auto& kv : out_ports_) kv.second->publish(t);
}

void FmuParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  kv.push_back({"fmu_file", fmu_file_});
  kv.push_back({"fmu_interface", hbt::fmi::name(map_.interface)});
  std::string np;
  for (const auto& f : map_.not_provided) np += (np.empty() ? "" : ", ") + f.field_name;
  kv.push_back({"fmu_not_provided", np.empty() ? "none" : np});
  kv.push_back({"fmu_log_warnings", std::to_string(log_warnings_)});
  kv.push_back({"fmu_log_errors", std::to_string(log_errors_)});
  if (!last_log_.empty()) kv.push_back({"fmu_last_log", last_log_});
  using cosim::core::formatNumber;
  kv.push_back({"fmu_steps", std::to_string(do_step_timing_.count())});
  kv.push_back({"fmu_do_step_s", formatNumber(do_step_timing_.sum_s())});
  kv.push_back({"fmu_do_step_us_median", formatNumber(1e6 * do_step_timing_.median_s())});
  kv.push_back({"fmu_overhead_us_median", formatNumber(1e6 * overhead_timing_.median_s())});
  if (me_) {
    kv.push_back({"fmu_time_events", std::to_string(me_->timeEvents())});
    kv.push_back({"fmu_state_events", std::to_string(me_->stateEvents())});
    kv.push_back({"fmu_step_events", std::to_string(me_->stepEvents())});
  }
}

}  // namespace hbt::fmi
