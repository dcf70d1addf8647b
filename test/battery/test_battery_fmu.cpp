// The exported battery FMU (<build>/fmus/battery.fmu, src/battery/fmu) loaded with the ROS-free
// importer src/fmi against the model library it is built from, driven with the same inputs:
// - every output (all 40 fields of BatteryState, by value reference), at every step of a 30 s drive cycle of discharge, regeneration and current
//   limits (0.01 s steps, cold pack at 0 degC), bit-identical to BatteryModel stepped directly
//   (the FMU adds no arithmetic: same parameters from the same YAML, same table, same steps);
// - battery.warning.battery_limited against the participant's rule written out here
//   (BatteryOutputs::request_limited held without a break for diagnostics/duration_s of
//   config/battery.yaml), step by step over the same cycle: raised by the assist beyond the cold
//   pack's discharge limit, held through the regeneration beyond the charge limit, cleared by the
//   cruise;
// - the units it declares convert to the message fields' SI units (Ah -> A s, degC -> K);
// - an FMU whose resources lack battery.yaml or the cell table refuses fmi2Instantiate, and its
//   log names the missing file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "battery/battery_io.hpp"
#include "battery/battery_model.hpp"
#include "battery/battery_warnings.hpp"
#include "battery_fmu_variables.hpp"  // generated: the FMU's variables by value reference
#include "common/units.hpp"
#include "exported_fmu_test_util.hpp"
#include "fmi/cs_instance.hpp"
#include "fmi/message_layout.hpp"

