// The cooling node's step means (cooling/step_inputs.hpp) over windows with an engine stop, and a
// warm cooling system fed the inputs of a stopped engine: zero heat, zero pump speed.
#include <gtest/gtest.h>

#include <cmath>

#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "cooling/cooling_model.hpp"
#include "support.hpp"
#include "cooling/step_inputs.hpp"

using namespace hbt;
using namespace hbt::cooling;
using units::celsiusToK;

namespace {

/// The engine integrating its 10 ms heat and crank speed (engine_model.hpp).
struct Engine {
  CoolingTotals tot;
  void run(double heat_W, double speed_rad_s, int steps) {
    for (int i = 0; i < steps; ++i) {
      tot.engine_heat_J += heat_W * 0.01;
      tot.pump_angle_rad += speed_rad_s * 0.01;
    }
  }
};

constexpr double kIdle_rad_s = 62.8, kIdleHeat_W = 9e3;

StepInputs primed(Engine& e) {
  StepInputs si;
  e.run(kIdleHeat_W, kIdle_rad_s, 100000);  // 1000 s: large totals
  si.next(e.tot, CoolingInputs{}, 0.1);
  return si;
}

using test::yamlParams;

}  // namespace

TEST(CoolingStepInputs, AWindowThatStartsAnEngineStopIsTheMeanOfBothParts) {
  Engine e;
  StepInputs si = primed(e);
  e.run(kIdleHeat_W, kIdle_rad_s, 3);
  e.run(0.0, 0.0, 7);
  CoolingInputs point;  // the sample: engine stopped
  const CoolingInputs in = si.next(e.tot, point, 0.1);
  EXPECT_NEAR(in.engine_heat_W, 0.3 * kIdleHeat_W, 1e-6);
  EXPECT_NEAR(in.pump_speed_rad_s, 0.3 * kIdle_rad_s, 1e-9);
}

TEST(CoolingStepInputs, AWindowThatEndsAnEngineStopIsTheMeanOfBothParts) {
  Engine e;
  StepInputs si = primed(e);
  e.run(0.0, 0.0, 10);
  si.next(e.tot, CoolingInputs{}, 0.1);
  e.run(0.0, 0.0, 6);
  e.run(kIdleHeat_W, kIdle_rad_s, 4);
  CoolingInputs point;
  point.pump_speed_rad_s = kIdle_rad_s;
  const CoolingInputs in = si.next(e.tot, point, 0.1);
  EXPECT_NEAR(in.engine_heat_W, 0.4 * kIdleHeat_W, 1e-6);
  EXPECT_NEAR(in.pump_speed_rad_s, 0.4 * kIdle_rad_s, 1e-9);
}

TEST(CoolingStepInputs, AWholeWindowOffIsZeroHeatAndAStandingPump) {
  Engine e;
  StepInputs si = primed(e);
  e.run(0.0, 0.0, 10);
  CoolingInputs point;
  point.engine_heat_W = 123.0;  // a stale point value must not leak through
  point.pump_speed_rad_s = 45.0;
  point.vehicle_speed_m_s = 0.0;
  point.ambient_T_K = 273.15;
  const CoolingInputs in = si.next(e.tot, point, 0.1);
  EXPECT_EQ(in.engine_heat_W, 0.0);
  EXPECT_EQ(in.pump_speed_rad_s, 0.0);
  EXPECT_EQ(in.lt_heat_W, 0.0);
  EXPECT_EQ(in.ambient_T_K, 273.15);  // the sample's own values pass as they are
}

TEST(CoolingStepInputs, TheFirstStepTakesThePointValues) {
  StepInputs si;
  CoolingTotals tot;
  tot.engine_heat_J = 5.0;
  CoolingInputs point;
  point.engine_heat_W = 4e3;
  point.pump_speed_rad_s = kIdle_rad_s;
  const CoolingInputs in = si.next(tot, point, 0.1);
  EXPECT_EQ(in.engine_heat_W, 4e3);
  EXPECT_EQ(in.pump_speed_rad_s, kIdle_rad_s);
}

