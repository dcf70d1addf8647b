// Helpers of the tests of the engine FMUs (test_engine_map_fmu, test_engine_1d_fmu; src/engine/
// engine_fmu.hpp): a drive of the engine participant's inputs, set into the FMU by variable name
// and turned into the model's EngineInputs by hand (the policies of engine_model.hpp, written
// here independently of engine_io.hpp), and the check that every output variable of the FMU
// equals, bit for bit, the native model's outputs written into the FMU's own variable layout.
// Include after the model's generated <model>_fmu_variables.hpp.
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "engine_interface/engine_io.hpp"
#include "engine_interface/engine_model.hpp"
#include "exported_fmu_test_util.hpp"
#include "fmi/cs_instance.hpp"

namespace hbt::engine::testing {

/// One step's inputs: the command's fields and the loop participants' (0 = not fed).
struct EngineDrive {
  double speed_rad_s, torque_request_nm, ambient_temperature_k, ambient_pressure_pa;
  bool engine_on;
  double coolant_ht_temperature_k, oil_temperature_k, back_pressure_pa;
};

/// At t [s] of a drive of period_s, phase u = t / period_s: speed 700 -> 1840 rpm and back;
/// torque request part load, beyond full load (PT1 build-up), motoring request, engine off, a
/// ripple; the command without an ambient temperature (u in [0.7, 0.75): the scenario ambient) or
/// pressure (u in [0.8, 0.85): the standard atmosphere); with `loops` coolant and oil warming from
/// cold and a back-pressure (else 0: not fed).
inline EngineDrive engineDrive(double t, double period_s, bool loops) {
  const double u = t / period_s;  // the drive's phase 0..1 over the test's duration
  EngineDrive d{};
  d.speed_rad_s = 73.3038 + 60.0 * (1.0 - std::cos(2.0 * M_PI * u));
  d.torque_request_nm = u < 0.15 ? 200.0 : u < 0.35 ? 1500.0 : u < 0.5 ? -300.0 : u < 0.65 ? 0.0 : 600.0 + 300.0 * std::sin(7.0 * t);
  d.engine_on = !(u >= 0.5 && u < 0.65);
  d.ambient_temperature_k = u >= 0.7 && u < 0.75 ? 0.0 : 278.15;
  d.ambient_pressure_pa = u >= 0.8 && u < 0.85 ? 0.0 : 96000.0;
  if (loops) {
    d.coolant_ht_temperature_k = 275.0 + 60.0 * u;
    d.oil_temperature_k = 274.0 + 50.0 * u;
    d.back_pressure_pa = 104000.0 + 8000.0 * u;
  }
  return d;
}

/// The model's inputs, by hand: a command ambient <= 0 is the scenario's; the rest one to one.
inline EngineInputs nativeInputs(const EngineDrive& d, double scenario_ambient_K) {
  EngineInputs in;
  in.speed_rad_s = d.speed_rad_s;
  in.torque_request_Nm = d.torque_request_nm;
  in.ambient_T_K = d.ambient_temperature_k > 0.0 ? d.ambient_temperature_k : scenario_ambient_K;
  in.ambient_p_Pa = d.ambient_pressure_pa;
  in.fuel_enabled = d.engine_on;
  in.coolant_T_K = d.coolant_ht_temperature_k;
  in.oil_T_K = d.oil_temperature_k;
  in.back_pressure_Pa = d.back_pressure_pa;
  return in;
}

/// The FMU's inputs by name: the command under the alternative producers ems|vehicle.
class EngineFmuInputs {
 public:
  explicit EngineFmuInputs(const fmi::CsInstance& f)
      : w_(real(f, "ems|vehicle.engine_command.engine_speed_rad_s")),
        T_(real(f, "ems|vehicle.engine_command.torque_request_nm")),
        amb_T_(real(f, "ems|vehicle.engine_command.ambient_temperature_k")),
        amb_p_(real(f, "ems|vehicle.engine_command.ambient_pressure_pa")),
        on_(f.settable("ems|vehicle.engine_command.engine_on", fmi::VarType::kBoolean)),
        coolant_(real(f, "cooling.state.coolant_ht_temperature_k")),
        oil_(real(f, "cooling.state.oil_temperature_k")),
        back_p_(real(f, "aftertreatment.state.back_pressure_pa")) {}
  /// The command always; the loop inputs only when `loops` (else they keep their start, 0).
  void set(fmi::CsInstance& f, const EngineDrive& d, bool loops) const {
    f.setReal(w_, d.speed_rad_s);
    f.setReal(T_, d.torque_request_nm);
    f.setReal(amb_T_, d.ambient_temperature_k);
    f.setReal(amb_p_, d.ambient_pressure_pa);
    f.setBoolean(on_, d.engine_on);
    if (!loops) return;
    f.setReal(coolant_, d.coolant_ht_temperature_k);
    f.setReal(oil_, d.oil_temperature_k);
    f.setReal(back_p_, d.back_pressure_pa);
  }

 private:
  static fmi::VariableRef real(const fmi::CsInstance& f, const std::string& n) { return f.settable(n, fmi::VarType::kReal); }
  fmi::VariableRef w_, T_, amb_T_, amb_p_, on_, coolant_, oil_, back_p_;
};

/// The native model's outputs in the FMU's variables (engine.state/exhaust/heat by value reference).
class NativeVariables : public fmi::exported::generated::VariablesModel {
 public:
  void write(const EngineOutputs& o) {
    writeEngineState(o, v_.engine_state);
    writeExhaustState(o, v_.engine_exhaust);
    writeEngineHeat(o, v_.engine_heat);
  }
  void initialize() override {}
  void doStep(double) override {}
};

/// Every output of the FMU (all Real) equals the native model's; "" or the first difference.
inline std::string firstDifference(fmi::CsInstance& f, const std::vector<fmi::VariableRef>& outputs,
                                   const EngineOutputs& native) {
  NativeVariables nv;
  nv.write(native);
  for (const auto& out : outputs) {
    const double a = f.getReal(out), b = *nv.real(out.variable->value_reference);
    if (!(a == b) && !(std::isnan(a) && std::isnan(b)))
    {
      std::ostringstream m;
      m.precision(17);
      m << out.variable->name << ": FMU " << a << " vs native " << b;
      return m.str();
    }
  }
  return "";
}

}  // namespace hbt::engine::testing
