// The twin's engine interface (engine_interface/engine_model.hpp) over both models: ONE start policy (both
// start at the idle speed of config/engine_map.yaml, torque 0, the standard atmosphere), ONE
// ambient-pressure policy (a step without one = 101325 Pa), the loop inputs echoed as used
// (<= 0 = none = 0), an exhaust temperature > 0 from the start; the factory (engine_factory.hpp):
// the model name check of the launch argument engine, each model built from its shipped YAML.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <vector>

#include "common/errors.hpp"
#include "common/params.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "engine/engine_factory.hpp"
#include "engine_1d/engine_1d_model.hpp"
#include "engine_map/map_engine_model.hpp"
#include "../common/input_errors.hpp"

using namespace hbt;

namespace {

std::string repoRoot() {
  const char* d = std::getenv("HBT_SOURCE_DIR");
  return d ? std::string(d) : std::string(".");
}

std::vector<std::unique_ptr<engine::EngineModel>> bothModels() {
  engine_map::MapEngineParams mp;
  ParamSet ps;
  mp.declare(ps);
  applyParams(ps, readYamlParams(repoRoot() + "/config/engine_map.yaml"));
  std::vector<std::unique_ptr<engine::EngineModel>> m;
  m.push_back(std::make_unique<engine_map::MapEngineModel>(mp, repoRoot()));
  m.push_back(std::make_unique<engine_1d::Engine1DModel>(engine_1d::Engine1DParams::load(repoRoot()), repoRoot()));
  return m;
}

}  // namespace

TEST(EngineModel, ModelNamesAreCheckedNamingTheKey) {
  EXPECT_NO_THROW(engine::checkEngineModelName("map", "engine", "model"));
  EXPECT_NO_THROW(engine::checkEngineModelName("1d", "engine", "model"));
  for (const char* bad : {"1D", "", "map ", "tvd"}) {
    SCOPED_TRACE(bad);
    const std::string msg = hbt::testing::expectInputError(
        [&] { engine::checkEngineModelName(bad, "/engine (private parameters)", "model"); },
        "/engine (private parameters)", "model");
    EXPECT_NE(msg.find("map | 1d"), std::string::npos) << msg;
    hbt::testing::expectInputError([&] { engine::makeEngineModel(bad, ParamSource{}, "x.yaml", repoRoot()); },
                                   "scenario (launch argument engine)", "engine_model");
  }
}

TEST(EngineFactory, BuildsEachModelFromItsShippedYamlAndRefusesAnEmptyOne) {
  const std::string map_file = repoRoot() + "/config/engine_map.yaml";
  const std::string file_1d = repoRoot() + "/config/engine_1d.yaml";
  const auto map = engine::makeEngineModel("map", readYamlParams(map_file), map_file, repoRoot());
  EXPECT_EQ(std::string(map->name()), "map");
  const auto e1d = engine::makeEngineModel("1d", readYamlParams(file_1d), file_1d, repoRoot(), "tvd");
  EXPECT_EQ(std::string(e1d->name()), "1d");
  EXPECT_EQ(map->idleSpeed(), e1d->idleSpeed());  // one key: engine_map.yaml
  hbt::testing::expectInputError([&] { engine::makeEngineModel("map", ParamSource{}, map_file, repoRoot()); },
                                 map_file, "");
  // a misspelt key of the map engine's YAML is named
  ParamSource bad = readYamlParams(map_file);
  bad.set("idle_sped_rad_s", 70.0);
  hbt::testing::expectInputError([&] { engine::makeEngineModel("map", bad, map_file, repoRoot()); }, map_file,
                                 "idle_sped_rad_s");
}

