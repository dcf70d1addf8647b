/* Test FMU (FMI 2.0 Co-Simulation), written from the standard: a lumped thermal mass
 *     C dT/dt = Q - G (T - T_amb)        [J/K] [K/s] = [W] - [W/K] [K]
 * T and T_amb in degC (the modelDescription's unit, BaseUnit K with offset 273.15), Q in kW
 * (factor 1000 to W). C [J/K] and G [W/K] are read from <resources>/thermal_mass.txt, the
 * resources location fmi2Instantiate receives as a file:// URI; without it instantiation
 * fails. insulated = true sets G = 0. fmi2DoStep integrates with the classical fourth-order
 * Runge-Kutta method on substeps of at most 0.01 s (the tests compare with the exact exponential).
 *
 * Variants (compile definitions): HBT_FMU_OMIT_DO_STEP (no fmi2DoStep export),
 * HBT_FMU_ERROR_FROM_S=t (fmi2DoStep returns fmi2Error from communication time t [s] on),
 * HBT_FMU_NAN_FROM_S=t (T becomes NaN from t on), HBT_FMU_HANG_FROM_S=t (fmi2DoStep never returns
 * from t on: it sleeps, as a hung tool would), HBT_FMU_SET_ERROR_FROM_S=t (fmi2SetReal returns
 * fmi2Error from t on), HBT_FMU_WARN_BELOW_C=T (the Boolean output mass_a.warning.cooled,
 * VR_WARNING: true while T < T degC, by the naming convention of the project's FMUs; the step
 * that sets it logs "cooled below T degC" with status OK). */
#include <math.h>
#ifdef HBT_FMU_HANG_FROM_S
#include <time.h>
#endif
#include <stdio.h>
#include <string.h>

#include "fmi2_api.h"

#define GUID "{4f1c2a7e-hbt-thermal-mass-1}"
#define MAX_SUBSTEP_S 0.01
#define HBT_FMU_STR2(x) #x
#define HBT_FMU_STR(x) HBT_FMU_STR2(x)

enum { VR_T, VR_Q, VR_T_AMB, VR_T_START, VR_STEPS, VR_INSULATED, VR_TIME, VR_WARNING, N_VR };

typedef struct {
  fmi2CallbackFunctions cb;
  char name[128];
  double C_J_per_K, G_W_per_K;
  double T_degC, Q_kW, T_amb_degC, T_start_degC, time_s;
  int steps, insulated;
} Instance;

static void log_msg(Instance* m, fmi2Status s, const char* category, const char* text, const char* arg) {
  if (m->cb.logger) m->cb.logger(m->cb.componentEnvironment, m->name, s, category, text, arg);
}

/* file:///a/b%20c or file:/a/b%20c (with or without the empty authority, as FMI 2.0 wants an FMU
 * to understand both) -> /a/b c; 0 if uri is not a file URI with an absolute path */
static int uri_to_path(const char* uri, char* path, size_t size) {
  const char* p;
  size_t n = 0;
  if (!uri || strncmp(uri, "file:", 5) != 0) return 0;
  p = strncmp(uri, "file://", 7) == 0 ? uri + 7 : uri + 5;
  if (*p != '/') return 0;
  for (; *p && n + 1 < size; ++p) {
    unsigned int byte;
    if (*p == '%' && sscanf(p + 1, "%2x", &byte) == 1) {
      path[n++] = (char)byte;
      p += 2;
    } else {
      path[n++] = *p;
    }
  }
  path[n] = '\0';
  return *p == '\0';
}

static int read_parameters(Instance* m, const char* resource_uri) {
  char path[4096], key[64], line[256];
  double value;
  int found = 0;
  FILE* f;
  if (!uri_to_path(resource_uri, path, sizeof path - 32)) {
    log_msg(m, fmi2Error, "error", "resources location %s is not a file URI", resource_uri ? resource_uri : "(null)");
    return 0;
  }
  strcat(path, "/thermal_mass.txt");
  f = fopen(path, "r");
  if (!f) {
    log_msg(m, fmi2Error, "error", "cannot open %s", path);
    return 0;
  }
  while (fgets(line, sizeof line, f)) {
    if (line[0] == '#' || sscanf(line, "%63s %lf", key, &value) != 2) continue;
    if (strcmp(key, "heat_capacity_J_per_K") == 0) m->C_J_per_K = value, found |= 1;
    if (strcmp(key, "conductance_W_per_K") == 0) m->G_W_per_K = value, found |= 2;
  }
  fclose(f);
  if (found != 3 || !(m->C_J_per_K > 0.0) || m->G_W_per_K < 0.0) {
    log_msg(m, fmi2Error, "error", "%s: needs heat_capacity_J_per_K > 0 and conductance_W_per_K >= 0", path);
    return 0;
  }
  log_msg(m, fmi2OK, "info", "parameters read from %s", path);
  return 1;
}

