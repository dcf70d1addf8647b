// Passenger and solar gains (src/hvac/cabin_gains.hpp) against the VECTO SSM formulas by hand.
#include <gtest/gtest.h>

#include "common/errors.hpp"
#include "hvac/cabin_gains.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::hvac;

TEST(CabinGains, PassengersFromThePayloadAndTheirHeat) {
  const HvacParams p = test::yamlParams();
  CabinGains g(p.gains, p.cabin, 1500.0, "config/hvac.yaml");
  EXPECT_NEAR(g.persons(), 1500.0 / 68.0 + 1.0, 1e-12);
  EXPECT_NEAR(g.people_W(273.15), g.persons() * 50.0, 1e-9);   // below 17 degC
  EXPECT_NEAR(g.people_W(313.15), g.persons() * 80.0, 1e-9);   // above
  EXPECT_NEAR(g.people_W(290.15), g.persons() * 80.0, 1e-9);   // at the boundary: warm
  EXPECT_NEAR(CabinGains(p.gains, p.cabin, 0.0, "f").people_W(273.15), 50.0, 1e-12);  // the driver
}

TEST(CabinGains, SolarIsIrradianceTimesGlazingTimesFactors) {
  const HvacParams p = test::yamlParams();
  CabinGains g(p.gains, p.cabin, 1500.0, "config/hvac.yaml");
  EXPECT_NEAR(g.windowArea_m2(), 1.5 * 12.0 + 5.0, 1e-12);
  EXPECT_NEAR(g.solar_W(273.15), 30.0 * 23.0 * 1.0 * 0.65 * 0.25, 1e-9);    // 0 degC: 30 W/m^2
  EXPECT_NEAR(g.solar_W(313.15), 150.0 * 23.0 * 1.0 * 0.8 * 0.25, 1e-9);    // 40 degC: held at 150
  EXPECT_NEAR(g.solar_W(298.15), 145.0 * 23.0 * 0.8 * 0.25, 1e-9);          // 25 degC: interpolated
}

TEST(CabinGains, BadPayloadAndTableNamed) {
  HvacParams p = test::yamlParams();
  EXPECT_THROW(CabinGains(p.gains, p.cabin, -1.0, "f"), InputError);
  p.gains.solar_ambient_K = {300.0, 290.0};
  p.gains.solar_irradiance_W_m2 = {1.0, 2.0};
  try {
    CabinGains(p.gains, p.cabin, 0.0, "config/hvac.yaml");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gains/solar_ambient_K"), std::string::npos) << e.what();
  }
}