TEST(EngineModel, BothModelsFollowTheSameStartAmbientAndLoopPolicies) {
  auto models = bothModels();
  ASSERT_EQ(models.size(), 2u);
  EXPECT_EQ(models[0]->idleSpeed(), models[1]->idleSpeed());  // one key: engine_map.yaml
  EXPECT_NEAR(units::radpsToRpm(models[0]->idleSpeed()), 700.0, 1e-3);
  for (auto& m : models) {
    SCOPED_TRACE(m->name());
    m->reset(278.15);
    EXPECT_EQ(m->outputs().speed_rad_s, m->idleSpeed());
    EXPECT_EQ(m->outputs().brake_torque_Nm, 0.0);
    EXPECT_EQ(m->inputs().ambient_p_Pa, units::kStandardAtmosphere_Pa);
    EXPECT_EQ(m->inputs().ambient_T_K, 278.15);
    EXPECT_GT(m->outputs().exhaust_T_K, 0.0);
    EXPECT_EQ(m->outputs().max_torque_Nm, m->fullLoadTorque(m->idleSpeed()));
    EXPECT_EQ(m->outputs().min_torque_Nm, m->motoringTorque(m->idleSpeed()));
    engine::EngineInputs in;
    in.speed_rad_s = units::rpmToRadps(900.0);
    in.torque_request_Nm = 200.0;
    in.ambient_T_K = 278.15;
    in.ambient_p_Pa = -1.0;      // none: the standard atmosphere
    in.coolant_T_K = -5.0;       // none
    in.oil_T_K = -5.0;           // none
    in.back_pressure_Pa = -1.0;  // none
    for (int k = 0; k < 20; ++k) m->step(0.01, in);
    EXPECT_EQ(m->inputs().ambient_p_Pa, 101325.0);
    EXPECT_EQ(m->outputs().coolant_T_K, 0.0);
    EXPECT_EQ(m->outputs().oil_T_K, 0.0);
    EXPECT_EQ(m->outputs().back_pressure_Pa, 0.0);
    EXPECT_EQ(m->outputs().speed_rad_s, in.speed_rad_s);
    EXPECT_GT(m->outputs().exhaust_T_K, 278.15);  // fired: hotter than the air
    EXPECT_GT(m->outputs().fuel_mass_kg, 0.0);
    EXPECT_GT(m->outputs().brake_torque_Nm, 0.0);
    EXPECT_GT(m->outputs().max_torque_Nm, 500.0);
    EXPECT_LT(m->outputs().min_torque_Nm, 0.0);
  }
}

TEST(EngineModel, ExhaustTotalsIntegrateEachStepsOutputs) {
  // the totals a 0.1 s consumer differentiates (the aftertreatment) are the sums of each 10 ms
  // step's published values times the step, for both models, through a tip-in and a fuel cut
  for (auto& m : bothModels()) {
    SCOPED_TRACE(m->name());
    m->reset(288.15);
    EXPECT_EQ(m->outputs().exhaust_mass_kg, 0.0);
    double mass = 0, massT = 0, Tt = 0, o2 = 0, co2 = 0, h2o = 0;
    engine::EngineInputs in;
    in.ambient_T_K = 288.15;
    for (int k = 0; k < 60; ++k) {
      in.speed_rad_s = units::rpmToRadps(800.0 + 10.0 * k);
      in.torque_request_Nm = k < 40 ? 50.0 + 20.0 * k : 0.0;
      in.fuel_enabled = k < 50;
      const engine::EngineOutputs& o = m->step(0.01, in);
      const double mdot = std::max(0.0, o.exhaust_mass_flow_kg_s);
      mass += mdot * 0.01;
      massT += mdot * o.exhaust_T_K * 0.01;
      Tt += o.exhaust_T_K * 0.01;
      o2 += mdot * o.y_O2 * 0.01;
      co2 += mdot * o.y_CO2 * 0.01;
      h2o += mdot * o.y_H2O * 0.01;
    }
    const engine::EngineOutputs& o = m->outputs();
    EXPECT_GT(mass, 0.0);
    EXPECT_NEAR(o.exhaust_mass_kg, mass, 1e-15 * 60);
    EXPECT_NEAR(o.exhaust_mass_T_kg_K, massT, 1e-12 * 60);
    EXPECT_NEAR(o.exhaust_T_time_K_s, Tt, 1e-12 * 60);
    EXPECT_NEAR(o.o2_mass_kg, o2, 1e-15 * 60);
    EXPECT_NEAR(o.co2_mass_kg, co2, 1e-15 * 60);
    EXPECT_NEAR(o.h2o_mass_kg, h2o, 1e-15 * 60);
    EXPECT_GT(o.co2_mass_kg, 0.0);  // fired
  }
}
