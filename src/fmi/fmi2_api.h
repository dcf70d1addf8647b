/* The FMI 2.0 C interface as this project uses it, written from the published standard
 * (Functional Mock-up Interface for Model Exchange and Co-Simulation, version 2.0, Modelica
 * Association, 2014; 2.0.4, 2022: section 2.1, the application programming interface common to
 * both interface types; section 3.2, Model Exchange; section 4.2, Co-Simulation). Plain C, so that the test FMUs (test/fmi/fmus, C) and the importer (C++) share it.
 *
 * A shared library of an FMU exports the functions under their plain names (fmi2DoStep, ...).
 * The hbt_fmi2_*_fn names below are the function types of those exports; the importer resolves
 * each export with dlsym into a pointer of that type, an FMU declares its definitions with them
 * so that the compiler checks every signature. */
#ifndef HBT_FMI2_API_H
#define HBT_FMI2_API_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Platform types of the standard's "default" platform (types platform string "default"). */
typedef void* fmi2Component;            /* an instance of the model */
typedef void* fmi2ComponentEnvironment; /* the importer's pointer, handed back to the callbacks */
typedef void* fmi2FMUstate;             /* a saved state of an instance */
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Integer;
typedef int fmi2Boolean; /* fmi2True = 1, fmi2False = 0 */
typedef char fmi2Char;
typedef const fmi2Char* fmi2String;
typedef char fmi2Byte;

#define fmi2True 1
#define fmi2False 0

typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;
typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;
typedef enum {
  fmi2DoStepStatus,
  fmi2PendingStatus,
  fmi2LastSuccessfulTime,
  fmi2Terminated
} fmi2StatusKind;

/* Callbacks the importer hands to fmi2Instantiate; the struct must stay valid (same address)
 * for the life of the instance. The logger's message is a printf format for the trailing
 * arguments. */
typedef void (*fmi2CallbackLogger)(fmi2ComponentEnvironment env, fmi2String instance_name,
                                   fmi2Status status, fmi2String category, fmi2String message,
                                   ...);
typedef void* (*fmi2CallbackAllocateMemory)(size_t n_objects, size_t object_size);
typedef void (*fmi2CallbackFreeMemory)(void* object);
typedef void (*fmi2StepFinished)(fmi2ComponentEnvironment env, fmi2Status status);

