// MapEngineModel, the map engine behind the twin's engine interface (engine_interface/engine_model.hpp):
// its outputs equal the wrapped MapEngine's exactly on a trace that visits every input (speed,
// request, fuel cut, coolant and back-pressure on and off, ambient pressure missing); the
// documented policies: start at engine_map.yaml's idle speed with the standard atmosphere, the
// live limits = static curve minus the cold-oil and back-pressure corrections, the boost_limited
// condition on a full-load step against the PT1 build-up.
#include <gtest/gtest.h>

#include <cmath>

#include "common/params.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "engine_map/map_engine_model.hpp"

using namespace hbt;
using namespace hbt::engine_map;

namespace {

MapEngineParams yamlParams() {
  MapEngineParams p;
  ParamSet ps;
  p.declare(ps);
  applyParams(ps, readYamlParams("config/engine_map.yaml"));
  return p;
}

// One step of the trace k (10 ms): idle, a tip-in to full load while the speed rises, a fuel-cut
// overrun, engine off; loops (coolant, back-pressure) and ambient pressure switched on and off.
engine::EngineInputs traceInputs(int k) {
  engine::EngineInputs in;
  const double t = 0.01 * k;
  in.speed_rad_s = units::rpmToRadps(700.0 + (t < 2.0 ? 0.0 : t < 5.0 ? 400.0 * (t - 2.0) : 1200.0 - 300.0 * (t - 5.0)));
  in.torque_request_Nm = t < 1.0 ? 40.0 : t < 4.0 ? 1200.0 : t < 5.0 ? 300.0 : t < 6.0 ? -200.0 : 100.0;
  in.fuel_enabled = t < 6.5;
  in.ambient_T_K = 273.15 + 5.0 + t;
  in.ambient_p_Pa = (k % 7 == 0) ? 0.0 : 98000.0 + 10.0 * k;  // 0: the command carries none
  in.coolant_T_K = t < 3.0 ? 0.0 : 280.0 + 10.0 * t;          // 0: no cooling node
  in.oil_T_K = t < 3.0 ? 0.0 : 283.0 + 10.0 * t;
  in.back_pressure_Pa = (t > 1.5 && t < 6.0) ? 104000.0 + 1000.0 * t : 0.0;  // 0: no ATS node
  return in;
}

}  // namespace

TEST(MapEngineModel, OutputsEqualTheWrappedModelExactlyOnATrace) {
  const MapEngineParams p = yamlParams();
  MapEngineModel model(p, "");
  MapEngine ref(p, "");
  const double T0 = 268.15;
  model.reset(T0);
  ref.reset(p.idle_speed_rad_s, 0.0, T0, units::kStandardAtmosphere_Pa);
  for (int k = 0; k < 800; ++k) {
    const engine::EngineInputs in = traceInputs(k);
    MapEngineInputs m;
    m.speed_rad_s = in.speed_rad_s;
    m.torque_request_Nm = in.torque_request_Nm;
    m.ambient_T_K = in.ambient_T_K;
    m.ambient_p_Pa = in.ambient_p_Pa > 0.0 ? in.ambient_p_Pa : 101325.0;
    m.fuel_enabled = in.fuel_enabled;
    m.oil_T_K = in.oil_T_K;
    m.back_pressure_Pa = in.back_pressure_Pa;
    const engine::EngineOutputs& a = model.step(0.01, in);
    const MapEngineOutputs& b = ref.step(0.01, m);
    SCOPED_TRACE(k);
    const double w = in.speed_rad_s, dT = b.friction_correction_Nm + b.pumping_correction_Nm;
    ASSERT_EQ(a.speed_rad_s, w);
    ASSERT_EQ(a.brake_torque_Nm, b.brake_torque_Nm);
    ASSERT_EQ(a.max_torque_Nm, ref.fullLoadTorque(w) - dT);
    ASSERT_EQ(a.min_torque_Nm, ref.motoringTorque(w) - dT);
    ASSERT_EQ(a.max_torque_Nm, b.max_torque_Nm);  // = MapEngine's own live limit
    ASSERT_EQ(a.min_torque_Nm, b.min_torque_Nm);
    ASSERT_EQ(a.fuel_mass_flow_kg_s, b.fuel_mass_flow_kg_s);
    ASSERT_EQ(a.fuel_mass_kg, b.fuel_mass_kg);
    ASSERT_EQ(a.positive_work_J, b.positive_work_J);
    ASSERT_EQ(a.motoring_work_J, b.motoring_work_J);
    ASSERT_EQ(a.boost_pressure_Pa, b.gas.boost_pressure_Pa);
    ASSERT_EQ(a.charge_air_T_K, b.gas.intake_manifold_T_K);
    ASSERT_EQ(a.lambda, b.gas.lambda);
    ASSERT_EQ(a.exhaust_mass_flow_kg_s, b.gas.exhaust_mass_flow_kg_s);
    ASSERT_EQ(a.exhaust_T_K, b.gas.exhaust_T_K);
    ASSERT_EQ(a.y_O2, b.gas.comp.y_O2);
    ASSERT_EQ(a.y_CO2, b.gas.comp.y_CO2);
    ASSERT_EQ(a.y_H2O, b.gas.comp.y_H2O);
    ASSERT_EQ(a.y_N2, b.gas.comp.y_N2);
    ASSERT_EQ(a.nox_mass_flow_kg_s, b.gas.nox_mass_flow_kg_s);
    ASSERT_EQ(a.nox_mass_kg, b.nox_mass_kg);
    ASSERT_EQ(a.heat_to_coolant_W, b.gas.metal_heat_W);
    ASSERT_EQ(a.heat_to_coolant_J, b.metal_heat_J);
    ASSERT_EQ(a.heat_to_oil_W, b.gas.oil_heat_W);
    ASSERT_EQ(a.heat_to_oil_J, b.oil_heat_J);
    ASSERT_EQ(a.friction_W, b.gas.friction_W);
    ASSERT_EQ(a.friction_correction_Nm, b.friction_correction_Nm);
    ASSERT_EQ(a.pumping_correction_Nm, b.pumping_correction_Nm);
    ASSERT_EQ(a.coolant_T_K, in.coolant_T_K);         // echoed as used (0 = none)
    ASSERT_EQ(a.oil_T_K, in.oil_T_K);
    ASSERT_EQ(a.back_pressure_Pa, in.back_pressure_Pa);
    ASSERT_EQ(a.turbo_speed_rad_s, 0.0);              // no turbocharger in this model
  }
  // the trace reached what it is for: full load with both corrections, the fuel cut, engine off
  EXPECT_GT(ref.outputs().fuel_mass_kg, 0.0);
  EXPECT_LT(model.outputs().motoring_work_J, 0.0);
}

