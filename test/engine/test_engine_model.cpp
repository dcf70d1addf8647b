// The twin's engine interface (engine/engine_model.hpp) over both models: ONE start policy (both
// start at the idle speed of config/engine_map.yaml, torque 0, the standard atmosphere), ONE
// ambient-pressure policy (a step without one = 101325 Pa), the loop inputs echoed as used
// (<= 0 = none = 0), an exhaust temperature > 0 from the start; the model name check of the
// participant's `model` parameter.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>
#include <vector>

#include "common/errors.hpp"
#include "common/params.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "engine_1d/engine_1d_model.hpp"
#include "engine_map/map_engine_model.hpp"

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
  m.push_back(std::make_unique<engine1d::Engine1DModel>(engine1d::Engine1DParams::load(repoRoot()), repoRoot()));
  return m;
}

}  // namespace

TEST(EngineModel, ModelNamesAreCheckedNamingTheKey) {
  EXPECT_NO_THROW(engine::checkEngineModelName("map", "engine", "model"));
  EXPECT_NO_THROW(engine::checkEngineModelName("1d", "engine", "model"));
  for (const char* bad : {"1D", "", "map ", "tvd"}) {
    try {
      engine::checkEngineModelName(bad, "/engine (private parameters)", "model");
      FAIL() << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "model");
      EXPECT_EQ(e.file(), "/engine (private parameters)");
      EXPECT_NE(std::string(e.what()).find("map | 1d"), std::string::npos);
    }
  }
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
    in.back_pressure_Pa = -1.0;  // none
    for (int k = 0; k < 20; ++k) m->step(0.01, in);
    EXPECT_EQ(m->inputs().ambient_p_Pa, 101325.0);
    EXPECT_EQ(m->outputs().coolant_T_K, 0.0);
    EXPECT_EQ(m->outputs().back_pressure_Pa, 0.0);
    EXPECT_EQ(m->outputs().speed_rad_s, in.speed_rad_s);
    EXPECT_GT(m->outputs().exhaust_T_K, 278.15);  // fired: hotter than the air
    EXPECT_GT(m->outputs().fuel_mass_kg, 0.0);
    EXPECT_GT(m->outputs().brake_torque_Nm, 0.0);
    EXPECT_GT(m->outputs().max_torque_Nm, 500.0);
    EXPECT_LT(m->outputs().min_torque_Nm, 0.0);
  }
}