namespace hbt::battery {
namespace {

using fmi::VarType;

BatteryModel nativeModel() {  // the library with config/battery.yaml as the FMU reads it
  return BatteryModel(fmi::exported::readResourceParams<BatteryParams>("config/battery.yaml"), "config/battery.yaml");
}

struct Drive {  // inputs of step k: e-machine DC power [W], DC/DC load [W], vehicle speed [m/s]
  double emachine_W, dcdc_W, speed_m_s;
};
Drive drive(int k) {
  const double t = 0.01 * k;
  // 18 kW assist, 35 kW regeneration (beyond the charge limit: limited), 2 kW cruise
  const double P = t < 10.0 ? 18e3 : t < 20.0 ? -35e3 : 2e3 * std::sin(t);
  return {P, 1500.0 + 100.0 * std::cos(0.5 * t), 8.0 + 0.2 * t};
}

// The FMU's inputs, resolved by name once; set() writes one step's Drive.
struct DriveInputs {
  fmi::VariableRef P, dcdc, v;
  explicit DriveInputs(const fmi::CsInstance& f)
      : P(f.settable("emachine.state.electrical_power_w", VarType::kReal)),
        dcdc(f.settable("vehicle.state.dcdc_power_w", VarType::kReal)),
        v(f.settable("vehicle.state.speed_m_s", VarType::kReal)) {}
  void set(fmi::CsInstance& f, const Drive& d) const {
    f.setReal(P, d.emachine_W);
    f.setReal(dcdc, d.dcdc_W);
    f.setReal(v, d.speed_m_s);
  }
};

// The library's outputs in the FMU's variables (BatteryState's fields by value reference)
class NativeVariables : public fmi::exported::generated::VariablesModel {
 public:
  void write(const BatteryOutputs& o, double dcdc_W) { writeBatteryState(o, dcdc_W, v_.battery_state); }
  void initialize() override {}
  void doStep(double) override {}
};

struct Fmu {
  std::vector<std::string> log;
  fmi::CsInstance inst;
  explicit Fmu(std::shared_ptr<const fmi::LoadedFmu> f)
      : inst(f, "battery", [this](const std::string&, fmi2Status, const std::string&, const std::string& m) {
          log.push_back(m);
        }) {}
};

TEST(BatteryFmu, EveryOutputBitIdenticalToTheLibraryOverADriveCycle) {
  auto loaded = fmi::testing::loadExported("battery", "cycle");
  Fmu fmu(loaded);
  fmi::CsInstance& f = fmu.inst;
  const double ambient_c = 0.0;
  fmi::testing::initializeAtAmbient(f, ambient_c);
  BatteryModel native = nativeModel();
  const double air_T_K = units::celsiusToK(ambient_c);
  native.reset(air_T_K);
  const DriveInputs inputs(f);
  const auto soc = f.gettable("battery.state.soc", VarType::kReal);
  const auto volt = f.gettable("battery.state.terminal_voltage_v", VarType::kReal);
  const auto cell_T = f.gettable("battery.state.cell_temperature_k", VarType::kReal);
  const auto ah = f.gettable("battery.state.charge_throughput_ah", VarType::kReal);
  const auto limited = f.gettable("battery.state.request_limited", VarType::kBoolean);
  const auto request = f.gettable("battery.state.request_w", VarType::kReal);
  const auto dcdc_out = f.gettable("battery.state.dcdc_power_w", VarType::kReal);
  const auto residual = f.gettable("battery.state.energy_residual_j", VarType::kReal);
  EXPECT_EQ(f.getReal(soc), native.outputs().soc);  // initial state, before any step
  const std::vector<fmi::VariableRef> outputs = fmi::testing::outputRefs(f, *loaded);  // by name
  ASSERT_EQ(outputs.size(), 41u);  // BatteryState's 40 fields and the warning (its own test)
  int limited_steps = 0;
  for (int k = 0; k < 3000; ++k) {
    const Drive d = drive(k);
    inputs.set(f, d);
    f.doStep(0.01);
    BatteryInputs in;
    in.power_request_W = d.emachine_W + d.dcdc_W;
    in.air_T_K = air_T_K;
    in.air_speed_m_s = d.speed_m_s;
    native.step(0.01, in);
    const BatteryOutputs& o = native.outputs();
    ASSERT_EQ(f.getReal(soc), o.soc) << "step " << k;
    ASSERT_EQ(f.getReal(volt), o.terminal_voltage_V) << "step " << k;
    ASSERT_EQ(f.getReal(cell_T), o.cell_T_K) << "step " << k;
    ASSERT_EQ(f.getReal(ah), o.charge_throughput_Ah) << "step " << k;
    ASSERT_EQ(f.getReal(request), o.request_W) << "step " << k;
    ASSERT_EQ(f.getReal(dcdc_out), d.dcdc_W) << "step " << k;
    ASSERT_EQ(f.getReal(residual), o.energy_residual_J) << "step " << k;
    ASSERT_EQ(f.getBoolean(limited), o.request_limited) << "step " << k;
    limited_steps += o.request_limited ? 1 : 0;
    NativeVariables nv;
    nv.write(o, d.dcdc_W);
    for (const auto& out : outputs) {
      if (out.variable->name == "battery.warning.battery_limited") continue;
      const unsigned vr = out.variable->value_reference;
      if (out.variable->type == VarType::kBoolean)
        ASSERT_EQ(f.getBoolean(out), *nv.boolean(vr)) << out.variable->name << " step " << k;
      else
        ASSERT_EQ(f.getReal(out), *nv.real(vr)) << out.variable->name << " step " << k;
    }
  }
  EXPECT_GT(limited_steps, 0) << "the cycle should reach the charge limit";
  EXPECT_LT(native.outputs().soc, 1.0);
  EXPECT_NEAR(f.time(), 30.0, 1e-9);
  EXPECT_TRUE(fmu.log.empty());
}

TEST(BatteryFmu, LimitedWarningFollowsTheParticipantsRuleStepByStep) {
  auto loaded = fmi::testing::loadExported("battery", "warning");
  Fmu fmu(loaded);
  fmi::CsInstance& f = fmu.inst;
  fmi::testing::initializeAtAmbient(f, 0.0);
  const auto warning = f.gettable("battery.warning.battery_limited", VarType::kBoolean);
  const DriveInputs inputs(f);
  const auto thresholds = fmi::exported::readResourceWarnings<BatteryWarnings>("config/battery.yaml");
  BatteryModel native = nativeModel();
  native.reset(units::celsiusToK(0.0));
  fmi::testing::WarningOracle rule{thresholds.duration_s};
  for (int k = 0; k <= 3000; ++k) {
    const double t = 0.01 * k;
    if (k > 0) {
      const Drive d = drive(k - 1);
      inputs.set(f, d);
      f.doStep(0.01);
      native.step(0.01, BatteryInputs{d.emachine_W + d.dcdc_W, units::celsiusToK(0.0), d.speed_m_s});
    }
    const bool expected = rule.update(t, native.outputs().request_limited);
    ASSERT_EQ(f.getBoolean(warning), expected) << "t = " << t << " s";
  }
  std::printf("battery_limited raised %d times, first %.2f s, last %.2f s\n", rule.raises, rule.first_raise_s, rule.last_raised_s);
  EXPECT_EQ(rule.raises, 1);
  EXPECT_LT(rule.first_raise_s, 1.0) << "raised by the assist beyond the cold pack's discharge limit";
  EXPECT_GE(rule.last_raised_s, 19.9) << "held through the regeneration beyond the charge limit";
  EXPECT_LT(rule.last_raised_s, 20.5) << "cleared by the cruise from 20 s";
  EXPECT_FALSE(f.getBoolean(warning));
}

TEST(BatteryFmu, EveryOutputOfTheMessageIsAnOutputWithTheFieldsUnit) {
  auto loaded = fmi::testing::loadExported("battery", "units");
  const fmi::ModelDescription& md = loaded->modelDescription();
  int outputs = 0;
  for (const auto& var : md.variables()) outputs += var.causality == fmi::Causality::kOutput ? 1 : 0;
  EXPECT_EQ(outputs, 40 + 1);  // BatteryState's fields (msg/BatteryState.msg, the header excepted), the warning
  const fmi::ScalarVariable& w = md.variable("battery.warning.battery_limited");
  EXPECT_EQ(w.type, VarType::kBoolean);
  EXPECT_EQ(w.variability, fmi::Variability::kDiscrete);
  const fmi::SiUnit ampere_second = fmi::unitOfName("charge_throughput_ah").si;  // A.s
  const fmi::UnitConversion ah = md.unitToSi(md.variable("battery.state.charge_throughput_ah"), ampere_second);
  EXPECT_DOUBLE_EQ(ah.toSi(1.0), 3600.0);
  const fmi::UnitConversion c = md.unitToSi(md.variable("scenario.ambient_temperature_c"), fmi::si::kelvin());
  EXPECT_DOUBLE_EQ(c.toSi(0.0), 273.15);
  EXPECT_EQ(md.defaultExperiment().step_size_s.value_or(0.0), 0.01);  // cosim/macro_step_s
}

TEST(BatteryFmu, MissingYamlRefusesInstantiationNamingTheFile) { fmi::testing::expectInstantiationRefusedWithout("battery", "battery.yaml"); }
TEST(BatteryFmu, MissingCellTableRefusesInstantiationNamingTheFile) {
  fmi::testing::expectInstantiationRefusedWithout("battery", "ecm_1RC_SOC_T_lookup.csv");
}

}  // namespace
}  // namespace hbt::battery