TEST(MapEngineModel, StartsAtTheIdleSpeedOfTheYamlWithTheStandardAtmosphere) {
  const MapEngineParams p = yamlParams();
  EXPECT_EQ(p.idle_speed_rad_s, 73.3038);  // 700 rpm (config/engine_map.yaml)
  MapEngineModel model(p, "");
  model.reset(298.15);
  const engine::EngineOutputs& o = model.outputs();
  EXPECT_EQ(model.idleSpeed(), p.idle_speed_rad_s);
  EXPECT_EQ(o.speed_rad_s, p.idle_speed_rad_s);
  EXPECT_EQ(model.inputs().ambient_p_Pa, 101325.0);
  EXPECT_EQ(o.brake_torque_Nm, 0.0);
  EXPECT_EQ(o.max_torque_Nm, model.fullLoadTorque(p.idle_speed_rad_s));  // warm, no correction
  EXPECT_EQ(o.min_torque_Nm, model.motoringTorque(p.idle_speed_rad_s));
  EXPECT_NEAR(units::radpsToRpm(o.speed_rad_s), 700.0, 1e-3);
  // the start state's gas path is MapEngine's at idle, 0 Nm, 298.15 K, 101325 Pa
  MapEngine ref(p, "");
  ref.reset(p.idle_speed_rad_s, 0.0, 298.15, 101325.0);
  EXPECT_EQ(o.exhaust_T_K, ref.outputs().gas.exhaust_T_K);
  EXPECT_EQ(o.exhaust_mass_flow_kg_s, ref.outputs().gas.exhaust_mass_flow_kg_s);
  EXPECT_GT(o.exhaust_T_K, 298.15);
  EXPECT_EQ(o.coolant_T_K, 0.0);
  EXPECT_EQ(o.back_pressure_Pa, 0.0);
  EXPECT_EQ(std::string(model.name()), "map");
}

TEST(MapEngineModel, AMissingAmbientPressureIsTheStandardAtmosphere) {
  const MapEngineParams p = yamlParams();
  MapEngineModel a(p, ""), b(p, "");
  a.reset(298.15);
  b.reset(298.15);
  engine::EngineInputs in = traceInputs(250);  // full load, back-pressure loop on
  in.ambient_p_Pa = 0.0;
  const engine::EngineOutputs oa = a.step(0.01, in);
  in.ambient_p_Pa = 101325.0;
  const engine::EngineOutputs ob = b.step(0.01, in);
  EXPECT_EQ(a.inputs().ambient_p_Pa, 101325.0);
  EXPECT_EQ(oa.pumping_correction_Nm, ob.pumping_correction_Nm);
  EXPECT_NE(oa.pumping_correction_Nm, 0.0);
  EXPECT_EQ(oa.boost_pressure_Pa, ob.boost_pressure_Pa);
  EXPECT_EQ(oa.fuel_mass_flow_kg_s, ob.fuel_mass_flow_kg_s);
}

TEST(MapEngineModel, BoostLimitedWhileThePt1BuildUpHoldsAFullLoadStep) {
  MapEngineModel model(yamlParams(), "");
  model.reset(298.15);
  engine::EngineInputs in;
  in.speed_rad_s = units::rpmToRadps(1000.0);
  in.torque_request_Nm = 0.0;
  for (int k = 0; k < 200; ++k) model.step(0.01, in);
  EXPECT_FALSE(model.boostLimited(50.0));
  in.torque_request_Nm = 2000.0;  // far above full load: the PT1 (τ 0.58 s at 1000 rpm) limits
  model.step(0.01, in);
  EXPECT_TRUE(model.boostLimited(50.0));
  EXPECT_NE(model.boostLimitedMessage(3.0).find("above the PT1"), std::string::npos);
  int k = 1;
  for (; k < 1000 && model.boostLimited(50.0); ++k) model.step(0.01, in);
  // the dynamic limit comes within 50 Nm of the full load after τ ln(T_fl/50) ~ 1.8 s
  const double tau = model.model().timeConstant(in.speed_rad_s);
  const double T_fl = model.fullLoadTorque(in.speed_rad_s);
  EXPECT_NEAR(0.01 * k, tau * std::log(T_fl / 50.0), 0.02);
  std::vector<engine::EngineDiagnosticValue> kv;
  model.diagnosticValues(kv);
  ASSERT_EQ(kv.size(), 3u);
  EXPECT_EQ(kv[0].key, "dynamic_full_load_nm");
  EXPECT_EQ(kv[1].key, "full_load_nm");
  EXPECT_EQ(kv[1].value, T_fl);
}