hbt_fmi2_GetTypesPlatform_fn fmi2GetTypesPlatform;
const char* fmi2GetTypesPlatform(void) { return "default"; }
hbt_fmi2_GetVersion_fn fmi2GetVersion;
const char* fmi2GetVersion(void) { return "2.0"; }

hbt_fmi2_Instantiate_fn fmi2Instantiate;
fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String resources,
                              const fmi2CallbackFunctions* cb, fmi2Boolean visible, fmi2Boolean logging_on) {
  Instance* m;
  (void)visible;
  (void)logging_on;
  if (!cb || !cb->allocateMemory || type != fmi2CoSimulation || !guid || strcmp(guid, GUID) != 0) return NULL;
  m = (Instance*)cb->allocateMemory(1, sizeof(Instance));
  if (!m) return NULL;
  m->cb = *cb;
  snprintf(m->name, sizeof m->name, "%s", name ? name : "");
  m->Q_kW = 0.0;
  m->T_amb_degC = 20.0;
  m->T_start_degC = 20.0;
  if (!read_parameters(m, resources)) {
    cb->freeMemory(m);
    return NULL;
  }
  return m;
}

hbt_fmi2_FreeInstance_fn fmi2FreeInstance;
void fmi2FreeInstance(fmi2Component c) {
  Instance* m = (Instance*)c;
  if (m) m->cb.freeMemory(m);
}

hbt_fmi2_SetDebugLogging_fn fmi2SetDebugLogging;
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String cats[]) {
  return fmi2OK;
}

hbt_fmi2_SetupExperiment_fn fmi2SetupExperiment;
fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean tol_defined, fmi2Real tol, fmi2Real start,
                               fmi2Boolean stop_defined, fmi2Real stop) {
  ((Instance*)c)->time_s = start;
  return fmi2OK;
}

hbt_fmi2_EnterInitializationMode_fn fmi2EnterInitializationMode;
fmi2Status fmi2EnterInitializationMode(fmi2Component c) { return fmi2OK; }

hbt_fmi2_ExitInitializationMode_fn fmi2ExitInitializationMode;
fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  Instance* m = (Instance*)c;
  m->T_degC = m->T_start_degC;
  return fmi2OK;
}

hbt_fmi2_Terminate_fn fmi2Terminate;
fmi2Status fmi2Terminate(fmi2Component c) {
  log_msg((Instance*)c, fmi2OK, "info", "terminated (%s)", "no error");
  return fmi2OK;
}

hbt_fmi2_Reset_fn fmi2Reset;
fmi2Status fmi2Reset(fmi2Component c) { return fmi2Error; }

hbt_fmi2_GetReal_fn fmi2GetReal;
fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[]) {
  Instance* m = (Instance*)c;
  size_t i;
  for (i = 0; i < n; ++i) {
    switch (vr[i]) {
      case VR_T: v[i] = m->T_degC; break;
      case VR_Q: v[i] = m->Q_kW; break;
      case VR_T_AMB: v[i] = m->T_amb_degC; break;
      case VR_T_START: v[i] = m->T_start_degC; break;
      case VR_TIME: v[i] = m->time_s; break;
      default: return fmi2Error;
    }
  }
  return fmi2OK;
}

hbt_fmi2_SetReal_fn fmi2SetReal;
fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Real v[]) {
  Instance* m = (Instance*)c;
  size_t i;
#ifdef HBT_FMU_SET_ERROR_FROM_S
  if (m->time_s >= HBT_FMU_SET_ERROR_FROM_S) {
    log_msg(m, fmi2Error, "error", "deliberate failure (%s)", "test variant set_error_at_2s");
    return fmi2Error;
  }
#endif
  for (i = 0; i < n; ++i) {
    switch (vr[i]) {
      case VR_Q: m->Q_kW = v[i]; break;
      case VR_T_AMB: m->T_amb_degC = v[i]; break;
      case VR_T_START: m->T_start_degC = v[i]; break;
      default: return fmi2Error;
    }
  }
  return fmi2OK;
}

hbt_fmi2_GetInteger_fn fmi2GetInteger;
fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Integer v[]) {
  size_t i;
  for (i = 0; i < n; ++i) {
    if (vr[i] != VR_STEPS) return fmi2Error;
    v[i] = ((Instance*)c)->steps;
  }
  return fmi2OK;
}

