// Test hook, never part of the product: one participant's model step made to throw, or to yield
// NaN, from a given simulated time on -- for test/scenario/test_faults.py. It is linked only into
// the test executables <participant>_fault_node (test/faults/CMakeLists.txt) with
// -Wl,--wrap=<the model's step symbol>: the linker sends the participant's call of its model's
// step to __wrap_<symbol> below, which calls the model (__real_<symbol>) and injects the fault.
// The product's executables, nodelets and libraries are built and linked without it.
// The nodelets' form: libhbt_nodelets built again with every participant's hook, in its own folder
// (the test puts it first on the library path of pluginlib).
//   HBT_FAULT_PARTICIPANT=<name>   HBT_FAULT=throw|nan|hang   HBT_FAULT_AT_S=<simulated time [s], default 5>
// throw: the step starting at or after HBT_FAULT_AT_S throws ModelDivergence (as a model whose
//        state became non-physical does); nan: from that step on, one output of the model is NaN
//        (HBT_FAULT_FIELD below), which the participant publishes; hang: that step never returns
//        (an endless loop in a model).
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <thread>

#include "common/errors.hpp"

namespace {
enum class Kind { None, Throw, NaN, Hang };

struct Fault {
  Kind kind = Kind::None;
  double at_s = 5.0;  // [s] simulated
  double t_s = 0.0;   // model time: the sum of the steps taken [s]
};

Fault& fault() {
  static Fault f = [] {
    Fault r;
    const char* k = std::getenv("HBT_FAULT");
    const char* p = std::getenv("HBT_FAULT_PARTICIPANT");
    const std::string kind = k && p && std::string(p) == HBT_FAULT_NAME ? k : "";
    r.kind = kind == "throw" ? Kind::Throw : kind == "nan" ? Kind::NaN : kind == "hang" ? Kind::Hang : Kind::None;
    if (const char* a = std::getenv("HBT_FAULT_AT_S")) r.at_s = std::strtod(a, nullptr);
    return r;
  }();
  return f;
}

/// Before the step from t to t + dt: throws if a throw is due, never returns if a hang is.
void beforeStep(const char* model) {
  const Fault& f = fault();
  if (f.kind == Kind::None || f.kind == Kind::NaN || f.t_s < f.at_s - 1e-9) return;
  while (f.kind == Kind::Hang) std::this_thread::sleep_for(std::chrono::seconds(1));
  std::ostringstream os;
  os << "diverged at t = " << f.t_s << " s (fault injected by the test hook)";
  throw hbt::ModelDivergence(model, "state", os.str());
}

/// After the step: advances the model time; true if the output is to be NaN.
bool nanDue(double dt_s) {
  Fault& f = fault();
  const bool due = f.kind == Kind::NaN && f.t_s >= f.at_s - 1e-9;
  f.t_s += dt_s;
  return due;
}
}  // namespace

#define HBT_CAT2(a, b) a##b
#define HBT_CAT(a, b) HBT_CAT2(a, b)
#define HBT_REAL HBT_CAT(__real_, HBT_FAULT_SYMBOL)
#define HBT_WRAP HBT_CAT(__wrap_, HBT_FAULT_SYMBOL)
#define HBT_STR2(a) #a
#define HBT_STR(a) HBT_STR2(a)

