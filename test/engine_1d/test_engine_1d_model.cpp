// Engine1DModel, the 1D engine behind the twin's engine interface (engine_interface/engine_model.hpp): its
// outputs equal the wrapped Engine1D's exactly on a short trace that switches every input (speed,
// request, fuel, coolant and back-pressure loops on and off, ambient pressure missing; the brake
// torque is the crank torque of the step while the engine is off, its work booked as such); the
// documented policies: start at the reference engine's idle speed (engine_map.yaml) with the
// standard atmosphere and the warm coolant, no cooling node = the thermostat temperature, the
// exhaust temperature of the start state = ambient, the limits = the reference map's curves.
#include <gtest/gtest.h>

#include "common/units.hpp"
#include "engine_1d/engine_1d_model.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::engine_1d;
using hbt::engine_1d::test::defaultParams;
using hbt::engine_1d::test::repoRoot;

namespace {

// Step k (10 ms) of a 1.5 s trace: idle, tip-in while the speed rises, overrun, engine off.
engine::EngineInputs traceInputs(int k) {
  engine::EngineInputs in;
  const double t = 0.01 * k;
  in.speed_rad_s = units::rpmToRadps(t < 0.4 ? 700.0 : 700.0 + 600.0 * (t - 0.4));
  in.torque_request_Nm = t < 0.3 ? 30.0 : t < 1.0 ? 900.0 : t < 1.2 ? -100.0 : 200.0;
  in.fuel_enabled = t < 1.3;
  in.ambient_T_K = 288.15;
  in.ambient_p_Pa = (k % 5 == 0) ? 0.0 : 99000.0;  // 0: the command carries none
  in.coolant_T_K = t < 0.5 ? 0.0 : 300.0;            // 0: no cooling node
  in.oil_T_K = t < 0.5 ? 0.0 : 295.0;
  in.back_pressure_Pa = (t > 0.7) ? 108000.0 : 0.0;  // 0: no ATS node (own orifice law)
  return in;
}

}  // namespace

TEST(Engine1DModel, OutputsEqualTheWrappedModelExactlyOnATrace) {
  const Engine1DParams& p = defaultParams();
  Engine1DModel model(p, repoRoot());
  Engine1D ref(p, repoRoot());
  const double T0 = 288.15;
  model.reset(T0);
  ref.reset(p.reference.idle_speed_rad_s, 0.0, T0, 101325.0, 363.15);
  double pos_J = 0.0, mot_J = 0.0;  // work of the published torque, split by sign
  for (int k = 0; k < 150; ++k) {
    const engine::EngineInputs in = traceInputs(k);
    Engine1DInputs e;
    e.speed_rad_s = in.speed_rad_s;
    e.torque_request_Nm = in.torque_request_Nm;
    e.ambient_T_K = in.ambient_T_K;
    e.ambient_p_Pa = in.ambient_p_Pa > 0.0 ? in.ambient_p_Pa : 101325.0;
    e.back_pressure_Pa = in.back_pressure_Pa;
    e.coolant_T_K = in.coolant_T_K > 0.0 ? in.coolant_T_K : 363.15;  // the thermostat temperature
    e.oil_T_K = in.oil_T_K;
    e.fuel_enabled = in.fuel_enabled;
    const engine::EngineOutputs& a = model.step(0.01, in);
    const Engine1DOutputs& b = ref.step(0.01, e);
    SCOPED_TRACE(k);
    const double w = in.speed_rad_s;
    ASSERT_EQ(a.speed_rad_s, w);
    // the cycle mean while fuelled, the crank torque of the step while the engine is off
    ASSERT_EQ(a.brake_torque_Nm, in.fuel_enabled ? b.brake_torque_Nm : b.crank_torque_Nm);
    const double work_J = a.brake_torque_Nm * w * 0.01;
    (work_J > 0.0 ? pos_J : mot_J) += work_J;
    ASSERT_EQ(a.max_torque_Nm, ref.fullLoadTorque(w));
    ASSERT_EQ(a.min_torque_Nm, ref.motoringTorque(w));
    ASSERT_EQ(a.fuel_mass_flow_kg_s, b.fuel_mass_flow_kg_s);
    ASSERT_EQ(a.fuel_mass_kg, b.fuel_mass_kg);
    ASSERT_EQ(a.positive_work_J, pos_J);
    ASSERT_EQ(a.motoring_work_J, mot_J);
    if (in.fuel_enabled) {  // the same as the wrapped model's while fuelled
      ASSERT_EQ(a.positive_work_J, b.positive_work_J);
      ASSERT_EQ(a.motoring_work_J, b.motoring_work_J);
    }
    ASSERT_EQ(a.boost_pressure_Pa, b.boost_pressure_Pa);
    ASSERT_EQ(a.charge_air_T_K, b.intake_manifold_T_K);
    ASSERT_EQ(a.turbo_speed_rad_s, b.turbo_speed_rad_s);
    ASSERT_EQ(a.lambda, b.lambda);
    ASSERT_EQ(a.exhaust_mass_flow_kg_s, b.exhaust_mass_flow_kg_s);
    ASSERT_EQ(a.exhaust_T_K, b.exhaust_T_K);
    ASSERT_EQ(a.y_O2, b.exhaust.y_O2);
    ASSERT_EQ(a.y_CO2, b.exhaust.y_CO2);
    ASSERT_EQ(a.y_H2O, b.exhaust.y_H2O);
    ASSERT_EQ(a.y_N2, b.exhaust.y_N2);
    ASSERT_EQ(a.nox_mass_flow_kg_s, b.nox_mass_flow_kg_s);
    ASSERT_EQ(a.nox_mass_kg, b.nox_mass_kg);
    ASSERT_EQ(a.heat_to_coolant_W, b.coolant_heat_W);
    ASSERT_EQ(a.heat_to_coolant_J, b.coolant_heat_J);
    ASSERT_EQ(a.heat_to_oil_W, b.oil_heat_W);
    ASSERT_EQ(a.heat_to_oil_J, b.oil_heat_J);
    ASSERT_EQ(a.friction_correction_Nm, 0.0);  // inside the cycle simulation
    ASSERT_EQ(a.pumping_correction_Nm, 0.0);
    ASSERT_EQ(a.coolant_T_K, in.coolant_T_K);  // echoed as given (0 = none)
    ASSERT_EQ(a.oil_T_K, in.oil_T_K);
    ASSERT_EQ(a.back_pressure_Pa, in.back_pressure_Pa);
  }
  EXPECT_GT(ref.outputs().fuel_mass_kg, 0.0);
  EXPECT_GT(ref.outputs().nox_mass_kg, 0.0);
}

