// The fmi2 C functions of an exported Co-Simulation FMU (FMI 2.0, sections 2.1 and 4.2), written
// from the standard over one ExportedModel (exported_model.hpp). Linked into every exported
// model's binary; only the fmi2 functions are visible (the rest is -fvisibility=hidden).
//
// State machine (FMI 2.0 section 4.2.4): instantiated -> initialization mode
// (fmi2EnterInitializationMode) -> stepping (fmi2ExitInitializationMode: ExportedModel::initialize)
// -> terminated; fmi2Error from any call puts the instance in the error state, in which only
// fmi2FreeInstance (and the getters, for diagnosis) are accepted. No exception crosses the C
// boundary: every failure is a log message through the importer's logger and fmi2Error.
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include "fmi/export/exported_model.hpp"
#include "fmi/fmi2_api.h"

#define HBT_FMI2_EXPORT extern "C" __attribute__((visibility("default")))

namespace hbt::fmi::exported {
namespace {

enum class Mode { kInstantiated, kInitialization, kStepping, kTerminated, kError };

struct Component {
  std::string name;
  fmi2CallbackFunctions callbacks{};
  std::unique_ptr<ExportedModel> model;
  Mode mode = Mode::kInstantiated;
  double time_s = 0.0;  // the communication point reached
};

void logTo(const fmi2CallbackFunctions* cb, const std::string& instance, fmi2Status s, const char* category,
           const std::string& text) {
  if (cb && cb->logger) cb->logger(cb->componentEnvironment, instance.c_str(), s, category, "%s", text.c_str());
}

fmi2Status fail(Component* c, const std::string& text) {
  logTo(&c->callbacks, c->name, fmi2Error, "error", text);
  c->mode = Mode::kError;
  return fmi2Error;
}

// file:///dir, file://localhost/dir or file:/dir (RFC 8089) with percent-encoded bytes -> /dir
bool uriToPath(const char* uri, std::string& path) {
  if (!uri) return false;
  std::string u(uri);
  if (u.rfind("file://localhost/", 0) == 0) u = u.substr(16);
  else if (u.rfind("file:///", 0) == 0) u = u.substr(7);
  else if (u.rfind("file:/", 0) == 0) u = u.substr(5);
  else return false;
  path.clear();
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (u[i] == '%' && i + 2 < u.size()) {
      path += static_cast<char>(std::stoi(u.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      path += u[i];
    }
  }
  while (path.size() > 1 && path.back() == '/') path.pop_back();
  return true;
}

Component* asComponent(fmi2Component c) { return static_cast<Component*>(c); }

// Runs f (which may throw) as one fmi2 call: fmi2Error in the error state or on an exception.
template <class F>
fmi2Status guarded(fmi2Component c, const char* call, F&& f) {
  Component* comp = asComponent(c);
  if (!comp) return fmi2Error;
  if (comp->mode == Mode::kError) return fmi2Error;
  try {
    return f(comp);
  } catch (const std::exception& e) {
    return fail(comp, std::string(call) + ": " + e.what());
  }
}

template <class T, class Get>
fmi2Status getValues(fmi2Component c, const char* call, const fmi2ValueReference vr[], std::size_t n, T value[],
                     Get get) {
  Component* comp = asComponent(c);
  if (!comp) return fmi2Error;
  for (std::size_t i = 0; i < n; ++i) {
    auto* p = get(*comp->model, vr[i]);
    if (!p) return fail(comp, std::string(call) + ": no variable with value reference " + std::to_string(vr[i]));
    value[i] = static_cast<T>(*p);
  }
  return fmi2OK;
}

template <class T, class Get>
fmi2Status setValues(fmi2Component c, const char* call, const fmi2ValueReference vr[], std::size_t n,
                     const T value[], Get get) {
  return guarded(c, call, [&](Component* comp) {
    for (std::size_t i = 0; i < n; ++i) {
      auto* p = get(*comp->model, vr[i]);
      if (!p) return fail(comp, std::string(call) + ": no variable with value reference " + std::to_string(vr[i]));
      const Causality k = comp->model->causality(vr[i]);
      if (k == Causality::kOutput)
        return fail(comp, std::string(call) + ": value reference " + std::to_string(vr[i]) + " is an output");
      if (k == Causality::kParameter && comp->mode != Mode::kInstantiated && comp->mode != Mode::kInitialization)
        return fail(comp, std::string(call) + ": value reference " + std::to_string(vr[i]) +
                              " is a fixed parameter: settable before fmi2ExitInitializationMode only");
      *p = static_cast<std::remove_reference_t<decltype(*p)>>(value[i]);
    }
    return fmi2OK;
  });
}

fmi2Status unsupported(fmi2Component c, const char* call) {
  Component* comp = asComponent(c);
  if (comp) logTo(&comp->callbacks, comp->name, fmi2Error, "error", std::string(call) + " is not supported by this FMU");
  return fmi2Error;
}

}  // namespace
}  // namespace hbt::fmi::exported

using namespace hbt::fmi::exported;

HBT_FMI2_EXPORT const char* fmi2GetTypesPlatform(void) { return "default"; }
HBT_FMI2_EXPORT const char* fmi2GetVersion(void) { return "2.0"; }

HBT_FMI2_EXPORT fmi2Component fmi2Instantiate(fmi2String instance_name, fmi2Type type, fmi2String guid,
                                              fmi2String resources, const fmi2CallbackFunctions* callbacks,
                                              fmi2Boolean /*visible*/, fmi2Boolean /*logging_on*/) {
  const std::string name = instance_name ? instance_name : "";
  auto refuse = [&](const std::string& why) -> fmi2Component {
    logTo(callbacks, name, fmi2Error, "error", std::string(kModelIdentifier) + ": fmi2Instantiate: " + why);
    return nullptr;
  };
  if (type != fmi2CoSimulation) return refuse("this FMU is Co-Simulation only");
  if (!guid || std::string(guid) != kGuid)
    return refuse(std::string("GUID ") + (guid ? guid : "(null)") + " is not this binary's " + kGuid);
  std::string dir;
  if (!uriToPath(resources, dir))
    return refuse(std::string("resources location '") + (resources ? resources : "(null)") + "' is not a file URI");
  try {
    auto comp = std::make_unique<Component>();
    comp->name = name;
    if (callbacks) comp->callbacks = *callbacks;
    comp->model = makeExportedModel(dir);
    return comp.release();
  } catch (const std::exception& e) {
    return refuse(e.what());
  }
}

HBT_FMI2_EXPORT void fmi2FreeInstance(fmi2Component c) { delete asComponent(c); }

HBT_FMI2_EXPORT fmi2Status fmi2SetDebugLogging(fmi2Component, fmi2Boolean, size_t, const fmi2String[]) {
  return fmi2OK;  // one log category (error); nothing else is logged
}

HBT_FMI2_EXPORT fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean, fmi2Real, fmi2Real start_time,
                                               fmi2Boolean, fmi2Real) {
  return guarded(c, "fmi2SetupExperiment", [&](Component* comp) {
    if (comp->mode != Mode::kInstantiated) return fail(comp, "fmi2SetupExperiment: not after instantiation");
    comp->time_s = start_time;
    return fmi2OK;
  });
}

