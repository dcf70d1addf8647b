// The exported map-engine FMU (<build>/fmus/engine_map.fmu, src/engine_map/fmu) loaded with the
// ROS-free importer src/fmi against the model library it is built from, driven with the same
// inputs (test/engine/engine_fmu_test_util.hpp: 40 s at the engine's 0.01 s step, ambient 0 degC):
// - every output (every field of EngineState, ExhaustState, EngineHeat, by value reference) at
//   every step bit-identical to MapEngineModel stepped directly, with the cooling and
//   aftertreatment inputs fed, and without them (their start 0 = no such participant: warm map,
//   the map's own back-pressure, as the node does);
// - the description: the command under the alternative producers ems|vehicle, the loop inputs,
//   42 outputs, stepSize 0.01 s (the engine steps at the base step);
// - engine.warning.boost_limited against the participant's rule written out here (the condition
//   EngineModel::boostLimited(margin_nm) held without a break for duration_s, both from the
//   diagnostics: section of config/engine_map.yaml), step by step, on a tip-in during a hard
//   acceleration at low speed: the full-load limit rises with speed faster than the PT1 build-up
//   follows it (raised), then constant speed and the request released (cleared);
// - an FMU whose resources lack engine_map.yaml or the full-load curve refuses fmi2Instantiate,
//   its log naming the missing file.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "engine/engine_warnings.hpp"
#include "engine_map/map_engine_model.hpp"
#include "engine_map_fmu_variables.hpp"  // generated: the FMU's variables by value reference
#include "../engine/engine_fmu_test_util.hpp"
#include "exported_fmu_test_util.hpp"
#include "fmi/cs_instance.hpp"

