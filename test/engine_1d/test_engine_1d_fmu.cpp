// The exported 1D-engine FMU (<build>/fmus/engine_1d.fmu, src/engine_1d/fmu) loaded with the
// ROS-free importer src/fmi against the model library it is built from, driven with the same
// inputs (test/engine/engine_fmu_test_util.hpp: 300 macro steps of 0.01 s, ambient 0 degC, the
// cooling and aftertreatment inputs fed):
// - every output (every field of EngineState, ExhaustState, EngineHeat, by value reference) at
//   every step bit-identical to Engine1DModel stepped directly (the same parameters from the same
//   four YAMLs, the same turbocharger maps and reference curves, read from resources/);
// - an FMU whose resources lack engine_1d.yaml, the cylinder file or a turbocharger map refuses
//   fmi2Instantiate, its log naming the missing file.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/units.hpp"
#include "engine_1d/engine_1d_model.hpp"
#include "engine_1d_fmu_variables.hpp"  // generated: the FMU's variables by value reference
#include "../engine/engine_fmu_test_util.hpp"
#include "exported_fmu_test_util.hpp"
#include "fmi/cs_instance.hpp"

namespace hbt::engine_1d {
namespace {

using engine::testing::EngineFmuInputs;
using engine::testing::engineDrive;

constexpr double kStep_s = 0.01, kDuration_s = 3.0;

TEST(Engine1DFmu, EveryOutputBitIdenticalToTheLibraryOverADrive) {
  auto loaded = fmi::testing::loadExported("engine_1d", "drive");
  std::vector<std::string> log;
  fmi::CsInstance f(loaded, "engine", [&](const std::string&, fmi2Status, const std::string&, const std::string& m) {
    log.push_back(m);
  });
  const double ambient_c = 0.0, ambient_K = units::celsiusToK(ambient_c);
  fmi::testing::initializeAtAmbient(f, ambient_c);
  // the library as the node's factory builds it (package root: the turbo maps under ../shared)
  Engine1DModel native(Engine1DParams::load(".", "config/engine_1d.yaml"), ".");
  native.reset(ambient_K);
  const std::vector<fmi::VariableRef> outputs = fmi::testing::outputRefs(f, *loaded, fmi::VarType::kReal);
  ASSERT_EQ(outputs.size(), 42u);  // the messages' fields (the warning output: a Boolean)
  ASSERT_EQ(engine::testing::firstDifference(f, outputs, native.outputs()), "") << "initial state";
  const EngineFmuInputs in(f);
  const int steps = static_cast<int>(kDuration_s / kStep_s + 0.5);
  for (int k = 0; k < steps; ++k) {
    const auto d = engineDrive(k * kStep_s, kDuration_s, true);
    in.set(f, d, true);
    f.doStep(kStep_s);
    native.step(kStep_s, engine::testing::nativeInputs(d, ambient_K));
    ASSERT_EQ(engine::testing::firstDifference(f, outputs, native.outputs()), "") << "step " << k;
  }
  EXPECT_GT(native.outputs().fuel_mass_kg, 0.0);
  EXPECT_GT(native.outputs().turbo_speed_rad_s, 0.0);  // the 1D engine's own turbocharger
  EXPECT_NEAR(f.time(), kDuration_s, 1e-9);
  EXPECT_TRUE(log.empty());
}

TEST(Engine1DFmu, MissingYamlRefusesInstantiationNamingTheFile) {
  fmi::testing::expectInstantiationRefusedWithout("engine_1d", "engine_1d.yaml");
}
TEST(Engine1DFmu, MissingCylinderFileRefusesInstantiationNamingTheFile) {
  fmi::testing::expectInstantiationRefusedWithout("engine_1d", "engine_1d_cylinder.yaml");
}
TEST(Engine1DFmu, MissingTurbineMapRefusesInstantiationNamingTheFile) {
  fmi::testing::expectInstantiationRefusedWithout("engine_1d", "turbine_map_SAE.csv");
}

}  // namespace
}  // namespace hbt::engine_1d