HBT_FMI2_EXPORT fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  return guarded(c, "fmi2EnterInitializationMode", [&](Component* comp) {
    if (comp->mode != Mode::kInstantiated) return fail(comp, "fmi2EnterInitializationMode: not after instantiation");
    comp->mode = Mode::kInitialization;
    return fmi2OK;
  });
}

HBT_FMI2_EXPORT fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  return guarded(c, "fmi2ExitInitializationMode", [&](Component* comp) {
    if (comp->mode != Mode::kInitialization) return fail(comp, "fmi2ExitInitializationMode: not in initialization mode");
    comp->model->initialize();
    comp->mode = Mode::kStepping;
    return fmi2OK;
  });
}

HBT_FMI2_EXPORT fmi2Status fmi2Terminate(fmi2Component c) {
  return guarded(c, "fmi2Terminate", [&](Component* comp) {
    comp->mode = Mode::kTerminated;
    return fmi2OK;
  });
}

HBT_FMI2_EXPORT fmi2Status fmi2Reset(fmi2Component c) { return unsupported(c, "fmi2Reset"); }

HBT_FMI2_EXPORT fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[]) {
  return getValues(c, "fmi2GetReal", vr, n, v, [](ExportedModel& m, unsigned r) { return m.real(r); });
}
HBT_FMI2_EXPORT fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[]) {
  return getValues(c, "fmi2GetInteger", vr, n, v, [](ExportedModel& m, unsigned r) { return m.integer(r); });
}
HBT_FMI2_EXPORT fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[]) {
  return getValues(c, "fmi2GetBoolean", vr, n, v, [](ExportedModel& m, unsigned r) { return m.boolean(r); });
}
HBT_FMI2_EXPORT fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference[], size_t n, fmi2String[]) {
  return n == 0 ? fmi2OK : unsupported(c, "fmi2GetString (this FMU has no String variable)");
}
HBT_FMI2_EXPORT fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real v[]) {
  return setValues(c, "fmi2SetReal", vr, n, v, [](ExportedModel& m, unsigned r) { return m.real(r); });
}
HBT_FMI2_EXPORT fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                          const fmi2Integer v[]) {
  return setValues(c, "fmi2SetInteger", vr, n, v, [](ExportedModel& m, unsigned r) { return m.integer(r); });
}
HBT_FMI2_EXPORT fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                          const fmi2Boolean v[]) {
  return setValues(c, "fmi2SetBoolean", vr, n, v, [](ExportedModel& m, unsigned r) { return m.boolean(r); });
}
HBT_FMI2_EXPORT fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference[], size_t n, const fmi2String[]) {
  return n == 0 ? fmi2OK : unsupported(c, "fmi2SetString (this FMU has no String variable)");
}

