// The example participant's model (trip_computer.hpp) against its definitions: the fuel volume
// of units::dieselLitres, the consumption hidden below the minimum distance and shown from it,
// standstill idling accumulated only while the bus stands with the crank turning.
#include <gtest/gtest.h>

#include "common/units.hpp"
#include "example_participant/trip_computer.hpp"

using namespace hbt;
using namespace hbt::example;

TEST(TripComputer, FuelVolumeAndConsumptionFromTheirDefinitions) {
  TripComputerParams p;
  TripComputer tc(p);
  TripInputs in;
  in.fuel_mass_kg = 0.4175;  // 0.5 L at 835 kg/m^3
  in.distance_m = 999.0;     // below 1 km: not shown
  in.vehicle_speed_m_s = 10.0;
  in.engine_speed_rad_s = 120.0;
  tc.update(0.1, in);
  EXPECT_NEAR(tc.outputs().fuel_l, 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(tc.outputs().fuel_l, units::dieselLitres(0.4175));
  EXPECT_FALSE(tc.outputs().shown);
  EXPECT_EQ(tc.outputs().consumption_l_100km, 0.0);
  in.distance_m = 1000.0;  // exactly the threshold: shown, 0.5 L over 1 km = 50 L/100 km
  tc.update(0.1, in);
  EXPECT_TRUE(tc.outputs().shown);
  EXPECT_NEAR(tc.outputs().consumption_l_100km, 50.0, 1e-9);
  EXPECT_DOUBLE_EQ(tc.outputs().distance_km, 1.0);
}

TEST(TripComputer, StandstillIdlingCountsOnlyStandingWithTheCrankTurning) {
  TripComputer tc(TripComputerParams{});
  TripInputs in;
  in.engine_speed_rad_s = 73.3;  // idle
  for (int k = 0; k < 25; ++k) tc.update(0.1, in);
  EXPECT_NEAR(tc.outputs().standstill_idle_s, 2.5, 1e-12);
  in.engine_speed_rad_s = 0.0;  // engine stopped (stop-start): no idling
  tc.update(0.1, in);
  EXPECT_EQ(tc.outputs().standstill_idle_s, 0.0);
  in.engine_speed_rad_s = 73.3;
  in.vehicle_speed_m_s = 0.5;  // moving
  tc.update(0.1, in);
  EXPECT_EQ(tc.outputs().standstill_idle_s, 0.0);
}
