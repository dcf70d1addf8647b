// Climate controller (src/hvac/climate_controller.hpp): with the demand delivered the cabin
// settles exactly on the heating set point in the cold and on the cooling set point in the heat;
// in the dead band it asks for nothing; heating and cooling are never asked together.
#include <gtest/gtest.h>

#include "hvac/cabin.hpp"
#include "hvac/climate_controller.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::hvac;

namespace {
double settle(double T_a, double gain_W, double T0) {
  const HvacParams p = test::yamlParams();
  Cabin cab(p.cabin, p.doors, p.air);
  ClimateController k(p.controller);
  cab.reset(T0);
  CabinInputs in;
  in.ambient_T_K = T_a;
  in.gain_W = gain_W;
  for (int i = 0; i < 100000; ++i) {
    const ClimateDemand d = k.demand(cab.temperature_K(), T_a, cab.conductance(in, cab.temperature_K()).total(), gain_W);
    in.heat_W = d.heating_W;
    in.cool_W = d.cooling_W;
    cab.step(0.1, in);
  }
  return cab.temperature_K();
}
}  // namespace

TEST(ClimateController, HoldsTheHeatingSetPointInTheCold) {
  EXPECT_NEAR(settle(273.15, 1300.0, 273.15), 293.15, 1e-6);
}

TEST(ClimateController, HoldsTheCoolingSetPointInTheHeat) {
  EXPECT_NEAR(settle(313.15, 2500.0, 313.15), 297.15, 1e-6);
}

TEST(ClimateController, NothingInTheDeadBandNeverBoth) {
  const HvacParams p = test::yamlParams();
  ClimateController k(p.controller);
  const ClimateDemand mid = k.demand(295.15, 295.15, 600.0, 0.0);  // ambient = cabin = mid band
  EXPECT_EQ(mid.heating_W, 0.0);
  EXPECT_EQ(mid.cooling_W, 0.0);
  for (double T = 260.0; T < 330.0; T += 0.5)
    for (double T_a = 250.0; T_a < 320.0; T_a += 2.5) {
      const ClimateDemand d = k.demand(T, T_a, 610.0, 1500.0);
      EXPECT_FALSE(d.heating_W > 0.0 && d.cooling_W > 0.0) << T << " " << T_a;
      EXPECT_LE(d.heating_W, p.controller.max_heating_W);
    }
}