hbt_fmi2_GetBoolean_fn fmi2GetBoolean;
fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Boolean v[]) {
  size_t i;
  for (i = 0; i < n; ++i) {
#ifdef HBT_FMU_WARN_BELOW_C
    if (vr[i] == VR_WARNING) {
      v[i] = ((Instance*)c)->T_degC < HBT_FMU_WARN_BELOW_C;
      continue;
    }
#endif
    if (vr[i] != VR_INSULATED) return fmi2Error;
    v[i] = ((Instance*)c)->insulated;
  }
  return fmi2OK;
}

hbt_fmi2_SetBoolean_fn fmi2SetBoolean;
fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Boolean v[]) {
  size_t i;
  for (i = 0; i < n; ++i) {
    if (vr[i] != VR_INSULATED) return fmi2Error;
    ((Instance*)c)->insulated = v[i] != fmi2False;
  }
  return fmi2OK;
}

/* no Integer inputs, no Strings */
hbt_fmi2_SetInteger_fn fmi2SetInteger;
fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2Integer v[]) {
  return n == 0 ? fmi2OK : fmi2Error;
}
hbt_fmi2_GetString_fn fmi2GetString;
fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2String v[]) {
  return n == 0 ? fmi2OK : fmi2Error;
}
hbt_fmi2_SetString_fn fmi2SetString;
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n, const fmi2String v[]) {
  return n == 0 ? fmi2OK : fmi2Error;
}

#ifndef HBT_FMU_OMIT_DO_STEP
/* dT/dt [K/s] */
static double derivative(const Instance* m, double T_degC) {
  const double G = m->insulated ? 0.0 : m->G_W_per_K;
  return (1000.0 * m->Q_kW - G * (T_degC - m->T_amb_degC)) / m->C_J_per_K;
}

hbt_fmi2_DoStep_fn fmi2DoStep;
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean no_prior) {
  Instance* m = (Instance*)c;
  const int n = (int)ceil(h / MAX_SUBSTEP_S - 1e-9);
#ifdef HBT_FMU_WARN_BELOW_C
  const int was_warm = m->T_degC >= HBT_FMU_WARN_BELOW_C;
#endif
  const double dt = h / n;
  int i;
#ifdef HBT_FMU_ERROR_FROM_S
  if (t >= HBT_FMU_ERROR_FROM_S) {
    log_msg(m, fmi2Error, "error", "deliberate failure (%s)", "test variant error_at_2s");
    return fmi2Error;
  }
#endif
#ifdef HBT_FMU_HANG_FROM_S
  if (t >= HBT_FMU_HANG_FROM_S) {
    for (;;) {
      const struct timespec one_second = {1, 0};
      nanosleep(&one_second, NULL);
    }
  }
#endif
  for (i = 0; i < n; ++i) {
    const double T = m->T_degC;
    const double k1 = derivative(m, T);
    const double k2 = derivative(m, T + 0.5 * dt * k1);
    const double k3 = derivative(m, T + 0.5 * dt * k2);
    const double k4 = derivative(m, T + dt * k3);
    m->T_degC = T + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
#ifdef HBT_FMU_NAN_FROM_S
  if (t >= HBT_FMU_NAN_FROM_S) m->T_degC = NAN;
#endif
  m->time_s = t + h;
  ++m->steps;
#ifdef HBT_FMU_WARN_BELOW_C
  if (was_warm && m->T_degC < HBT_FMU_WARN_BELOW_C) log_msg(m, fmi2OK, "info", "cooled below %s degC", HBT_FMU_STR(HBT_FMU_WARN_BELOW_C));
#endif
  return fmi2OK;
}
#endif

hbt_fmi2_CancelStep_fn fmi2CancelStep;
fmi2Status fmi2CancelStep(fmi2Component c) { return fmi2Error; } /* doStep is synchronous */

/* asynchronous status queries: nothing is pending */
hbt_fmi2_GetStatus_fn fmi2GetStatus;
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status* v) { return fmi2Discard; }
hbt_fmi2_GetRealStatus_fn fmi2GetRealStatus;
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k, fmi2Real* v) {
  if (k != fmi2LastSuccessfulTime) return fmi2Discard;
  *v = ((Instance*)c)->time_s;
  return fmi2OK;
}
hbt_fmi2_GetIntegerStatus_fn fmi2GetIntegerStatus;
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k, fmi2Integer* v) { return fmi2Discard; }
hbt_fmi2_GetBooleanStatus_fn fmi2GetBooleanStatus;
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean* v) {
  if (k != fmi2Terminated) return fmi2Discard;
  *v = fmi2False;
  return fmi2OK;
}
hbt_fmi2_GetStringStatus_fn fmi2GetStringStatus;
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k, fmi2String* v) { return fmi2Discard; }