TEST(CoolingModel, AWarmSystemWithAStandingPumpLosesNoHeatThroughTheRadiator) {
  // A stopped engine at a bus stop at 25 degC (above the heater's balance point): no engine heat,
  // pump and belt-driven fan standing. No coolant reaches the radiator, so the radiator and the
  // pumps carry nothing; the engine cools through its surface alone and the balance closes.
  const CoolingParams p = yamlParams();
  CoolingModel m(p);
  const double Ta = celsiusToK(25.0);
  m.reset(Ta);
  CoolingInputs run;
  run.engine_heat_W = 60e3;
  run.pump_speed_rad_s = 150.0;
  run.ambient_T_K = Ta;
  for (int k = 0; k < 12000 && m.outputs().thermostat_opening < 0.5; ++k) m.step(0.1, run);
  ASSERT_GT(m.outputs().thermostat_opening, 0.0);  // warm: the thermostat is open
  const double E0 = m.outputs().energy_residual_J;
  CoolingInputs off;
  off.ambient_T_K = Ta;  // engine_heat_W = 0, pump_speed_rad_s = 0
  const auto stored_J = [&] {  // Σ C T of metal, HT and LT coolant
    const CoolingOutputs& o = m.outputs();
    const NetworkCapacities& C = m.capacities();
    return C.metal * o.metal_T_K + C.engine_loop * o.coolant_ht_T_K + C.radiator * o.radiator_coolant_T_K +
           C.convector * o.convector_coolant_T_K + C.lt * o.coolant_lt_T_K;
  };
  double E_prev = stored_J();
  for (int k = 0; k < 600; ++k) {  // a 60 s stop
    m.step(0.1, off);
    const CoolingOutputs& o = m.outputs();
    ASSERT_EQ(o.radiator_ht_heat_W, 0.0) << k;
    ASSERT_EQ(o.pump_power_W, 0.0) << k;
    ASSERT_EQ(o.fan_speed_rad_s, 0.0) << k;
    ASSERT_TRUE(std::isfinite(o.coolant_ht_T_K));
    ASSERT_LT(stored_J(), E_prev) << k;  // no heat source: the stored heat only falls
    ASSERT_GT(o.coolant_ht_T_K, Ta);
    E_prev = stored_J();
  }
  EXPECT_GT(m.outputs().surface_loss_W, 0.0);
  EXPECT_NEAR(m.outputs().energy_residual_J, E0, 1e-6 * m.outputs().engine_heat_J);
}

TEST(CoolingModel, AWarmStartHoldsItsStateAndCountsFromIt) {
  // start:=warm: the states as given, warm-up already done (coolant at the thermostat's opening),
  // the heater valve open, nothing stored or booked yet; with no heat and no flow the first step
  // moves only by the internal exchange (metal -> coolant), the balance closed.
  const CoolingParams p = yamlParams();
  CoolingModel m(p);
  const double Ta = celsiusToK(0.0);
  const auto& w = p.warm_start;
  m.reset(Ta, w.metal_K, w.coolant_ht_K, Ta + w.coolant_lt_above_ambient_K);
  const CoolingOutputs& o = m.outputs();
  EXPECT_EQ(o.metal_T_K, w.metal_K);
  EXPECT_EQ(o.coolant_ht_T_K, w.coolant_ht_K);
  EXPECT_EQ(o.coolant_lt_T_K, Ta + w.coolant_lt_above_ambient_K);
  EXPECT_GE(w.coolant_ht_K, p.thermostat.opening_start_K);  // the shipped warm state is warm
  EXPECT_EQ(o.warmup_time_s, 0.0);
  EXPECT_EQ(o.stored_change_J, 0.0);
  CoolingInputs in;
  in.ambient_T_K = Ta;
  in.engine_heat_W = 15e3;
  in.pump_speed_rad_s = 70.0;
  m.step(0.1, in);
  EXPECT_GT(m.outputs().heater_heat_W, 0.0);  // 0 degC: the cabin draws at once
  EXPECT_NEAR(m.outputs().energy_residual_J, 0.0, 1e-6 * 15e3 * 0.1);
  // a cold reset is the warm reset at ambient
  CoolingModel c(p), d(p);
  c.reset(Ta);
  d.reset(Ta, Ta, Ta, Ta);
  c.step(0.1, in);
  d.step(0.1, in);
  EXPECT_EQ(c.outputs().coolant_ht_T_K, d.outputs().coolant_ht_T_K);
  EXPECT_EQ(c.outputs().metal_T_K, d.outputs().metal_T_K);
}
