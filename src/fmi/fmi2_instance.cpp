#include "fmi/fmi2_instance.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

#include "common/errors.hpp"
#include "fmi/fmu_error.hpp"

namespace hbt::fmi {

const char* statusName(fmi2Status s) {
  static const char* const k[] = {"fmi2OK",    "fmi2Warning", "fmi2Discard",
                                  "fmi2Error", "fmi2Fatal",   "fmi2Pending"};
  return (s >= fmi2OK && s <= fmi2Pending) ? k[s] : "unknown status";
}

namespace {
std::string timeText(double t_s) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "t = %.9g s", t_s);
  return buf;
}
}  // namespace

void Fmi2Instance::logMessage(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                            fmi2String category, fmi2String message, ...) {
  auto* self = static_cast<Fmi2Instance*>(env);
  if (!self || !self->sink_) return;
  std::string text;
  if (message) {
    va_list args, copy;
    va_start(args, message);
    va_copy(copy, args);
    const int n = std::vsnprintf(nullptr, 0, message, args);
    if (n > 0) {
      text.resize(static_cast<std::size_t>(n) + 1);
      std::vsnprintf(text.data(), text.size(), message, copy);
      text.resize(static_cast<std::size_t>(n));
    }
    va_end(copy);
    va_end(args);
  }
  try {  // nothing may unwind through the FMU's C frames
    self->sink_(instance ? instance : "", status, category ? category : "", text);
  } catch (...) {
  }
}

Fmi2Instance::Fmi2Instance(std::shared_ptr<const LoadedFmu> fmu, const std::string& instance_name,
                           LogSink sink)
    : fmu_(std::move(fmu)), f_(fmu_->functions()), name_(instance_name), sink_(std::move(sink)) {
  const bool cs = fmu_->interfaceType() == InterfaceType::kCoSimulation;
  callbacks_.logger = &Fmi2Instance::logMessage;
  callbacks_.allocateMemory = &std::calloc;
  callbacks_.freeMemory = &std::free;
  callbacks_.stepFinished = nullptr;  // Co-Simulation: synchronous doStep
  callbacks_.componentEnvironment = this;
  c_ = f_.instantiate(name_.c_str(), cs ? fmi2CoSimulation : fmi2ModelExchange,
                      fmu_->modelDescription().guid().c_str(),
                      fmu_->resourceUri().c_str(), &callbacks_, fmi2False, fmi2True);
  if (!c_) {
    throw FmuError(fmu_->file(), "fmi2Instantiate of instance '" + name_ +
                                     "' returned NULL (resources " + fmu_->resourceUri() + ")");
  }
}

Fmi2Instance::~Fmi2Instance() {
  if (state_ == State::kFatal) return;  // the standard allows no further call
  if (state_ == State::kStepping || state_ == State::kInitialization) f_.terminate(c_);
  f_.freeInstance(c_);
}

void Fmi2Instance::fail(const std::string& call, const std::string& what) const {
  throw ModelDivergence("FMU " + fmu_->file() + " instance '" + name_ + "'", call,
                        what + " at " + timeText(time_s_));
}

void Fmi2Instance::check(fmi2Status s, const char* call, const std::string* variable) {
  if (s == fmi2OK || s == fmi2Warning) return;
  if (s == fmi2Error) state_ = State::kError;
  if (s == fmi2Fatal) state_ = State::kFatal;
  fail(variable ? std::string(call) + " '" + *variable + "'" : std::string(call),
       std::string("returned ") + statusName(s));
}

VariableRef Fmi2Instance::gettable(const std::string& name, VarType t) const {
  const ScalarVariable& v = fmu_->modelDescription().variable(name);
  if (v.type != t) {
    throw FmuError(fmu_->file(), "variable '" + name + "' is " + fmi::name(v.type) + ", not " +
                                     fmi::name(t));
  }
  return {&v, v.value_reference};
}

VariableRef Fmi2Instance::settable(const std::string& name, VarType t) const {
  const VariableRef ref = gettable(name, t);
  const ScalarVariable& v = *ref.variable;
  const bool input = v.causality == Causality::kInput;
  const bool parameter = v.causality == Causality::kParameter &&
                         (v.variability == Variability::kFixed || v.variability == Variability::kTunable);
  if (!input && !parameter) {
    throw FmuError(fmu_->file(), "variable '" + name + "' has causality " + fmi::name(v.causality) +
                                     " and variability " + fmi::name(v.variability) +
                                     ": the importer cannot set it (an input or a fixed or tunable "
                                     "parameter is needed)");
  }
  return ref;
}

void Fmi2Instance::setupExperiment(std::optional<double> tolerance, double start_s,
                                 std::optional<double> stop_s) {
  time_s_ = start_s;
  stop_s_ = stop_s;
  check(f_.setupExperiment(c_, tolerance.has_value(), tolerance.value_or(0.0), start_s,
                           stop_s.has_value(), stop_s.value_or(0.0)),
        "fmi2SetupExperiment");
}

void Fmi2Instance::enterInitializationMode() {
  check(f_.enterInitializationMode(c_), "fmi2EnterInitializationMode");
  state_ = State::kInitialization;
}

void Fmi2Instance::exitInitializationMode() {
  check(f_.exitInitializationMode(c_), "fmi2ExitInitializationMode");
  state_ = State::kStepping;
}

void Fmi2Instance::requireSet(const VariableRef& v, VarType t) const {
  if (v.variable->type != t) {
    fail(std::string("set ") + fmi::name(t) + " '" + v.variable->name + "'",
         std::string("the variable is ") + fmi::name(v.variable->type));
  }
  if (state_ == State::kStepping && v.variable->variability == Variability::kFixed) {
    fail("set '" + v.variable->name + "'", "a fixed parameter cannot change after initialisation");
  }
}

