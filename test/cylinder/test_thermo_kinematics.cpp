// Thermodynamic data, slider-crank kinematics and the parameter file.
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"
#include "cylinder/thermo.hpp"
#include "support.hpp"
#include "../common/input_errors.hpp"

using namespace hbt::cylinder;

TEST(Thermo, SpeciesDataMatchJanafAt298K) {
  // NIST-JANAF tables (Chase 1998): cp [J/mol K], Δf H° [kJ/mol], S° [J/mol K] at 298.15 K.
  const double T = 298.15;
  EXPECT_NEAR(cpR(kN2, T) * kRu, 29.124, 0.1);
  EXPECT_NEAR(cpR(kO2, T) * kRu, 29.376, 0.1);
  EXPECT_NEAR(cpR(kCO2, T) * kRu, 37.135, 0.1);
  EXPECT_NEAR(cpR(kH2O, T) * kRu, 33.590, 0.1);
  EXPECT_NEAR(hRT(kH2O, T) * kRu * T * 1e-3, -241.826, 0.05);
  EXPECT_NEAR(hRT(kCO2, T) * kRu * T * 1e-3, -393.522, 0.05);
  EXPECT_NEAR(hRT(kO, T) * kRu * T * 1e-3, 249.175, 0.1);
  EXPECT_NEAR(hRT(kN, T) * kRu * T * 1e-3, 472.683, 0.1);
  EXPECT_NEAR(sR(kN2, T) * kRu, 191.609, 0.15);
  EXPECT_NEAR(sR(kNO, T) * kRu, 210.758, 0.15);
  EXPECT_NEAR(sR(kO, T) * kRu, 161.059, 0.15);
  // The two polynomial ranges join continuously at 1000 K.
  for (int s = 0; s < kNumSpecies; ++s) {
    EXPECT_NEAR(cpR(Species(s), 1000.0 - 1e-9), cpR(Species(s), 1000.0), 1e-5);
    EXPECT_NEAR(hRT(Species(s), 1000.0 - 1e-9), hRT(Species(s), 1000.0), 1e-5);
  }
}

TEST(Thermo, AirAndFuelProperties) {
  const GasThermo th;
  // Dry air: R = 287.05 J/(kg K), cp(300 K) = 1005 J/(kg K) (textbook values).
  EXPECT_NEAR(th.group(kAir).R, 287.05, 0.1);
  EXPECT_NEAR(th.group(kAir).cp(300.0), 1005.0, 4.0);
  EXPECT_NEAR(th.group(kAir).h(kTref), 0.0, 1e-6);
  // Diesel stoichiometric air/fuel ratio 14.5–14.6 (SPEC §3; EN 590 13.5 wt-% H).
  EXPECT_GT(th.afrStoich(), 14.5);
  EXPECT_LT(th.afrStoich(), 14.6);
  // Burned-gas composition: carbon mass of the products = carbon of fuel + air CO2.
  const double afr = th.afrStoich();
  const double C_prod = th.elements(kBurned)[0] * (1 + afr);
  const double C_in = th.elements(kFuelVap)[0] + afr * th.elements(kAir)[0];
  EXPECT_NEAR(C_prod, C_in, 1e-9 * C_in);
  const double O_prod = th.elements(kBurned)[2] * (1 + afr);
  EXPECT_NEAR(O_prod, afr * th.elements(kAir)[2], 1e-9 * O_prod);
}

TEST(Thermo, TemperatureFromInternalEnergyInvertsU) {
  const GasThermo th;
  const double m[kNumGroups] = {2.0e-3, 0.05e-3, 0.4e-3};
  const Poly P = mixturePoly(th, m);
  for (double T : {250.0, 800.0, 999.9, 1000.1, 2400.0, 3200.0}) {
    const double U = P.u(T);
    EXPECT_NEAR(temperatureFromU(P, U, 1500.0), T, 1e-7 * T);
  }
}

TEST(Kinematics, SliderCrankVolumes) {
  const SliderCrank k;
  const double Ap = M_PI / 4 * 0.104 * 0.104;
  EXPECT_NEAR(k.displacement(), Ap * 0.132, 1e-12);
  EXPECT_NEAR(6 * k.displacement(), 6.72e-3, 0.01e-3);  // SPEC: 6.72 L
  EXPECT_NEAR(k.volume(0.0), k.clearanceVolume(), 1e-15);
  EXPECT_NEAR(k.volume(M_PI) / k.volume(0.0), 16.8, 1e-9);
  // Hand calculation at 90 deg: s = r + l − sqrt(l² − r²).
  const double r = 0.066, l = 0.195;
  EXPECT_NEAR(k.travel(M_PI / 2), r + l - std::sqrt(l * l - r * r), 1e-12);
  for (double th : {-2.5, -1.0, 0.3, 1.7, 3.0}) {  // dV/dθ against a central difference
    const double h = 1e-6;
    EXPECT_NEAR(k.dVdtheta(th), (k.volume(th + h) - k.volume(th - h)) / (2 * h), 1e-12);
  }
  EXPECT_NEAR(k.meanPistonSpeed(1400 * M_PI / 30), 2 * 0.132 * 1400 / 60.0, 1e-12);
}

TEST(Params, ConfigFileLoadsAndBadKeysAreNamed) {
  RigParams rp;
  const CylinderParams cp = test::loadParams(&rp);
  EXPECT_DOUBLE_EQ(cp.geometry.bore_m, 0.104);
  EXPECT_EQ(cp.nozzle.holes, 8);
  EXPECT_DOUBLE_EQ(cp.soi_main(1400, 0.5), 2.0);  // NOx-calibrated map: 2 deg aTDC
  EXPECT_DOUBLE_EQ(cp.rail_pressure(1200, 0.5), 0.5 * (1000 + 1300));  // bilinear
  EXPECT_DOUBLE_EQ(rp.speed_rpm, 1400.0);
  // A misspelt key and a table of the wrong size are rejected with file and key.
  hbt::ParamSource src = hbt::parseYamlParams("cylinder:\n  geometry:\n    bore_mm: 104\n", "x.yaml");
  CylinderParams c2;
  hbt::ParamSet ps;
  c2.declare(ps);
  hbt::testing::expectInputError([&] { hbt::applyParams(ps, src); }, "x.yaml", "cylinder/geometry/bore_mm");
  src = hbt::parseYamlParams("cylinder:\n  injection:\n    soi_main_deg: [1, 2,\n      3]\n", "y.yaml");
  hbt::applyParams(ps, src);
  hbt::testing::expectInputError([&] { c2.finalize("y.yaml"); }, "y.yaml", "cylinder/injection/soi_main_deg");
}
