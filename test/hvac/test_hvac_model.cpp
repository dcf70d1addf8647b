// The HVAC model as the participant steps it (src/hvac/hvac_model.hpp): its cabin balance
// closes over a stop-and-go hour with heating, doors and the heater; A/C in the heat with the
// compressor only while the engine runs; the shipped YAML and bad input named by key.
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"
#include "common/yaml_params.hpp"
#include "hvac/hvac_model.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::hvac;

TEST(HvacModel, ColdHourClosesTheCabinBalanceAndBooksTheHeaterFuel) {
  HvacModel m(test::yamlParams(), 1500.0, "config/hvac.yaml");
  m.reset(273.15);
  HvacInputs in;
  in.ambient_T_K = 273.15;
  for (int i = 0; i < 36000; ++i) {
    in.heater_water_T_K = 273.15 + std::min(85.0, i * 0.004);  // the coolant warming over ~6 h
    in.coolant_heat_W = m.outputs().heating_demand_W * (in.heater_water_T_K > 313.15 ? 1.0 : 0.0);
    in.vehicle_speed_m_s = (i / 200) % 3 == 0 ? 0.0 : 8.0;  // standing 20 s of every 60 s
    m.step(0.1, in);
  }
  const HvacOutputs& o = m.outputs();
  EXPECT_NEAR(o.energy_residual_J, 0.0, 1e-9 * o.coolant_heat_J);
  EXPECT_GT(o.doors_J, 0.0);
  EXPECT_GT(o.aux_heater_heat_J, 0.0);
  EXPECT_NEAR(o.aux_heater_fuel_kg * units::kDieselLhv_J_kg * 0.82, o.aux_heater_heat_J, 1e-9 * o.aux_heater_heat_J);
  EXPECT_EQ(o.ac_cooling_J, 0.0);
  EXPECT_GT(units::kToCelsius(o.cabin_T_K), 15.0);
}

TEST(HvacModel, HotAmbientCoolsOnlyWithTheEngineRunning) {
  HvacModel m(test::yamlParams(), 1500.0, "config/hvac.yaml");
  m.reset(313.15);
  HvacInputs in;
  in.ambient_T_K = 313.15;
  in.heater_water_T_K = 358.15;
  in.vehicle_speed_m_s = 8.0;
  for (int i = 0; i < 36000; ++i) m.step(0.1, in);
  const HvacOutputs& o = m.outputs();
  EXPECT_NEAR(o.cabin_T_K, 297.15, 1e-3);  // the cooling set point, the A/C within its capacity
  EXPECT_NEAR(o.compressor_energy_J * m.ac().cop(313.15), o.ac_cooling_J, 1e-9 * o.ac_cooling_J);
  EXPECT_EQ(o.heating_demand_W, 0.0);
  EXPECT_EQ(o.aux_heater_fuel_kg, 0.0);
  EXPECT_NEAR(o.energy_residual_J, 0.0, 1e-9 * o.ac_cooling_J);
  EXPECT_FALSE(o.engine_run_request);  // held at the set point: no need to keep the engine
  in.engine_running = false;  // stop-start: the belt-driven compressor stands
  in.vehicle_speed_m_s = 0.0;
  const double T_before = o.cabin_T_K;
  for (int i = 0; i < 300; ++i) m.step(0.1, in);
  EXPECT_EQ(m.outputs().compressor_power_W, 0.0);
  EXPECT_GT(m.outputs().cabin_T_K, T_before);
  // the cabin drifts above T_c + engine_run_above_K: the A/C asks the engine to run
  while (m.outputs().cabin_T_K <= 297.15 + 2.0) {
    EXPECT_FALSE(m.outputs().engine_run_request);
    m.step(0.1, in);
  }
  EXPECT_TRUE(m.outputs().engine_run_request);
}

TEST(HvacModel, WarmStartCabinIsTheNearestSetPoint) {
  HvacModel m(test::yamlParams(), 1500.0, "config/hvac.yaml");
  EXPECT_EQ(m.inServiceCabin_K(273.15), 293.15);
  EXPECT_EQ(m.inServiceCabin_K(313.15), 297.15);
  EXPECT_EQ(m.inServiceCabin_K(295.15), 295.15);
}

TEST(HvacModel, BadInputNamed) {
  HvacParams p = test::yamlParams();
  p.controller.cooling_setpoint_K = p.controller.heating_setpoint_K - 1.0;
  try {
    HvacModel(p, 1500.0, "config/hvac.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("controller/cooling_setpoint_K"), std::string::npos) << e.what();
  }
  HvacModel m(test::yamlParams(), 1500.0, "config/hvac.yaml");
  HvacInputs in;
  in.heater_water_T_K = std::nan("");
  try {
    m.step(0.1, in);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("heater_water_T_K"), std::string::npos) << e.what();
  }
  HvacParams q;
  ParamSet ps;
  q.declare(ps);
  ParamSource src = readYamlParams("config/hvac.yaml");
  src.set("ac/carnot_fraction", 7.0);
  EXPECT_THROW(applyParams(ps, src, {"cosim/", "diagnostics/"}), InputError);
}