TEST(Engine1DModel, StartsAtTheReferenceIdleSpeedWarmWithTheStandardAtmosphere) {
  const Engine1DParams& p = defaultParams();
  EXPECT_EQ(p.reference.idle_speed_rad_s, 73.3038);  // config/engine_map.yaml, the reference
  Engine1DModel model(p, repoRoot());
  model.reset(263.15);
  const engine::EngineOutputs& o = model.outputs();
  EXPECT_EQ(model.idleSpeed(), p.reference.idle_speed_rad_s);
  EXPECT_EQ(o.speed_rad_s, p.reference.idle_speed_rad_s);
  EXPECT_EQ(model.inputs().ambient_p_Pa, 101325.0);
  EXPECT_EQ(Engine1DModel::kWarmCoolant_K, 363.15);
  EXPECT_EQ(o.brake_torque_Nm, 0.0);
  EXPECT_EQ(o.max_torque_Nm, model.model().reference().fullLoadTorque(p.reference.idle_speed_rad_s));
  EXPECT_EQ(model.model().outputs().exhaust_T_K, 0.0);  // no cycle simulated yet ...
  EXPECT_EQ(o.exhaust_T_K, 263.15);                     // ... so the ambient temperature
  EXPECT_EQ(o.coolant_T_K, 0.0);
  EXPECT_EQ(std::string(model.name()), "1d");
  // diagnostics: the sub-steps of the window restart at each status
  engine::EngineInputs in = traceInputs(10);
  for (int k = 0; k < 5; ++k) model.step(0.01, in);
  std::vector<engine::EngineDiagnosticValue> kv, kv2;
  model.diagnosticValues(kv);
  ASSERT_GE(kv.size(), 2u);
  EXPECT_EQ(kv[0].key, "gas_steps_window");
  EXPECT_EQ(kv[0].value, kv[1].value);
  EXPECT_GT(kv[0].value, 10.0);  // several coupled sub-steps per 10 ms
  model.step(0.01, in);
  model.diagnosticValues(kv2);
  EXPECT_EQ(kv2[0].value, kv2[1].value - kv[1].value);
  EXPECT_FALSE(model.boostLimited(50.0));
}
