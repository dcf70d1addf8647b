/* Test FMU (FMI 2.0 Model Exchange), written from the standard: one continuous state
 *     dx/dt = -k x + b        [1/s]: x dimensionless, k [1/s], b [1/s]
 * b = b1 before t_switch and b2 from t_switch on (a time event: nextEventTime), x := x_reset
 * whenever x falls through x_threshold (a state event: event indicator x - x_threshold), and
 * one step event: the first fmi2CompletedIntegratorStep from t_step_event on asks for event
 * mode (counted in step_events, no effect on x). Between events x is the exponential
 * x(t) = b/k + (x(t0) - b/k) exp(-k (t - t0)) that the tests compare with. */
#include <stdio.h>
#include <string.h>

#include "fmi2_api.h"

#define GUID "{9b3e5d10-hbt-switched-decay-1}"

enum { VR_X, VR_DX, VR_K, VR_B1, VR_B2, VR_T_SWITCH, VR_X_THRESHOLD, VR_X_RESET, VR_T_STEP_EVENT,
       VR_RESETS, VR_STEP_EVENTS };

typedef struct {
  fmi2CallbackFunctions cb;
  double p[VR_T_STEP_EVENT + 1]; /* x, der(x) unused here; parameters by value reference */
  double time_s, x;
  int switched, resets, step_events, step_event_due, step_event_done;
} Instance;

static double b(const Instance* m) { return m->switched ? m->p[VR_B2] : m->p[VR_B1]; }
static double dxdt(const Instance* m) { return -m->p[VR_K] * m->x + b(m); }

hbt_fmi2_GetTypesPlatform_fn fmi2GetTypesPlatform;
const char* fmi2GetTypesPlatform(void) { return "default"; }
hbt_fmi2_GetVersion_fn fmi2GetVersion;
const char* fmi2GetVersion(void) { return "2.0"; }

hbt_fmi2_Instantiate_fn fmi2Instantiate;
fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String resources,
                              const fmi2CallbackFunctions* cb, fmi2Boolean visible, fmi2Boolean logging_on) {
  Instance* m;
  if (!cb || !cb->allocateMemory || type != fmi2ModelExchange || !guid || strcmp(guid, GUID) != 0) return NULL;
  m = (Instance*)cb->allocateMemory(1, sizeof(Instance));
  if (!m) return NULL;
  m->cb = *cb;
  m->x = 1.0; /* start values of modelDescription.xml */
  m->p[VR_K] = 0.5;
  m->p[VR_B1] = 2.0;
  m->p[VR_B2] = -1.0;
  m->p[VR_T_SWITCH] = 1.5;
  m->p[VR_X_THRESHOLD] = 0.5;
  m->p[VR_X_RESET] = 1.5;
  m->p[VR_T_STEP_EVENT] = 0.25;
  return m;
}

hbt_fmi2_FreeInstance_fn fmi2FreeInstance;
void fmi2FreeInstance(fmi2Component c) {
  Instance* m = (Instance*)c;
  if (m) m->cb.freeMemory(m);
}

hbt_fmi2_SetDebugLogging_fn fmi2SetDebugLogging;
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cats[]) { return fmi2OK; }
hbt_fmi2_SetupExperiment_fn fmi2SetupExperiment;
fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tol_defined, fmi2Real tol, fmi2Real start,
                               fmi2Boolean stop_defined, fmi2Real stop) {
  ((Instance*)c)->time_s = start;
  return fmi2OK;
}
hbt_fmi2_EnterInitializationMode_fn fmi2EnterInitializationMode;
fmi2Status fmi2EnterInitializationMode(fmi2Component c) { return fmi2OK; }
hbt_fmi2_ExitInitializationMode_fn fmi2ExitInitializationMode;
fmi2Status fmi2ExitInitializationMode(fmi2Component c) { return fmi2OK; }
hbt_fmi2_Terminate_fn fmi2Terminate;
fmi2Status fmi2Terminate(fmi2Component c) { return fmi2OK; }
hbt_fmi2_Reset_fn fmi2Reset;
fmi2Status fmi2Reset(fmi2Component c) { return fmi2Error; }

