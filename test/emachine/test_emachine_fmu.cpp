// The exported e-machine FMU (<build>/fmus/emachine.fmu, src/emachine/fmu) loaded with the
// ROS-free importer src/fmi against the model library it is built from, driven with the same
// inputs (0.01 s steps, cold machine at 0 degC, 40 s of motoring, generating beyond the envelope
// and a speed sweep):
// - every output (every field of EMachineState, by value reference) at every step bit-identical to
//   EMachineModel stepped directly, with the cooling inputs fed, and without them (no cooling
//   participant: the node takes the ambient air for coolant and engine, the FMU its inputs' start
//   at the ambient);
// - emachine.warning.emachine_derating against the participant's rule written out here
//   (EMachineWarnings::derating of the live/peak torque limit held without a break for
//   diagnostics/duration_s of config/emachine.yaml), step by step: the generating peak with hot
//   coolant heats the winding into the derating range (raised), then no torque lets it cool below
//   the derating start (cleared);
// - an FMU whose resources lack emachine.yaml or the .vemp refuses fmi2Instantiate, its log naming
//   the missing file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "emachine/emachine_io.hpp"
#include "emachine/emachine_model.hpp"
#include "emachine/emachine_warnings.hpp"
#include "emachine_fmu_variables.hpp"  // generated: the FMU's variables by value reference
#include "exported_fmu_test_util.hpp"
#include "fmi/cs_instance.hpp"

