// The exported e-machine FMU (<build>/fmus/emachine.fmu, src/emachine/fmu) loaded with the
// ROS-free importer src/fmi against the model library it is built from, driven with the same
// inputs (0.01 s steps, cold machine at 0 degC, 40 s of motoring, generating beyond the envelope
// and a speed sweep):
// - every output (every field of EMachineState, by value reference) at every step bit-identical to
//   EMachineModel stepped directly, with the cooling inputs fed, and without them (no cooling
//   participant: the node takes the ambient air for coolant and engine, the FMU its inputs' start
//   at the ambient);
// - an FMU whose resources lack emachine.yaml or the .vemp refuses fmi2Instantiate, its log naming
//   the missing file.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "emachine/emachine_io.hpp"
#include "emachine/emachine_model.hpp"
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
  const std::vector<fmi::VariableRef> outputs = fmi::testing::outputRefs(f, *loaded);  // by name
  const auto T = f.settable("ems.command.em_torque_request_nm", VarType::kReal);
  const auto w = f.settable("ems.command.engine_speed_rad_s", VarType::kReal);
  const auto V = f.settable("battery.state.terminal_voltage_v", VarType::kReal);
  const auto Tc = f.settable("cooling.state.coolant_lt_temperature_k", VarType::kReal);
  const auto Te = f.settable("cooling.state.metal_temperature_k", VarType::kReal);
  const auto torque = f.gettable("emachine.state.torque_nm", VarType::kReal);
  double min_torque_Nm = 0.0;
  for (int k = 0; k < 4000; ++k) {
    const Inputs in = drive(k);
    f.setReal(T, in.cmd.em_torque_request_nm);
    f.setReal(w, in.cmd.engine_speed_rad_s);
    f.setReal(V, in.battery.terminal_voltage_v);
    if (with_cooling) {
      f.setReal(Tc, in.cooling.coolant_lt_temperature_k);
      f.setReal(Te, in.cooling.metal_temperature_k);
    }
    f.doStep(0.01);
    native.step(0.01, emachineInputs(in.cmd, in.battery, with_cooling ? &in.cooling : nullptr, ambient_K));
    NativeVariables nv;
    nv.write(native.outputs());
    for (const auto& out : outputs)
      ASSERT_EQ(f.getReal(out), *nv.real(out.variable->value_reference)) << out.variable->name << " step " << k;
    min_torque_Nm = std::min(min_torque_Nm, native.outputs().torque_Nm);
  }
  EXPECT_EQ(outputs.size(), 44u);  // EMachineState's fields (msg/EMachineState.msg), the header excepted
  EXPECT_GT(min_torque_Nm, -600.0) << "the generating request should be clamped by the envelope";
  EXPECT_EQ(f.getReal(torque), native.outputs().torque_Nm);
  EXPECT_TRUE(log.empty());
}

TEST(EMachineFmu, EveryOutputBitIdenticalToTheLibraryWithCoolingInputs) { runAgainstLibrary(true); }
TEST(EMachineFmu, EveryOutputBitIdenticalToTheLibraryWithoutCoolingAtAmbient) { runAgainstLibrary(false); }

TEST(EMachineFmu, MissingYamlRefusesInstantiationNamingTheFile) { fmi::testing::expectInstantiationRefusedWithout("emachine", "emachine.yaml"); }
TEST(EMachineFmu, MissingVempRefusesInstantiationNamingTheFile) { fmi::testing::expectInstantiationRefusedWithout("emachine", ".vemp"); }

}  // namespace
}  // namespace hbt::emachine