void Fmi2Instance::setReal(const VariableRef& v, double value) {
  requireSet(v, VarType::kReal);
  check(f_.setReal(c_, &v.vr, 1, &value), "fmi2SetReal", &v.variable->name);
}

void Fmi2Instance::setInteger(const VariableRef& v, int value) {
  requireSet(v, v.variable->type == VarType::kEnumeration ? VarType::kEnumeration : VarType::kInteger);
  check(f_.setInteger(c_, &v.vr, 1, &value), "fmi2SetInteger", &v.variable->name);
}

void Fmi2Instance::setBoolean(const VariableRef& v, bool value) {
  requireSet(v, VarType::kBoolean);
  const fmi2Boolean b = value ? fmi2True : fmi2False;
  check(f_.setBoolean(c_, &v.vr, 1, &b), "fmi2SetBoolean", &v.variable->name);
}

double Fmi2Instance::getReal(const VariableRef& v) {
  double value = 0.0;
  check(f_.getReal(c_, &v.vr, 1, &value), "fmi2GetReal", &v.variable->name);
  if (std::isnan(value)) fail("variable '" + v.variable->name + "'", "NaN output");
  return value;
}

int Fmi2Instance::getInteger(const VariableRef& v) {
  fmi2Integer value = 0;
  check(f_.getInteger(c_, &v.vr, 1, &value), "fmi2GetInteger", &v.variable->name);
  return value;
}

bool Fmi2Instance::getBoolean(const VariableRef& v) {
  fmi2Boolean value = fmi2False;
  check(f_.getBoolean(c_, &v.vr, 1, &value), "fmi2GetBoolean", &v.variable->name);
  return value != fmi2False;
}

VariableBatch Fmi2Instance::batch(const std::vector<VariableRef>& refs, VarType t) const {
  VariableBatch b;
  b.type = t;
  for (const VariableRef& r : refs) {
    const VarType vt = r.variable->type == VarType::kEnumeration ? VarType::kInteger : r.variable->type;
    if (vt != t) {
      throw FmuError(fmu_->file(), "variable '" + r.variable->name + "' is " + fmi::name(r.variable->type) +
                                       ", not " + fmi::name(t));
    }
    if (!b.fixed && r.variable->causality == Causality::kParameter && r.variable->variability == Variability::kFixed)
      b.fixed = r.variable;
    b.vrs.push_back(r.vr);
    b.variables.push_back(r.variable);
  }
  return b;
}

void Fmi2Instance::requireSet(const VariableBatch& b, VarType t) const {
  if (b.type != t) fail(std::string("set ") + fmi::name(t), std::string("the batch is ") + fmi::name(b.type));
  if (state_ == State::kStepping && b.fixed) {
    fail("set '" + b.fixed->name + "'", "a fixed parameter cannot change after initialisation");
  }
}

void Fmi2Instance::checkBatch(fmi2Status s, const char* call, const VariableBatch& b) {
  if (s == fmi2OK || s == fmi2Warning) return;
  if (s == fmi2Error) state_ = State::kError;
  if (s == fmi2Fatal) state_ = State::kFatal;
  std::string names;
  for (const ScalarVariable* v : b.variables) names += (names.empty() ? "'" : ", '") + v->name + "'";
  fail(std::string(call) + " of " + std::to_string(b.size()) + (b.size() == 1 ? " variable " : " variables ") + names,
       std::string("returned ") + statusName(s));
}

void Fmi2Instance::setReals(const VariableBatch& b, const double* values) {
  requireSet(b, VarType::kReal);
  if (b.size()) checkBatch(f_.setReal(c_, b.vrs.data(), b.size(), values), "fmi2SetReal", b);
}

void Fmi2Instance::setIntegers(const VariableBatch& b, const int* values) {
  requireSet(b, VarType::kInteger);
  if (b.size()) checkBatch(f_.setInteger(c_, b.vrs.data(), b.size(), values), "fmi2SetInteger", b);
}

void Fmi2Instance::setBooleans(const VariableBatch& b, const fmi2Boolean* values) {
  requireSet(b, VarType::kBoolean);
  if (b.size()) checkBatch(f_.setBoolean(c_, b.vrs.data(), b.size(), values), "fmi2SetBoolean", b);
}

void Fmi2Instance::getReals(const VariableBatch& b, double* values) {
  if (!b.size()) return;
  checkBatch(f_.getReal(c_, b.vrs.data(), b.size(), values), "fmi2GetReal", b);
  for (std::size_t i = 0; i < b.size(); ++i)
    if (std::isnan(values[i])) fail("variable '" + b.variables[i]->name + "'", "NaN output");
}

void Fmi2Instance::getIntegers(const VariableBatch& b, int* values) {
  if (b.size()) checkBatch(f_.getInteger(c_, b.vrs.data(), b.size(), values), "fmi2GetInteger", b);
}

void Fmi2Instance::getBooleans(const VariableBatch& b, fmi2Boolean* values) {
  if (b.size()) checkBatch(f_.getBoolean(c_, b.vrs.data(), b.size(), values), "fmi2GetBoolean", b);
}

void Fmi2Instance::checkStep(const char* call, double h_s) const {
  if (state_ != State::kStepping) fail(call, "called before exitInitializationMode or after an error");
  if (!(h_s > 0.0)) fail(call, "step size " + std::to_string(h_s) + " s is not > 0");
  if (stop_s_ && time_s_ + h_s > *stop_s_ * (1.0 + 1e-12)) {
    fail(call, "a step of " + std::to_string(h_s) + " s would pass the stop time " +
                   std::to_string(*stop_s_) + " s");
  }
}

}  // namespace hbt::fmi
