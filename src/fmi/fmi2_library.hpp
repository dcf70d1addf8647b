// The shared library of an FMU (binaries/linux64/<modelIdentifier>.so), opened with dlopen
// (RTLD_NOW | RTLD_LOCAL: two FMUs exporting the same names do not clash) and closed by the
// destructor. Every function the interface type needs is resolved by its plain FMI 2.0 name; a
// missing one is an FmuError naming it. Required: the functions common to both interface types
// apart from the capability-dependent ones (FMU state, serialisation, directional derivatives),
// plus, for Co-Simulation, fmi2DoStep, fmi2CancelStep and the fmi2Get*Status family (input and
// output derivatives are capability-dependent), for Model Exchange the functions of FMI 2.0
// section 3.2. The capability-dependent ones are resolved if
// present (nullptr otherwise).
#pragma once
#include <string>

#include "fmi/fmi2_api.h"
#include "fmi/fmu_archive.hpp"

namespace hbt::fmi {

struct Fmi2Functions {
  // both interface types
  hbt_fmi2_GetTypesPlatform_fn* getTypesPlatform = nullptr;
  hbt_fmi2_GetVersion_fn* getVersion = nullptr;
  hbt_fmi2_SetDebugLogging_fn* setDebugLogging = nullptr;
  hbt_fmi2_Instantiate_fn* instantiate = nullptr;
  hbt_fmi2_FreeInstance_fn* freeInstance = nullptr;
  hbt_fmi2_SetupExperiment_fn* setupExperiment = nullptr;
  hbt_fmi2_EnterInitializationMode_fn* enterInitializationMode = nullptr;
  hbt_fmi2_ExitInitializationMode_fn* exitInitializationMode = nullptr;
  hbt_fmi2_Terminate_fn* terminate = nullptr;
  hbt_fmi2_Reset_fn* reset = nullptr;
  hbt_fmi2_GetReal_fn* getReal = nullptr;
  hbt_fmi2_GetInteger_fn* getInteger = nullptr;
  hbt_fmi2_GetBoolean_fn* getBoolean = nullptr;
  hbt_fmi2_GetString_fn* getString = nullptr;
  hbt_fmi2_SetReal_fn* setReal = nullptr;
  hbt_fmi2_SetInteger_fn* setInteger = nullptr;
  hbt_fmi2_SetBoolean_fn* setBoolean = nullptr;
  hbt_fmi2_SetString_fn* setString = nullptr;
  // capability-dependent (nullptr if absent)
  hbt_fmi2_GetFMUstate_fn* getFMUstate = nullptr;
  hbt_fmi2_SetFMUstate_fn* setFMUstate = nullptr;
  hbt_fmi2_FreeFMUstate_fn* freeFMUstate = nullptr;
  hbt_fmi2_SerializedFMUstateSize_fn* serializedFMUstateSize = nullptr;
  hbt_fmi2_SerializeFMUstate_fn* serializeFMUstate = nullptr;
  hbt_fmi2_DeSerializeFMUstate_fn* deSerializeFMUstate = nullptr;
  hbt_fmi2_GetDirectionalDerivative_fn* getDirectionalDerivative = nullptr;
  // Co-Simulation
  hbt_fmi2_SetRealInputDerivatives_fn* setRealInputDerivatives = nullptr;
  hbt_fmi2_GetRealOutputDerivatives_fn* getRealOutputDerivatives = nullptr;
  hbt_fmi2_DoStep_fn* doStep = nullptr;
  hbt_fmi2_CancelStep_fn* cancelStep = nullptr;
  hbt_fmi2_GetStatus_fn* getStatus = nullptr;
  hbt_fmi2_GetRealStatus_fn* getRealStatus = nullptr;
  hbt_fmi2_GetIntegerStatus_fn* getIntegerStatus = nullptr;
  hbt_fmi2_GetBooleanStatus_fn* getBooleanStatus = nullptr;
  hbt_fmi2_GetStringStatus_fn* getStringStatus = nullptr;
  // Model Exchange
  hbt_fmi2_EnterEventMode_fn* enterEventMode = nullptr;
  hbt_fmi2_NewDiscreteStates_fn* newDiscreteStates = nullptr;
  hbt_fmi2_EnterContinuousTimeMode_fn* enterContinuousTimeMode = nullptr;
  hbt_fmi2_CompletedIntegratorStep_fn* completedIntegratorStep = nullptr;
  hbt_fmi2_SetTime_fn* setTime = nullptr;
  hbt_fmi2_SetContinuousStates_fn* setContinuousStates = nullptr;
  hbt_fmi2_GetDerivatives_fn* getDerivatives = nullptr;
  hbt_fmi2_GetEventIndicators_fn* getEventIndicators = nullptr;
  hbt_fmi2_GetContinuousStates_fn* getContinuousStates = nullptr;
  hbt_fmi2_GetNominalsOfContinuousStates_fn* getNominalsOfContinuousStates = nullptr;
};

class Fmi2Library {
 public:
  /// Opens so_path (the extracted binary of an FMU) and resolves the functions interface type
  /// t needs; fmu_file names the FMU in errors.
  Fmi2Library(const std::string& so_path, InterfaceType t, const std::string& fmu_file);
  ~Fmi2Library();
  Fmi2Library(const Fmi2Library&) = delete;
  Fmi2Library& operator=(const Fmi2Library&) = delete;

  const Fmi2Functions& functions() const { return f_; }
  InterfaceType interfaceType() const { return type_; }

 private:
  template <class F>
  void resolve(F*& slot, const char* symbol, bool required);

  std::string so_path_, fmu_file_;
  InterfaceType type_;
  void* handle_ = nullptr;
  Fmi2Functions f_;
};

}  // namespace hbt::fmi
