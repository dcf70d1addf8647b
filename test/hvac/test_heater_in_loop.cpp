// The fuel-fired water heater in the heating loop (src/hvac/aux_heater.hpp feeding
// src/cooling's convector volume, as the two participants are coupled): its heat lands in the
// heating loop, not the engine (conservation by parts with the valve to the engine shut and
// open), and it switches on its own sensor (the water reaching it; with the valve shut the loop's
// own water): the water stays inside the
// controller's band up to one step's rise, and with the band closed (on/off at one temperature)
// the water holds that temperature while the heater's mean power is the convectors' draw
// (energy balance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../cooling/support.hpp"
#include "common/units.hpp"
#include "cooling/cooling_model.hpp"
#include "hvac/aux_heater.hpp"
#include "support.hpp"

using namespace hbt;
using units::celsiusToK;
using units::rpmToRadps;

namespace {

constexpr double kDt = 0.1;  // both participants' macro step [s]

// The heater and the cooling stepped as the participants are: the heater decides on the loop's
// water as the cooling published it, its heat enters the cooling's next step.
struct Loop {
  cooling::CoolingModel cool;
  hvac::AuxHeater heater;
  cooling::CoolingInputs in;
  Loop(const cooling::CoolingParams& pc, const hvac::AuxHeaterParams& ph) : cool(pc), heater(ph) {}
  void step() {
    const cooling::CoolingOutputs& o = cool.outputs();
    const double T_s = hvac::AuxHeater::waterAtHeater(o.coolant_ht_T_K, o.convector_coolant_T_K,
                                                     o.heater_valve_open && o.heater_loop_flow_m3_s > 0.0);
    const hvac::AuxHeaterState& h = heater.step(kDt, T_s, in.cabin_heat_demand_W > 0);
    in.aux_heater_heat_W = h.heat_W;
    cool.step(kDt, in);
  }
  // Σ C (T - T_a) of the engine side (metal, oil, engine loop, radiator volume) [J]
  double engineSide(double Ta) const {
    const cooling::NetworkCapacities& C = cool.capacities();
    const cooling::CoolingOutputs& o = cool.outputs();
    return C.metal * (o.metal_T_K - Ta) + C.oil * (o.oil_T_K - Ta) + C.engine_loop * (o.coolant_ht_T_K - Ta) +
           C.radiator * (o.radiator_coolant_T_K - Ta);
  }
  double loop(double Ta) const { return cool.capacities().convector * (cool.outputs().convector_coolant_T_K - Ta); }
};

}  // namespace

// Cold bus at 0 degC, idling engine (8 kW), cabin asking 12 kW: the heater's heat warms the
// heating loop alone while its valve to the engine is shut (engine outlet below 40 degC); once
// the valve opens the loop's water exchanges with the engine loop, and what the cabin does not
// take flows on to the engine: loop and engine side each balance.
TEST(HeaterInLoop, HeatLandsInTheHeatingLoopAndFlowsToTheEngineOnlyThroughTheValve) {
  const cooling::CoolingParams pc = cooling::test::yamlParams();
  const hvac::AuxHeaterParams ph = hvac::test::yamlParams().aux_heater;
  Loop L(pc, ph);
  const double Ta = celsiusToK(0.0);
  L.cool.reset(Ta);
  L.in.ambient_T_K = Ta;
  L.in.engine_heat_W = 8e3;
  L.in.pump_speed_rad_s = rpmToRadps(700.0);
  L.in.cabin_from_hvac = true;
  L.in.cabin_T_K = celsiusToK(5.0);
  L.in.cabin_heat_demand_W = 12e3;
  double shut_s = 0.0, pump_J = 0.0;
  while (!L.cool.outputs().heater_valve_open && shut_s < 3000.0) {
    L.step();
    shut_s += kDt;
    const cooling::CoolingOutputs& o = L.cool.outputs();
    if (!o.heater_valve_open) {  // by parts: the loop holds the heater's heat less the cabin's,
      // the engine side its own heat less its surface loss
      ASSERT_EQ(o.heater_loop_flow_m3_s, 0.0);  // nothing exchanged with the engine loop
      ASSERT_EQ(o.electric_pump_power_W, o.aux_heater_heat_W > 0.0 ? pc.heater.electric_pump_power_W : 0.0);
      ASSERT_NEAR(L.loop(Ta), o.aux_heater_J - o.heater_J, 1e-9 * (o.aux_heater_J + 1.0));
      ASSERT_NEAR(L.engineSide(Ta), L.in.engine_heat_W * shut_s - o.surface_loss_J - o.radiator_ht_J,
                  1e-9 * L.in.engine_heat_W * shut_s);
    }
    pump_J += o.electric_pump_power_W * kDt;
  }
  const cooling::CoolingOutputs& o = L.cool.outputs();
  ASSERT_TRUE(o.heater_valve_open);
  const double engine_in = L.in.engine_heat_W * shut_s;
  EXPECT_GT(o.aux_heater_J, 0.0);
  EXPECT_GT(o.heater_J, 0.0);  // the cabin was heated before the engine's valve opened
  EXPECT_NEAR(o.electric_pump_energy_J, pump_J, 1e-9 * pump_J);
  std::printf("valve shut for %.1f s: heater %.0f kJ, cabin %.0f kJ, loop %.1f degC, engine outlet %.1f degC\n",
              shut_s, o.aux_heater_J / 1e3, o.heater_J / 1e3, units::kToCelsius(o.convector_coolant_T_K),
              units::kToCelsius(o.coolant_ht_T_K));
  // (the last step opened the valve: the totals still close)
  EXPECT_NEAR(L.loop(Ta) + L.engineSide(Ta),
              o.aux_heater_J + engine_in - o.heater_J - o.surface_loss_J - o.radiator_ht_J, 1e-9 * engine_in);
  // Valve open: 600 s more; what the loop lost to the engine = what the engine side gained
  // beyond its own heat.
  const double E_loop0 = L.loop(Ta), E_eng0 = L.engineSide(Ta);
  const double aux0 = o.aux_heater_J, cab0 = o.heater_J, surf0 = o.surface_loss_J, rad0 = o.radiator_ht_J;
  for (int k = 0; k < 6000; ++k) L.step();
  const double to_engine_by_loop = (o.aux_heater_J - aux0) - (o.heater_J - cab0) - (L.loop(Ta) - E_loop0);
  const double to_engine_by_engine =
      (L.engineSide(Ta) - E_eng0) - L.in.engine_heat_W * 600.0 + (o.surface_loss_J - surf0) + (o.radiator_ht_J - rad0);
  EXPECT_NEAR(to_engine_by_loop, to_engine_by_engine, 1e-9 * L.in.engine_heat_W * 600.0);
  EXPECT_GT(to_engine_by_loop, 0.0);  // the 30 kW heater's loop is hotter than the idling engine
  std::printf("valve open 600 s: %.0f kJ of the heater's heat flowed on to the engine\n", to_engine_by_loop / 1e3);
}