namespace hbt::engine_map {
namespace {

using engine::testing::EngineFmuInputs;
using engine::testing::engineDrive;

constexpr double kStep_s = 0.01, kDuration_s = 40.0;

MapEngineModel nativeModel() {  // the library with config/engine_map.yaml as the FMU reads it
  return MapEngineModel(fmi::exported::readResourceParams<MapEngineParams>("config/engine_map.yaml"), ".");
}

void runAgainstLibrary(bool loops) {
  auto loaded = fmi::testing::loadExported("engine_map", loops ? "loops" : "alone");
  std::vector<std::string> log;
  fmi::CsInstance f(loaded, "engine", [&](const std::string&, fmi2Status, const std::string&, const std::string& m) {
    log.push_back(m);
  });
  const double ambient_c = 0.0, ambient_K = units::celsiusToK(ambient_c);
  fmi::testing::initializeAtAmbient(f, ambient_c);
  MapEngineModel native = nativeModel();
  native.reset(ambient_K);
  const std::vector<fmi::VariableRef> outputs = fmi::testing::outputRefs(f, *loaded, fmi::VarType::kReal);
  ASSERT_EQ(outputs.size(), 42u);  // the messages' fields (the warning output: a Boolean)
  ASSERT_EQ(engine::testing::firstDifference(f, outputs, native.outputs()), "") << "initial state";
  const EngineFmuInputs in(f);
  const int steps = static_cast<int>(kDuration_s / kStep_s);
  int limited = 0, cut = 0;
  for (int k = 0; k < steps; ++k) {
    const auto d = engineDrive(k * kStep_s, kDuration_s, loops);
    in.set(f, d, loops);
    f.doStep(kStep_s);
    native.step(kStep_s, engine::testing::nativeInputs(d, ambient_K));
    ASSERT_EQ(engine::testing::firstDifference(f, outputs, native.outputs()), "") << "step " << k;
    limited += native.outputs().brake_torque_Nm < d.torque_request_nm - 50.0 && d.engine_on ? 1 : 0;
    cut += d.engine_on ? 0 : 1;
  }
  EXPECT_GT(limited, 100) << "the drive should reach the full-load and PT1 limits";
  EXPECT_GT(cut, 100) << "the drive should switch the engine off";
  EXPECT_GT(native.outputs().fuel_mass_kg, 0.0);
  EXPECT_EQ(native.outputs().coolant_T_K > 0.0, loops);  // echoed as used: 0 = none
  EXPECT_NEAR(f.time(), kDuration_s, 1e-9);
  EXPECT_TRUE(log.empty());
}

TEST(EngineMapFmu, EveryOutputBitIdenticalToTheLibraryWithTheLoopsFed) { runAgainstLibrary(true); }
TEST(EngineMapFmu, EveryOutputBitIdenticalToTheLibraryWithoutCoolingOrAftertreatment) { runAgainstLibrary(false); }

TEST(EngineMapFmu, DescriptionDeclaresTheParticipantsInputsOutputsAndStep) {
  auto loaded = fmi::testing::loadExported("engine_map", "description");
  const fmi::ModelDescription& md = loaded->modelDescription();
  int inputs = 0, outputs = 0;
  for (const auto& v : md.variables()) {
    inputs += v.causality == fmi::Causality::kInput ? 1 : 0;
    outputs += v.causality == fmi::Causality::kOutput ? 1 : 0;
  }
  EXPECT_EQ(inputs, 5 + 2 + 1);     // EngineCommand's 5 fields, coolant and oil, back-pressure
  EXPECT_EQ(outputs, 17 + 19 + 6 + 1);  // EngineState, ExhaustState, EngineHeat (headers excepted), the warning
  const fmi::ScalarVariable& w = md.variable("engine.warning.boost_limited");
  EXPECT_EQ(w.type, fmi::VarType::kBoolean);
  EXPECT_EQ(w.causality, fmi::Causality::kOutput);
  EXPECT_EQ(w.variability, fmi::Variability::kDiscrete);
  EXPECT_EQ(md.variable("ems|vehicle.engine_command.engine_on").type, fmi::VarType::kBoolean);
  EXPECT_EQ(md.variable("ems|vehicle.engine_command.torque_request_nm").unit, "N.m");
  EXPECT_EQ(md.variable("engine.heat.coolant_pump_angle_rad").unit, "rad");
  EXPECT_EQ(md.defaultExperiment().step_size_s.value_or(0.0), 0.01);
}

// At t [s]: idle 700 rpm, no request until 1 s; then 3000 Nm (far above any full load) while the
// speed ramps 700 -> 1250 rpm over 4 s (full load +~600 Nm: ~150 Nm/s against PT1 tau ~0.5 s);
// 1250 rpm held; the request released to 100 Nm at 8 s; 10 s in all.
engine::testing::EngineDrive tipInDrive(double t) {
  engine::testing::EngineDrive d{};
  const double ramp = std::clamp((t - 1.0) / 4.0, 0.0, 1.0);
  d.speed_rad_s = units::rpmToRadps(700.0 + 550.0 * ramp);
  d.torque_request_nm = t < 1.0 ? 0.0 : t < 8.0 ? 3000.0 : 100.0;
  d.engine_on = true;
  d.ambient_temperature_k = 278.15;
  d.ambient_pressure_pa = 101325.0;
  return d;
}

TEST(EngineMapFmu, BoostLimitedWarningFollowsTheParticipantsRuleStepByStep) {
  auto loaded = fmi::testing::loadExported("engine_map", "warning");
  fmi::CsInstance f(loaded, "engine", [](const std::string&, fmi2Status, const std::string&, const std::string&) {});
  fmi::testing::initializeAtAmbient(f, 5.0);
  const fmi::VariableRef warning = f.gettable("engine.warning.boost_limited", fmi::VarType::kBoolean);
  const auto thresholds = fmi::exported::readResourceWarnings<engine::EngineWarnings>("config/engine_map.yaml", "map");
  ASSERT_GT(thresholds.duration_s, 1.0);  // the rule below is not trivially met
  MapEngineModel native = nativeModel();
  native.reset(units::celsiusToK(5.0));
  const EngineFmuInputs in(f);
  fmi::testing::WarningOracle rule{thresholds.duration_s};
  const int steps = static_cast<int>(10.0 / kStep_s);
  for (int k = 0; k <= steps; ++k) {
    const double t = k * kStep_s;
    if (k > 0) {
      const auto d = tipInDrive((k - 1) * kStep_s);
      in.set(f, d, false);
      f.doStep(kStep_s);
      native.step(kStep_s, engine::testing::nativeInputs(d, units::celsiusToK(5.0)));
    }
    const bool expected = rule.update(t, native.boostLimited(thresholds.margin_nm));
    ASSERT_EQ(f.getBoolean(warning), expected) << "t = " << t << " s";
  }
  EXPECT_GT(rule.first_raise_s, 1.0 + thresholds.duration_s - 1e-9) << "raised after the tip-in at 1 s plus the persistence";
  EXPECT_GT(rule.raised_states, 10) << "the drive should hold the warning for a while";
  EXPECT_FALSE(f.getBoolean(warning)) << "cleared once the PT1 limit caught up and the request was released";
}

TEST(EngineMapFmu, MissingYamlRefusesInstantiationNamingTheFile) {
  fmi::testing::expectInstantiationRefusedWithout("engine_map", "engine_map.yaml");
}
TEST(EngineMapFmu, MissingFullLoadCurveRefusesInstantiationNamingTheFile) {
  fmi::testing::expectInstantiationRefusedWithout("engine_map", "FullLoad.vfld");
}

}  // namespace
}  // namespace hbt::engine_map