hbt_fmi2_GetReal_fn fmi2GetReal;
fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[]) {
  Instance* m = (Instance*)c;
  size_t i;
  for (i = 0; i < n; ++i) {
    if (vr[i] == VR_X) v[i] = m->x;
    else if (vr[i] == VR_DX) v[i] = dxdt(m);
    else if (vr[i] <= VR_T_STEP_EVENT) v[i] = m->p[vr[i]];
    else return fmi2Error;
  }
  return fmi2OK;
}
hbt_fmi2_SetReal_fn fmi2SetReal;
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real v[]) {
  Instance* m = (Instance*)c;
  size_t i;
  for (i = 0; i < n; ++i) {
    if (vr[i] == VR_X) m->x = v[i];
    else if (vr[i] >= VR_K && vr[i] <= VR_T_STEP_EVENT) m->p[vr[i]] = v[i];
    else return fmi2Error;
  }
  return fmi2OK;
}
hbt_fmi2_GetInteger_fn fmi2GetInteger;
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[]) {
  Instance* m = (Instance*)c;
  size_t i;
  for (i = 0; i < n; ++i) {
    if (vr[i] == VR_RESETS) v[i] = m->resets;
    else if (vr[i] == VR_STEP_EVENTS) v[i] = m->step_events;
    else return fmi2Error;
  }
  return fmi2OK;
}
/* no Integer inputs, no Booleans, no Strings */
hbt_fmi2_SetInteger_fn fmi2SetInteger;
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[]) { return n ? fmi2Error : fmi2OK; }
hbt_fmi2_GetBoolean_fn fmi2GetBoolean;
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[]) { return n ? fmi2Error : fmi2OK; }
hbt_fmi2_SetBoolean_fn fmi2SetBoolean;
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]) { return n ? fmi2Error : fmi2OK; }
hbt_fmi2_GetString_fn fmi2GetString;
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]) { return n ? fmi2Error : fmi2OK; }
hbt_fmi2_SetString_fn fmi2SetString;
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]) { return n ? fmi2Error : fmi2OK; }

/* ---- Model Exchange ---- */
hbt_fmi2_EnterEventMode_fn fmi2EnterEventMode;
fmi2Status fmi2EnterEventMode(fmi2Component c) { return fmi2OK; }

hbt_fmi2_NewDiscreteStates_fn fmi2NewDiscreteStates;
fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo* info) {
  Instance* m = (Instance*)c;
  memset(info, 0, sizeof *info);
  if (!m->switched && m->time_s >= m->p[VR_T_SWITCH]) m->switched = 1;
  /* falling through the threshold (the indicator's sign after the crossing) towards an
   * equilibrium below it */
  if (m->x <= m->p[VR_X_THRESHOLD] && b(m) / m->p[VR_K] < m->p[VR_X_THRESHOLD]) {
    m->x = m->p[VR_X_RESET];
    ++m->resets;
    info->valuesOfContinuousStatesChanged = fmi2True;
  }
  if (m->step_event_due) {
    m->step_event_due = 0;
    m->step_event_done = 1;
    ++m->step_events;
  }
  info->nextEventTimeDefined = !m->switched;
  info->nextEventTime = m->p[VR_T_SWITCH];
  return fmi2OK;
}

hbt_fmi2_EnterContinuousTimeMode_fn fmi2EnterContinuousTimeMode;
fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) { return fmi2OK; }

hbt_fmi2_CompletedIntegratorStep_fn fmi2CompletedIntegratorStep;
fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean no_prior, fmi2Boolean* enter_event,
                                       fmi2Boolean* terminate) {
  Instance* m = (Instance*)c;
  m->step_event_due = !m->step_event_done && m->time_s >= m->p[VR_T_STEP_EVENT];
  *enter_event = m->step_event_due ? fmi2True : fmi2False;
  *terminate = fmi2False;
  return fmi2OK;
}

hbt_fmi2_SetTime_fn fmi2SetTime;
fmi2Status fmi2SetTime(fmi2Component c, fmi2Real t) {
  ((Instance*)c)->time_s = t;
  return fmi2OK;
}
hbt_fmi2_SetContinuousStates_fn fmi2SetContinuousStates;
fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t n) {
  if (n != 1) return fmi2Error;
  ((Instance*)c)->x = x[0];
  return fmi2OK;
}
hbt_fmi2_GetDerivatives_fn fmi2GetDerivatives;
fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real dx[], size_t n) {
  if (n != 1) return fmi2Error;
  dx[0] = dxdt((Instance*)c);
  return fmi2OK;
}
hbt_fmi2_GetEventIndicators_fn fmi2GetEventIndicators;
fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real z[], size_t n) {
  Instance* m = (Instance*)c;
  if (n != 1) return fmi2Error;
  z[0] = m->x - m->p[VR_X_THRESHOLD];
  return fmi2OK;
}
hbt_fmi2_GetContinuousStates_fn fmi2GetContinuousStates;
fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t n) {
  if (n != 1) return fmi2Error;
  x[0] = ((Instance*)c)->x;
  return fmi2OK;
}
hbt_fmi2_GetNominalsOfContinuousStates_fn fmi2GetNominalsOfContinuousStates;
fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real nominal[], size_t n) {
  if (n != 1) return fmi2Error;
  nominal[0] = 1.0;
  return fmi2OK;
}
