// The heater loop with the engine stopped (hybrid stop-start, src/cooling/cooling_model.hpp):
// without the electric circulation pump the loop stands and the cabin's heat comes from the
// convector volume alone; with it the loop circulates through the engine jacket at the pump's
// flow and its electric energy is P_e x the time it runs. References: the energy of each part
// of the network (conservation), the pump's rated flow and power.
#include <gtest/gtest.h>

#include <cmath>

#include "common/units.hpp"
#include "cooling/cooling_model.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::cooling;
using units::celsiusToK;
using units::rpmToRadps;

namespace {

constexpr double kStop_s = 600.0;  // a long stop: 7.2 MJ of cabin demand vs 93 kJ/K of convector water

struct StopResult {
  double engine_side_J = 0.0;  // Σ C ΔT of metal, oil, engine loop and radiator volume over the stop
  double convector_J = 0.0;    // C_v ΔT_v over the stop
  double heater_J = 0.0, surface_J = 0.0, pump_J = 0.0, flow_m3_s = 0.0;
};

// A bus warm at 0 degC (valve open, 12 kW cabin demand), then a kStop_s engine stop.
StopResult warmThenStop(double pump_flow_m3_s) {
  CoolingParams p = test::yamlParams();
  p.heater.electric_pump_flow_m3_s = pump_flow_m3_s;
  CoolingModel m(p);
  const double Ta = celsiusToK(0.0);
  m.reset(Ta, celsiusToK(86.0), celsiusToK(83.0), Ta);
  CoolingInputs run;
  run.ambient_T_K = Ta;
  run.engine_heat_W = 30e3;
  run.pump_speed_rad_s = rpmToRadps(1000.0);
  for (int k = 0; k < 3000; ++k) m.step(0.1, run);  // 300 s running: the loop is warm
  const CoolingOutputs& o = m.outputs();
  EXPECT_TRUE(o.heater_valve_open);
  EXPECT_EQ(o.electric_pump_power_W, 0.0);  // the engine's pump circulates: no electric pump
  EXPECT_EQ(o.electric_pump_energy_J, 0.0);
  const NetworkCapacities& C = m.capacities();
  const auto engineSide = [&] {
    return C.metal * o.metal_T_K + C.oil * o.oil_T_K + C.engine_loop * o.coolant_ht_T_K +
           C.radiator * o.radiator_coolant_T_K;
  };
  const double E0 = engineSide(), Tv0 = o.convector_coolant_T_K, H0 = o.heater_J, S0 = o.surface_loss_J;
  CoolingInputs stop;  // engine at rest: no heat, pump standing
  stop.ambient_T_K = Ta;
  StopResult r;
  for (int k = 0; k < static_cast<int>(kStop_s / 0.1 + 0.5); ++k) {
    m.step(0.1, stop);
    EXPECT_TRUE(o.heater_valve_open) << k;
    EXPECT_EQ(o.radiator_ht_heat_W, 0.0) << k;
    r.flow_m3_s = o.heater_loop_flow_m3_s;
  }
  r.engine_side_J = engineSide() - E0;
  r.convector_J = C.convector * (o.convector_coolant_T_K - Tv0);
  r.heater_J = o.heater_J - H0;
  r.surface_J = o.surface_loss_J - S0;
  r.pump_J = o.electric_pump_energy_J;
  return r;
}

}  // namespace

// No electric pump: the standing loop keeps the convectors warm only with its own water; the
// engine side loses nothing but its surface loss (no heat drawn from the engine loop).
TEST(CoolingHeaterLoop, EngineStoppedWithoutPumpDrawsNoHeatFromTheEngine) {
  const StopResult r = warmThenStop(0.0);
  EXPECT_EQ(r.flow_m3_s, 0.0);
  EXPECT_EQ(r.pump_J, 0.0);
  EXPECT_GT(r.heater_J, 0.0);
  EXPECT_NEAR(r.convector_J, -r.heater_J, 1e-9 * r.heater_J);
  EXPECT_NEAR(r.engine_side_J, -r.surface_J, 1e-9 * r.heater_J);
  std::printf("stop without pump: cabin %.0f kJ from the convector water, engine side -%.1f kJ (surface)\n",
              r.heater_J / 1e3, r.surface_J / 1e3);
}

// With the pump: the loop circulates at its flow through the engine jacket, the engine side
// supplies the cabin (its loss beyond the surface loss is the heat carried to the convectors),
// the cabin gets more heat than from the standing water (which falls below the temperature that
// delivers the 12 kW), and the pump's electric energy is its power x the time it ran.
TEST(CoolingHeaterLoop, EngineStoppedWithPumpHeatsFromTheEngineAndBooksItsEnergy) {
  const CoolingParams p = test::yamlParams();
  const StopResult without = warmThenStop(0.0);
  const StopResult r = warmThenStop(p.heater.electric_pump_flow_m3_s);
  ASSERT_GT(p.heater.electric_pump_flow_m3_s, 0.0);
  EXPECT_EQ(r.flow_m3_s, p.heater.electric_pump_flow_m3_s);
  EXPECT_NEAR(r.pump_J, p.heater.electric_pump_power_W * kStop_s, 1e-9 * r.pump_J);
  const double carried_J = -r.engine_side_J - r.surface_J;  // engine side -> convector volume
  EXPECT_GT(carried_J, 0.1 * r.heater_J);
  EXPECT_NEAR(r.convector_J, carried_J - r.heater_J, 1e-9 * r.heater_J);  // conservation
  EXPECT_GT(r.heater_J, without.heater_J);
  EXPECT_LT(without.heater_J, 12e3 * kStop_s);  // the standing water could not keep up
  std::printf("stop with the pump: cabin %.0f kJ (%.0f kJ without), %.0f kJ of it from the engine side, "
              "pump %.1f kJ electric\n",
              r.heater_J / 1e3, without.heater_J / 1e3, carried_J / 1e3, r.pump_J / 1e3);
}