// Switching on its own sensor: the loop's water stays within [T_on, T_off] up to one step's rise
// or fall; with the band closed (T_on = T_off) the water holds T_off within one step's rise and
// the heater's mean power over whole cycles is the convectors' draw. Engine off and cold: the
// valve stays shut, the engine side untouched.
TEST(HeaterInLoop, SwitchesOnTheLoopWaterAndHoldsItInItsBand) {
  const cooling::CoolingParams pc = cooling::test::yamlParams();
  for (double band_K : {10.0, 0.0}) {
    hvac::AuxHeaterParams ph = hvac::test::yamlParams().aux_heater;
    ph.on_below_K = ph.off_above_K - band_K;
    Loop L(pc, ph);
    const double Ta = celsiusToK(0.0);
    L.cool.reset(Ta);
    L.in.ambient_T_K = Ta;
    L.in.cabin_from_hvac = true;
    L.in.cabin_T_K = celsiusToK(15.0);
    L.in.cabin_heat_demand_W = 12e3;
    const double C_v = L.cool.capacities().convector;
    const double rise_K = ph.heat_output_W * kDt / C_v;  // the most one step can move the water
    while (L.cool.outputs().convector_coolant_T_K < ph.on_below_K) L.step();
    double Tmin = 1e9, Tmax = 0.0;
    const cooling::CoolingOutputs& o = L.cool.outputs();
    const double aux0 = o.aux_heater_J, cab0 = o.heater_J, E0 = L.loop(Ta);
    int switches = 0;
    bool was_on = L.heater.state().on;
    for (int k = 0; k < 30000; ++k) {  // 3000 s
      L.step();
      Tmin = std::min(Tmin, o.convector_coolant_T_K);
      Tmax = std::max(Tmax, o.convector_coolant_T_K);
      switches += L.heater.state().on != was_on;
      was_on = L.heater.state().on;
      ASSERT_FALSE(o.heater_valve_open);
    }
    EXPECT_GT(switches, 10);
    EXPECT_GE(Tmin, ph.on_below_K - rise_K);
    EXPECT_LE(Tmax, ph.off_above_K + rise_K);
    const double heat = o.aux_heater_J - aux0, draw = o.heater_J - cab0;
    EXPECT_NEAR(heat - draw, L.loop(Ta) - E0, 1e-9 * heat);  // the loop's balance
    EXPECT_NEAR(draw / 3000.0, 12e3, 1e-6);                   // the cabin got its demand
    // mean heater power = the draw, up to the loop's stored change within the band (+ a step)
    EXPECT_NEAR(heat / 3000.0, 12e3, (band_K + 2.0 * rise_K) * C_v / 3000.0);
    EXPECT_NEAR(L.engineSide(Ta), 0.0, 1e-6);  // engine cold and off: nothing reached it
    std::printf("band %.0f K: loop water %.2f..%.2f degC, %d switches, mean heater %.0f W for a 12 kW draw\n",
                band_K, units::kToCelsius(Tmin), units::kToCelsius(Tmax), switches, heat / 3000.0);
  }
}