typedef struct {
  fmi2CallbackLogger logger;
  fmi2CallbackAllocateMemory allocateMemory; /* zero-initialised, like calloc */
  fmi2CallbackFreeMemory freeMemory;
  fmi2StepFinished stepFinished; /* NULL: fmi2DoStep works synchronously */
  fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;

/* Model Exchange: what fmi2NewDiscreteStates reports. */
typedef struct {
  fmi2Boolean newDiscreteStatesNeeded;
  fmi2Boolean terminateSimulation;
  fmi2Boolean nominalsOfContinuousStatesChanged;
  fmi2Boolean valuesOfContinuousStatesChanged;
  fmi2Boolean nextEventTimeDefined;
  fmi2Real nextEventTime; /* [s] */
} fmi2EventInfo;

/* ---- Functions of both interface types ---- */
typedef const char* hbt_fmi2_GetTypesPlatform_fn(void);
typedef const char* hbt_fmi2_GetVersion_fn(void);
typedef fmi2Status hbt_fmi2_SetDebugLogging_fn(fmi2Component c, fmi2Boolean logging_on,
                                               size_t n_categories, const fmi2String categories[]);
typedef fmi2Component hbt_fmi2_Instantiate_fn(fmi2String instance_name, fmi2Type type,
                                              fmi2String guid, fmi2String resource_location,
                                              const fmi2CallbackFunctions* functions,
                                              fmi2Boolean visible, fmi2Boolean logging_on);
typedef void hbt_fmi2_FreeInstance_fn(fmi2Component c);
typedef fmi2Status hbt_fmi2_SetupExperiment_fn(fmi2Component c, fmi2Boolean tolerance_defined,
                                               fmi2Real tolerance, fmi2Real start_time,
                                               fmi2Boolean stop_time_defined, fmi2Real stop_time);
typedef fmi2Status hbt_fmi2_EnterInitializationMode_fn(fmi2Component c);
typedef fmi2Status hbt_fmi2_ExitInitializationMode_fn(fmi2Component c);
typedef fmi2Status hbt_fmi2_Terminate_fn(fmi2Component c);
typedef fmi2Status hbt_fmi2_Reset_fn(fmi2Component c);
typedef fmi2Status hbt_fmi2_GetReal_fn(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       fmi2Real value[]);
typedef fmi2Status hbt_fmi2_GetInteger_fn(fmi2Component c, const fmi2ValueReference vr[],
                                          size_t n, fmi2Integer value[]);
typedef fmi2Status hbt_fmi2_GetBoolean_fn(fmi2Component c, const fmi2ValueReference vr[],
                                          size_t n, fmi2Boolean value[]);
typedef fmi2Status hbt_fmi2_GetString_fn(fmi2Component c, const fmi2ValueReference vr[],
                                         size_t n, fmi2String value[]);
typedef fmi2Status hbt_fmi2_SetReal_fn(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Real value[]);
typedef fmi2Status hbt_fmi2_SetInteger_fn(fmi2Component c, const fmi2ValueReference vr[],
                                          size_t n, const fmi2Integer value[]);
typedef fmi2Status hbt_fmi2_SetBoolean_fn(fmi2Component c, const fmi2ValueReference vr[],
                                          size_t n, const fmi2Boolean value[]);
typedef fmi2Status hbt_fmi2_SetString_fn(fmi2Component c, const fmi2ValueReference vr[],
                                         size_t n, const fmi2String value[]);
/* capability canGetAndSetFMUstate / canSerializeFMUstate / providesDirectionalDerivative */
typedef fmi2Status hbt_fmi2_GetFMUstate_fn(fmi2Component c, fmi2FMUstate* state);
typedef fmi2Status hbt_fmi2_SetFMUstate_fn(fmi2Component c, fmi2FMUstate state);
typedef fmi2Status hbt_fmi2_FreeFMUstate_fn(fmi2Component c, fmi2FMUstate* state);
typedef fmi2Status hbt_fmi2_SerializedFMUstateSize_fn(fmi2Component c, fmi2FMUstate state,
                                                      size_t* size);
typedef fmi2Status hbt_fmi2_SerializeFMUstate_fn(fmi2Component c, fmi2FMUstate state,
                                                 fmi2Byte bytes[], size_t size);
typedef fmi2Status hbt_fmi2_DeSerializeFMUstate_fn(fmi2Component c, const fmi2Byte bytes[],
                                                   size_t size, fmi2FMUstate* state);
typedef fmi2Status hbt_fmi2_GetDirectionalDerivative_fn(
    fmi2Component c, const fmi2ValueReference unknowns[], size_t n_unknowns,
    const fmi2ValueReference knowns[], size_t n_knowns, const fmi2Real d_knowns[],
    fmi2Real d_unknowns[]);

/* ---- Co-Simulation ---- */
typedef fmi2Status hbt_fmi2_SetRealInputDerivatives_fn(fmi2Component c,
                                                       const fmi2ValueReference vr[], size_t n,
                                                       const fmi2Integer order[],
                                                       const fmi2Real value[]);
typedef fmi2Status hbt_fmi2_GetRealOutputDerivatives_fn(fmi2Component c,
                                                        const fmi2ValueReference vr[], size_t n,
                                                        const fmi2Integer order[],
                                                        fmi2Real value[]);
typedef fmi2Status hbt_fmi2_DoStep_fn(fmi2Component c, fmi2Real current_communication_point,
                                      fmi2Real communication_step_size,
                                      fmi2Boolean no_set_fmu_state_prior_to_current_point);
typedef fmi2Status hbt_fmi2_CancelStep_fn(fmi2Component c);
typedef fmi2Status hbt_fmi2_GetStatus_fn(fmi2Component c, const fmi2StatusKind kind,
                                         fmi2Status* value);
typedef fmi2Status hbt_fmi2_GetRealStatus_fn(fmi2Component c, const fmi2StatusKind kind,
                                             fmi2Real* value);
typedef fmi2Status hbt_fmi2_GetIntegerStatus_fn(fmi2Component c, const fmi2StatusKind kind,
                                                fmi2Integer* value);
typedef fmi2Status hbt_fmi2_GetBooleanStatus_fn(fmi2Component c, const fmi2StatusKind kind,
                                                fmi2Boolean* value);
typedef fmi2Status hbt_fmi2_GetStringStatus_fn(fmi2Component c, const fmi2StatusKind kind,
                                               fmi2String* value);

/* ---- Model Exchange ---- */
typedef fmi2Status hbt_fmi2_EnterEventMode_fn(fmi2Component c);
typedef fmi2Status hbt_fmi2_NewDiscreteStates_fn(fmi2Component c, fmi2EventInfo* info);
typedef fmi2Status hbt_fmi2_EnterContinuousTimeMode_fn(fmi2Component c);
typedef fmi2Status hbt_fmi2_CompletedIntegratorStep_fn(fmi2Component c,
                                                       fmi2Boolean no_set_fmu_state_prior,
                                                       fmi2Boolean* enter_event_mode,
                                                       fmi2Boolean* terminate_simulation);
typedef fmi2Status hbt_fmi2_SetTime_fn(fmi2Component c, fmi2Real time);
typedef fmi2Status hbt_fmi2_SetContinuousStates_fn(fmi2Component c, const fmi2Real x[], size_t n);
typedef fmi2Status hbt_fmi2_GetDerivatives_fn(fmi2Component c, fmi2Real derivatives[], size_t n);
typedef fmi2Status hbt_fmi2_GetEventIndicators_fn(fmi2Component c, fmi2Real indicators[],
                                                  size_t n);
typedef fmi2Status hbt_fmi2_GetContinuousStates_fn(fmi2Component c, fmi2Real x[], size_t n);
typedef fmi2Status hbt_fmi2_GetNominalsOfContinuousStates_fn(fmi2Component c, fmi2Real nominals[],
                                                             size_t n);

#ifdef __cplusplus
}
#endif

#endif /* HBT_FMI2_API_H */
