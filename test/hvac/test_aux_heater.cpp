// Fuel-fired heater (src/hvac/aux_heater.hpp): its fuel against its energy balance
// (m_f LHV η = Q), its electric energy, and its controller's coolant hysteresis.
#include <gtest/gtest.h>

#include "hvac/aux_heater.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::hvac;

TEST(AuxHeater, FuelTimesLhvTimesEfficiencyIsTheHeat) {
  const HvacParams p = test::yamlParams();
  AuxHeater h(p.aux_heater);
  double T = 273.15;
  for (int i = 0; i < 36000; ++i) {  // an hour, the coolant cycling 0..90 degC
    T = 273.15 + 90.0 * ((i % 6000) / 6000.0);
    h.step(0.1, T, true);
  }
  const AuxHeaterState& s = h.state();
  EXPECT_GT(s.heat_J, 0.0);
  EXPECT_NEAR(s.fuel_kg * units::kDieselLhv_J_kg * p.aux_heater.efficiency, s.heat_J, 1e-12 * s.heat_J);
  EXPECT_NEAR(s.electric_J / p.aux_heater.electric_power_W, s.heat_J / p.aux_heater.heat_output_W, 1e-9);
  // The data-sheet point: 30 kW for one hour burns 3.7 L (0.835 kg/L) within 1 %.
  AuxHeater one(p.aux_heater);
  for (int i = 0; i < 36000; ++i) one.step(0.1, 280.0, true);
  EXPECT_NEAR(one.state().fuel_kg / 0.835, 3.7, 0.037);
}

TEST(AuxHeater, CoolantHysteresisAndDemand) {
  const HvacParams p = test::yamlParams();
  AuxHeater h(p.aux_heater);
  EXPECT_TRUE(h.step(0.1, 300.0, true).on);          // cold coolant, demand: on
  EXPECT_TRUE(h.step(0.1, 348.15, true).on);         // 75 degC: stays on (in the band)
  EXPECT_FALSE(h.step(0.1, 353.25, true).on);        // above 80 degC: off
  EXPECT_FALSE(h.step(0.1, 348.15, true).on);        // 75 degC: stays off
  EXPECT_TRUE(h.step(0.1, 343.0, true).on);          // below 70 degC: on again
  EXPECT_FALSE(h.step(0.1, 300.0, false).on);        // no demand: off
  EXPECT_EQ(h.state().heat_W, 0.0);
  EXPECT_EQ(h.state().fuel_kg_s, 0.0);
  EXPECT_EQ(h.state().electric_W, 0.0);
}
