// Map engine: where its friction work goes (gas_path.hpp, common/friction_heat.hpp). Checked
// against the engine's own motoring curve by hand: the friction work rate P_f = s_f |T_mot| φ ω
// ends wholly in the oil (f_o P_f) and the metal (the rest + wall heat), the cold-oil extra
// ΔT_fric ω is heat (not exhaust enthalpy), the first-law balance of the gas path still closes,
// and in motoring the heat is the friction alone.
#include <gtest/gtest.h>

#include <cmath>

#include "common/units.hpp"
#include "engine_map/map_engine.hpp"

using namespace hbt;
using namespace hbt::engine_map;

namespace {

// Steady point (settled PT1) at speed w, brake torque request T, oil temperature oil_K (0: warm
// map), fuel on/off; returns the engine after 3 s.
MapEngine runSteady(double w, double T, double oil_K, bool fuel) {
  MapEngine e{MapEngineParams{}};
  e.reset(w, T);
  MapEngineInputs in;
  in.speed_rad_s = w;
  in.torque_request_Nm = T;
  in.oil_T_K = oil_K;
  in.fuel_enabled = fuel;
  for (int k = 0; k < 300; ++k) e.step(0.01, in);
  return e;
}

double vogelFactor(double T_oil) {  // config/engine_map.yaml oil law, by hand
  return std::pow(std::exp(1170.0 / (T_oil - 150.0) - 1170.0 / (363.15 - 150.0)), 0.25);
}

}  // namespace

TEST(MapEngineFrictionHeat, FiredFrictionEndsInOilAndMetal) {
  const double w = units::rpmToRadps(1200.0), T = 400.0, T_oil = 278.15;  // oil at 5 degC
  const MapEngine cold = runSteady(w, T, T_oil, true);
  const MapEngine warm = runSteady(w, T, 0.0, true);
  const GasPathState& g = cold.outputs().gas;
  const MapEngineParams& p = cold.params();
  const double P_f_warm = 0.75 * std::fabs(cold.motoringTorque(w)) * w;
  const double P_f = P_f_warm * vogelFactor(T_oil);
  EXPECT_NEAR(g.friction_W, P_f, 1e-9 * P_f);
  EXPECT_NEAR(warm.outputs().gas.friction_W, P_f_warm, 1e-9 * P_f_warm);
  // All of the friction: oil f_o P_f, metal the rest plus the wall heat; nothing lost.
  EXPECT_NEAR(g.oil_heat_W, p.gas.friction_heat_to_oil_fraction * P_f, 1e-9 * P_f);
  EXPECT_NEAR(g.metal_heat_W + g.oil_heat_W, g.coolant_heat_W, 1e-9 * g.coolant_heat_W);
  EXPECT_GE(g.coolant_heat_W - g.friction_W, 0.0);  // wall heat
  // The cold-oil extra is heat: Q_cool = f_cool F + ΔT_fric ω (f_cool at this load fraction).
  const double load = T / cold.outputs().max_torque_Nm;
  const double fcool = p.gas.coolant_fraction_light_load +
                       load * (p.gas.coolant_fraction_full_load - p.gas.coolant_fraction_light_load);
  const double dP = (P_f - P_f_warm);
  EXPECT_NEAR(g.coolant_heat_W, fcool * g.fuel_power_W + dP, 1e-9 * g.coolant_heat_W);
  // First law of the gas path still closes with the extra heat taken from the exhaust.
  const double exh = g.exhaust_mass_flow_kg_s * p.gas.exhaust_cp_J_kgK * (g.exhaust_T_K - 298.15);
  EXPECT_NEAR(g.brake_power_W + g.coolant_heat_W + g.misc_heat_W + g.intercooler_heat_W + exh, g.fuel_power_W,
              1e-9 * g.fuel_power_W);
  // Cumulative: over 3 s at a steady point the totals are the rates x 3 s, oil + metal = total.
  const MapEngineOutputs& o = cold.outputs();
  EXPECT_NEAR(o.oil_heat_J, p.gas.friction_heat_to_oil_fraction * o.friction_work_J, 1e-9 * o.oil_heat_J);
  EXPECT_NEAR(o.oil_heat_J + o.metal_heat_J, o.coolant_heat_J, 1e-9 * o.coolant_heat_J);
}

TEST(MapEngineFrictionHeat, MotoringHeatIsTheFrictionAlone) {
  // Fuel cut at 1800 rpm with oil at 40 degC: the engine's heat = its mechanical friction work,
  // the rest of the motoring work (pumping, 1 - s_f) heats the gas.
  const double w = units::rpmToRadps(1800.0), T_oil = 313.15;
  const MapEngine e = runSteady(w, 0.0, T_oil, false);
  const GasPathState& g = e.outputs().gas;
  const double P_f = 0.75 * std::fabs(e.motoringTorque(w)) * vogelFactor(T_oil) * w;
  EXPECT_DOUBLE_EQ(g.fuel_power_W, 0.0);
  EXPECT_NEAR(g.coolant_heat_W, P_f, 1e-9 * P_f);
  EXPECT_NEAR(g.oil_heat_W, 0.5 * P_f, 1e-9 * P_f);
  EXPECT_NEAR(g.metal_heat_W, 0.5 * P_f, 1e-9 * P_f);
  // Brake power = -(friction + pumping) = -(|T_mot| + ΔT_fric) ω.
  EXPECT_NEAR(-g.brake_power_W, P_f + 0.25 * std::fabs(e.motoringTorque(w)) * w, 1e-9 * P_f);
  // Engine standing: no friction, no heat.
  const MapEngine still = runSteady(0.0, 0.0, T_oil, false);
  EXPECT_DOUBLE_EQ(still.outputs().gas.coolant_heat_W, 0.0);
  EXPECT_DOUBLE_EQ(still.outputs().gas.oil_heat_W, 0.0);
}