// One participant per executable: its model, the model's inputs and step's return type, and the
// output made NaN (a field its participant publishes).
#if defined(HBT_FAULT_PARTICIPANT_battery)
#include "battery/battery_model.hpp"
#define HBT_MODEL hbt::battery::BatteryModel
#define HBT_INPUTS hbt::battery::BatteryInputs
#define HBT_RETURN void
#define HBT_RETURNS_VOID 1
#define HBT_FAULT_FIELD(m) const_cast<hbt::battery::BatteryOutputs&>(m->outputs()).soc
#elif defined(HBT_FAULT_PARTICIPANT_aftertreatment)
#include "aftertreatment/aftertreatment.hpp"
#define HBT_MODEL hbt::aftertreatment::Aftertreatment
#define HBT_INPUTS hbt::aftertreatment::AtsInputs
#define HBT_RETURN void
#define HBT_RETURNS_VOID 1
#define HBT_FAULT_FIELD(m) const_cast<hbt::aftertreatment::AtsOutputs&>(m->outputs()).outlet_T_K
#elif defined(HBT_FAULT_PARTICIPANT_cooling)
#include "cooling/cooling_model.hpp"
#define HBT_MODEL hbt::cooling::CoolingModel
#define HBT_INPUTS hbt::cooling::CoolingInputs
#define HBT_RETURN void
#define HBT_RETURNS_VOID 1
#define HBT_FAULT_FIELD(m) const_cast<hbt::cooling::CoolingOutputs&>(m->outputs()).coolant_ht_T_K
#elif defined(HBT_FAULT_PARTICIPANT_hvac)
#include "hvac/hvac_model.hpp"
#define HBT_MODEL hbt::hvac::HvacModel
#define HBT_INPUTS hbt::hvac::HvacInputs
#define HBT_RETURN void
#define HBT_RETURNS_VOID 1
#define HBT_FAULT_FIELD(m) const_cast<hbt::hvac::HvacOutputs&>(m->outputs()).cabin_T_K
#elif defined(HBT_FAULT_PARTICIPANT_emachine)
#include "emachine/emachine_model.hpp"
#define HBT_MODEL hbt::emachine::EMachineModel
#define HBT_INPUTS hbt::emachine::EMachineInputs
#define HBT_RETURN void
#define HBT_RETURNS_VOID 1
#define HBT_FAULT_FIELD(m) const_cast<hbt::emachine::EMachineOutputs&>(m->outputs()).torque_Nm
#elif defined(HBT_FAULT_PARTICIPANT_ems)
#include "ems/ems_model.hpp"
#define HBT_MODEL hbt::ems::EmsModel
#define HBT_INPUTS hbt::ems::EmsInputs
#define HBT_RETURN const hbt::ems::EmsDecision&
#define HBT_FAULT_FIELD(m) const_cast<hbt::ems::EmsDecision&>(m->decision()).engine_torque_request_Nm
#elif defined(HBT_FAULT_PARTICIPANT_vehicle)
#include "vehicle/vehicle_model.hpp"
#define HBT_MODEL hbt::vehicle::VehicleModel
#define HBT_INPUTS hbt::vehicle::VehicleInputs
#define HBT_RETURN const hbt::vehicle::VehicleOutputs&
#define HBT_FAULT_FIELD(m) const_cast<hbt::vehicle::VehicleOutputs&>(m->outputs()).engine_speed_rad_s
#elif defined(HBT_FAULT_PARTICIPANT_engine)  // the map engine, behind the engine interface
#include "engine_map/map_engine.hpp"
#define HBT_MODEL hbt::engine_map::MapEngine
#define HBT_INPUTS hbt::engine_map::MapEngineInputs
#define HBT_RETURN const hbt::engine_map::MapEngineOutputs&
#define HBT_FAULT_FIELD(m) const_cast<hbt::engine_map::MapEngineOutputs&>(m->outputs()).fuel_mass_flow_kg_s
#else
#error "define HBT_FAULT_PARTICIPANT_<name> (test/faults/CMakeLists.txt)"
#endif

// The member function `R Model::step(double, const Inputs&)` called as a function of (this, dt,
// in): the same registers in the x86-64 System V ABI.
extern "C" HBT_RETURN HBT_REAL(HBT_MODEL* self, double dt_s, const HBT_INPUTS& in);

extern "C" HBT_RETURN HBT_WRAP(HBT_MODEL* self, double dt_s, const HBT_INPUTS& in) {
  beforeStep(HBT_STR(HBT_MODEL) "::step");
#ifdef HBT_RETURNS_VOID
  HBT_REAL(self, dt_s, in);
  if (nanDue(dt_s)) HBT_FAULT_FIELD(self) = std::numeric_limits<double>::quiet_NaN();
#else
  HBT_RETURN r = HBT_REAL(self, dt_s, in);
  if (nanDue(dt_s)) HBT_FAULT_FIELD(self) = std::numeric_limits<double>::quiet_NaN();
  return r;
#endif
}