// Capabilities declared false in modelDescription.xml: present as the standard requires, refused.
HBT_FMI2_EXPORT fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate*) { return unsupported(c, "fmi2GetFMUstate"); }
HBT_FMI2_EXPORT fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate) { return unsupported(c, "fmi2SetFMUstate"); }
HBT_FMI2_EXPORT fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate*) { return unsupported(c, "fmi2FreeFMUstate"); }
HBT_FMI2_EXPORT fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate, size_t*) {
  return unsupported(c, "fmi2SerializedFMUstateSize");
}
HBT_FMI2_EXPORT fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate, fmi2Byte[], size_t) {
  return unsupported(c, "fmi2SerializeFMUstate");
}
HBT_FMI2_EXPORT fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte[], size_t, fmi2FMUstate*) {
  return unsupported(c, "fmi2DeSerializeFMUstate");
}
HBT_FMI2_EXPORT fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference[], size_t,
                                                        const fmi2ValueReference[], size_t, const fmi2Real[],
                                                        fmi2Real[]) {
  return unsupported(c, "fmi2GetDirectionalDerivative");
}
HBT_FMI2_EXPORT fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                                       const fmi2Integer[], const fmi2Real[]) {
  return unsupported(c, "fmi2SetRealInputDerivatives");
}
HBT_FMI2_EXPORT fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                                        const fmi2Integer[], fmi2Real[]) {
  return unsupported(c, "fmi2GetRealOutputDerivatives");
}

// One communication step [t, t + h]: t must be the point reached (no rollback), h > 0.
HBT_FMI2_EXPORT fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean) {
  return guarded(c, "fmi2DoStep", [&](Component* comp) {
    if (comp->mode != Mode::kStepping) return fail(comp, "fmi2DoStep: not after fmi2ExitInitializationMode");
    if (!(h > 0.0) || !std::isfinite(h)) return fail(comp, "fmi2DoStep: step size " + std::to_string(h) + " s is not > 0");
    if (std::abs(t - comp->time_s) > 1e-9 * std::max(1.0, std::abs(t)))
      return fail(comp, "fmi2DoStep: communication point " + std::to_string(t) + " s is not the time reached, " +
                            std::to_string(comp->time_s) + " s (no rollback)");
    comp->model->doStep(h);
    comp->time_s = t + h;
    return fmi2OK;
  });
}

HBT_FMI2_EXPORT fmi2Status fmi2CancelStep(fmi2Component c) { return unsupported(c, "fmi2CancelStep (doStep is synchronous)"); }

HBT_FMI2_EXPORT fmi2Status fmi2GetStatus(fmi2Component, const fmi2StatusKind, fmi2Status*) { return fmi2Discard; }
HBT_FMI2_EXPORT fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k, fmi2Real* v) {
  if (k != fmi2LastSuccessfulTime || !c) return fmi2Discard;
  *v = asComponent(c)->time_s;
  return fmi2OK;
}
HBT_FMI2_EXPORT fmi2Status fmi2GetIntegerStatus(fmi2Component, const fmi2StatusKind, fmi2Integer*) { return fmi2Discard; }
HBT_FMI2_EXPORT fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean* v) {
  if (k != fmi2Terminated || !c) return fmi2Discard;
  *v = fmi2False;  // the model never asks to end the simulation
  return fmi2OK;
}
HBT_FMI2_EXPORT fmi2Status fmi2GetStringStatus(fmi2Component, const fmi2StatusKind, fmi2String*) { return fmi2Discard; }
