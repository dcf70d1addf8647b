#include "fmi/fmi2_library.hpp"

#include <dlfcn.h>

#include <cstring>

#include "fmi/fmu_error.hpp"

namespace hbt::fmi {

template <class F>
void Fmi2Library::resolve(F*& slot, const char* symbol, bool required) {
  slot = reinterpret_cast<F*>(dlsym(handle_, symbol));
  if (!slot && required) {
    throw FmuError(fmu_file_, std::string("binary ") + so_path_ + " does not export " + symbol +
                                  " (required for " + name(type_) + ")");
  }
}

Fmi2Library::Fmi2Library(const std::string& so_path, InterfaceType t, const std::string& fmu_file)
    : so_path_(so_path), fmu_file_(fmu_file), type_(t) {
  handle_ = dlopen(so_path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle_) throw FmuError(fmu_file, std::string("cannot load binary: ") + dlerror());
  try {
    const bool cs = t == InterfaceType::kCoSimulation, me = !cs;
    resolve(f_.getTypesPlatform, "fmi2GetTypesPlatform", true);
    resolve(f_.getVersion, "fmi2GetVersion", true);
    resolve(f_.setDebugLogging, "fmi2SetDebugLogging", true);
    resolve(f_.instantiate, "fmi2Instantiate", true);
    resolve(f_.freeInstance, "fmi2FreeInstance", true);
    resolve(f_.setupExperiment, "fmi2SetupExperiment", true);
    resolve(f_.enterInitializationMode, "fmi2EnterInitializationMode", true);
    resolve(f_.exitInitializationMode, "fmi2ExitInitializationMode", true);
    resolve(f_.terminate, "fmi2Terminate", true);
    resolve(f_.reset, "fmi2Reset", true);
    resolve(f_.getReal, "fmi2GetReal", true);
    resolve(f_.getInteger, "fmi2GetInteger", true);
    resolve(f_.getBoolean, "fmi2GetBoolean", true);
    resolve(f_.getString, "fmi2GetString", true);
    resolve(f_.setReal, "fmi2SetReal", true);
    resolve(f_.setInteger, "fmi2SetInteger", true);
    resolve(f_.setBoolean, "fmi2SetBoolean", true);
    resolve(f_.setString, "fmi2SetString", true);
    resolve(f_.getFMUstate, "fmi2GetFMUstate", false);
    resolve(f_.setFMUstate, "fmi2SetFMUstate", false);
    resolve(f_.freeFMUstate, "fmi2FreeFMUstate", false);
    resolve(f_.serializedFMUstateSize, "fmi2SerializedFMUstateSize", false);
    resolve(f_.serializeFMUstate, "fmi2SerializeFMUstate", false);
    resolve(f_.deSerializeFMUstate, "fmi2DeSerializeFMUstate", false);
    resolve(f_.getDirectionalDerivative, "fmi2GetDirectionalDerivative", false);
    resolve(f_.setRealInputDerivatives, "fmi2SetRealInputDerivatives", false);
    resolve(f_.getRealOutputDerivatives, "fmi2GetRealOutputDerivatives", false);
    resolve(f_.doStep, "fmi2DoStep", cs);
    resolve(f_.cancelStep, "fmi2CancelStep", cs);
    resolve(f_.getStatus, "fmi2GetStatus", cs);
    resolve(f_.getRealStatus, "fmi2GetRealStatus", cs);
    resolve(f_.getIntegerStatus, "fmi2GetIntegerStatus", cs);
    resolve(f_.getBooleanStatus, "fmi2GetBooleanStatus", cs);
    resolve(f_.getStringStatus, "fmi2GetStringStatus", cs);
    resolve(f_.enterEventMode, "fmi2EnterEventMode", me);
    resolve(f_.newDiscreteStates, "fmi2NewDiscreteStates", me);
    resolve(f_.enterContinuousTimeMode, "fmi2EnterContinuousTimeMode", me);
    resolve(f_.completedIntegratorStep, "fmi2CompletedIntegratorStep", me);
    resolve(f_.setTime, "fmi2SetTime", me);
    resolve(f_.setContinuousStates, "fmi2SetContinuousStates", me);
    resolve(f_.getDerivatives, "fmi2GetDerivatives", me);
    resolve(f_.getEventIndicators, "fmi2GetEventIndicators", me);
    resolve(f_.getContinuousStates, "fmi2GetContinuousStates", me);
    resolve(f_.getNominalsOfContinuousStates, "fmi2GetNominalsOfContinuousStates", me);
    const char* version = f_.getVersion();
    if (!version || std::strcmp(version, "2.0") != 0) {
      throw FmuError(fmu_file, std::string("fmi2GetVersion returns \"") + (version ? version : "") +
                                   "\", not \"2.0\"");
    }
  } catch (...) {
    dlclose(handle_);
    throw;
  }
}

Fmi2Library::~Fmi2Library() { dlclose(handle_); }

}  // namespace hbt::fmi