namespace hbt::emachine {
namespace {

using fmi::VarType;

EMachineModel nativeModel() {  // the library with config/emachine.yaml as the FMU reads it
  return EMachineModel(fmi::exported::readResourceParams<EMachineParams>("config/emachine.yaml"), "config/emachine.yaml");
}

struct Inputs {  // one step's messages, by the fields emachine_io.hpp reads
  struct { double em_torque_request_nm, engine_speed_rad_s; } cmd;
  struct { double terminal_voltage_v; } battery;
  struct { double coolant_lt_temperature_k, metal_temperature_k; } cooling;
};
Inputs drive(int k) {
  const double t = 0.01 * k;
  Inputs in{};
  // 150 Nm assist, then -600 Nm (beyond the generating envelope), then a part-load ripple
  in.cmd.em_torque_request_nm = t < 15.0 ? 150.0 : t < 30.0 ? -600.0 : 40.0 * std::sin(t);
  in.cmd.engine_speed_rad_s = 60.0 + 8.0 * t;  // 570 .. 3600 rpm at the crank
  in.battery.terminal_voltage_v = 48.0 - 3.0 * std::sin(0.3 * t);
  in.cooling.coolant_lt_temperature_k = 275.0 + 0.5 * t;
  in.cooling.metal_temperature_k = 280.0 + 1.0 * t;
  return in;
}

class NativeVariables : public fmi::exported::generated::VariablesModel {
 public:
  void write(const EMachineOutputs& o) { writeEMachineState(o, v_.emachine_state); }
  void initialize() override {}
  void doStep(double) override {}
};

// The FMU's inputs, resolved by name once; set() writes one step's Inputs (the cooling inputs
// only if with_cooling: otherwise the FMU runs at its ambient).
struct FmuInputs {
  fmi::VariableRef T, w, V, Tc, Te;
  explicit FmuInputs(const fmi::CsInstance& f)
      : T(f.settable("ems.command.em_torque_request_nm", VarType::kReal)),
        w(f.settable("ems.command.engine_speed_rad_s", VarType::kReal)),
        V(f.settable("battery.state.terminal_voltage_v", VarType::kReal)),
        Tc(f.settable("cooling.state.coolant_lt_temperature_k", VarType::kReal)),
        Te(f.settable("cooling.state.metal_temperature_k", VarType::kReal)) {}
  void set(fmi::CsInstance& f, const Inputs& in, bool with_cooling) const {
    f.setReal(T, in.cmd.em_torque_request_nm);
    f.setReal(w, in.cmd.engine_speed_rad_s);
    f.setReal(V, in.battery.terminal_voltage_v);
    if (!with_cooling) return;
    f.setReal(Tc, in.cooling.coolant_lt_temperature_k);
    f.setReal(Te, in.cooling.metal_temperature_k);
  }
};

void runAgainstLibrary(bool with_cooling) {
  auto loaded = fmi::testing::loadExported("emachine", with_cooling ? "cooling" : "ambient");
  std::vector<std::string> log;
  fmi::CsInstance f(loaded, "emachine", [&](const std::string&, fmi2Status, const std::string&, const std::string& m) {
    log.push_back(m);
  });
  const double ambient_c = 0.0, ambient_K = units::celsiusToK(ambient_c);
  fmi::testing::initializeAtAmbient(f, ambient_c);
  EMachineModel native = nativeModel();
  native.reset(ambient_K);
  const std::vector<fmi::VariableRef> outputs = fmi::testing::outputRefs(f, *loaded, VarType::kReal);  // by name
  const FmuInputs inputs(f);
  const auto torque = f.gettable("emachine.state.torque_nm", VarType::kReal);
  double min_torque_Nm = 0.0;
  for (int k = 0; k < 4000; ++k) {
    const Inputs in = drive(k);
    inputs.set(f, in, with_cooling);
    f.doStep(0.01);
    native.step(0.01, emachineInputs(in.cmd, in.battery, with_cooling ? &in.cooling : nullptr, ambient_K));
    NativeVariables nv;
    nv.write(native.outputs());
    for (const auto& out : outputs)
      ASSERT_EQ(f.getReal(out), *nv.real(out.variable->value_reference)) << out.variable->name << " step " << k;
    min_torque_Nm = std::min(min_torque_Nm, native.outputs().torque_Nm);
  }
  EXPECT_EQ(outputs.size(), 44u);  // EMachineState's fields (msg/EMachineState.msg), the header excepted
  EXPECT_EQ(loaded->modelDescription().variable("emachine.warning.emachine_derating").type, VarType::kBoolean);
  EXPECT_GT(min_torque_Nm, -600.0) << "the generating request should be clamped by the envelope";
  EXPECT_EQ(f.getReal(torque), native.outputs().torque_Nm);
  EXPECT_TRUE(log.empty());
}

TEST(EMachineFmu, EveryOutputBitIdenticalToTheLibraryWithCoolingInputs) { runAgainstLibrary(true); }
TEST(EMachineFmu, EveryOutputBitIdenticalToTheLibraryWithoutCoolingAtAmbient) { runAgainstLibrary(false); }

// At t [s]: a generating request beyond the envelope at 700 rpm crank (1400 rpm EM: the generating
// peak, 30 kW, is twice the continuous power, so the peak heats the winding past the 140 degC
// derating start) with the coolant and engine at 95 degC until kHeat_s, then no torque; 48 V; the
// machine starts at 60 degC (the hottest ambient the scenario accepts).
constexpr double kHeat_s = 150.0, kEnd_s = 300.0;
Inputs heatThenCool(double t) {
  Inputs in{};
  in.cmd.em_torque_request_nm = t < kHeat_s ? -1000.0 : 0.0;  // beyond the peak: the limit applies
  in.cmd.engine_speed_rad_s = units::rpmToRadps(700.0);
  in.battery.terminal_voltage_v = 48.0;
  in.cooling.coolant_lt_temperature_k = in.cooling.metal_temperature_k = units::celsiusToK(95.0);
  return in;
}

TEST(EMachineFmu, DeratingWarningFollowsTheParticipantsRuleStepByStep) {
  auto loaded = fmi::testing::loadExported("emachine", "warning");
  fmi::CsInstance f(loaded, "emachine", [](const std::string&, fmi2Status, const std::string&, const std::string&) {});
  const double ambient_c = 60.0, ambient_K = units::celsiusToK(ambient_c);
  fmi::testing::initializeAtAmbient(f, ambient_c, kEnd_s);
  const auto warning = f.gettable("emachine.warning.emachine_derating", VarType::kBoolean);
  const FmuInputs inputs(f);
  const auto thresholds = fmi::exported::readResourceWarnings<EMachineWarnings>("config/emachine.yaml");
  EMachineModel native = nativeModel();
  native.reset(ambient_K);
  fmi::testing::WarningOracle rule{thresholds.duration_s};
  const int steps = static_cast<int>(kEnd_s / 0.01);
  for (int k = 0; k <= steps; ++k) {
    const double t = 0.01 * k;
    if (k > 0) {
      const Inputs in = heatThenCool(0.01 * (k - 1));
      inputs.set(f, in, true);
      f.doStep(0.01);
      native.step(0.01, emachineInputs(in.cmd, in.battery, &in.cooling, ambient_K));
    }
    const bool expected = rule.update(t, native.outputs().limits.derating_factor < thresholds.derating_factor_below);
    ASSERT_EQ(f.getBoolean(warning), expected) << "t = " << t << " s";
  }
  std::printf("emachine_derating raised %d times, first %.2f s, last %.2f s\n", rule.raises, rule.first_raise_s, rule.last_raised_s);
  EXPECT_EQ(rule.raises, 1);
  EXPECT_GT(rule.first_raise_s, 0.0) << "the peak torque should heat the machine into derating";
  EXPECT_LT(rule.first_raise_s, kHeat_s);
  EXPECT_GT(rule.last_raised_s, kHeat_s) << "the hot winding derates past the end of the torque";
  EXPECT_LT(rule.last_raised_s, kEnd_s - 1.0) << "cleared as the winding cools";
  EXPECT_FALSE(f.getBoolean(warning));
}

TEST(EMachineFmu, MissingYamlRefusesInstantiationNamingTheFile) { fmi::testing::expectInstantiationRefusedWithout("emachine", "emachine.yaml"); }
TEST(EMachineFmu, MissingVempRefusesInstantiationNamingTheFile) { fmi::testing::expectInstantiationRefusedWithout("emachine", ".vemp"); }

}  // namespace
}  // namespace hbt::emachine
