// Equilibrium composition and extended-Zeldovich NO kinetics (CVODE).
#include <gtest/gtest.h>

#include <cmath>

#include "cylinder/equilibrium.hpp"
#include "cylinder/zeldovich.hpp"

using namespace hbt::cylinder;

namespace {
// Element moles per kg of the products of diesel burned at air excess λ (groups of thermo.hpp).
std::array<double, 5> productElements(const GasThermo& th, double lambda) {
  const double afr = th.afrStoich();
  const double mB = 1 + afr, mA = (lambda - 1) * afr;
  std::array<double, 5> b{};
  for (int e = 0; e < 5; ++e)
    b[e] = (mB * th.elements(kBurned)[e] + mA * th.elements(kAir)[e]) / (mB + mA);
  return b;
}
double dfG_kJ(Species s, Species ref1, double n1, Species ref2, double n2, double T) {
  return (gRT(s, T) - n1 * gRT(ref1, T) - n2 * gRT(ref2, T)) * kRu * T * 1e-3;
}
}  // namespace

TEST(Equilibrium, GibbsDataAgainstJanaf) {
  // NIST-JANAF Δf G° [kJ/mol]: O 231.736 (298.15 K), 121.552 (2000 K); NO 86.600 and 64.855.
  // (GRI data use Δf H°(NO) = 91.27 kJ/mol, the newer ATcT value, ~1 kJ/mol above JANAF.)
  EXPECT_NEAR(dfG_kJ(kO, kO2, 0.5, kN2, 0.0, 298.15), 231.736, 0.05);
  EXPECT_NEAR(dfG_kJ(kO, kO2, 0.5, kN2, 0.0, 2000.0), 121.552, 0.1);
  EXPECT_NEAR(dfG_kJ(kNO, kO2, 0.5, kN2, 0.5, 298.15), 86.600, 1.5);
  EXPECT_NEAR(dfG_kJ(kNO, kO2, 0.5, kN2, 0.5, 2000.0), 64.855, 1.5);
}

TEST(Equilibrium, ConservesElementsAndSatisfiesEveryReaction) {
  const GasThermo th;
  Equilibrium eq;
  for (double lambda : {1.0, 1.4, 2.5}) {
    for (double T : {1600.0, 2300.0, 2900.0}) {
      const double p = 80e5;
      const auto b = productElements(th, lambda);
      double x[kNumSpecies];
      ASSERT_TRUE(eq.solve(b, T, p, x)) << lambda << " " << T;
      double sum = 0, n_mix;
      for (int s = 0; s < kNumSpecies; ++s) sum += x[s];
      EXPECT_NEAR(sum, 1.0, 1e-10);
      n_mix = b[4] / x[kAr];  // mol of mixture per kg
      const double C = n_mix * (x[kCO2] + x[kCO]);
      const double H = n_mix * (2 * x[kH2O] + 2 * x[kH2] + x[kOH] + x[kH]);
      const double O = n_mix * (2 * x[kCO2] + x[kCO] + x[kH2O] + x[kOH] + 2 * x[kO2] + x[kO] + x[kNO]);
      const double N = n_mix * (2 * x[kN2] + x[kN] + x[kNO]);
      EXPECT_NEAR(C, b[0], 1e-9 * b[0]);
      EXPECT_NEAR(H, b[1], 1e-9 * b[1]);
      EXPECT_NEAR(O, b[2], 1e-9 * b[2]);
      EXPECT_NEAR(N, b[3], 1e-9 * b[3]);
      // Law of mass action for ½N2 + ½O2 ⇌ NO and CO + ½O2 ⇌ CO2 (written independently).
      const double P = p / kPref;
      const double K_NO = std::exp(-(gRT(kNO, T) - 0.5 * gRT(kN2, T) - 0.5 * gRT(kO2, T)));
      EXPECT_NEAR(x[kNO] / std::sqrt(x[kN2] * x[kO2]), K_NO, 1e-8 * K_NO);
      const double K_CO2 = std::exp(-(gRT(kCO2, T) - gRT(kCO, T) - 0.5 * gRT(kO2, T)));
      EXPECT_NEAR(x[kCO2] / (x[kCO] * std::sqrt(x[kO2] * P)), K_CO2, 1e-7 * K_CO2);
    }
  }
}

TEST(Equilibrium, DissociationTrends) {
  const GasThermo th;
  Equilibrium eq;
  const auto b = productElements(th, 1.0);
  double lo[kNumSpecies], hi[kNumSpecies], hp[kNumSpecies];
  ASSERT_TRUE(eq.solve(b, 2200.0, 1e5, lo));
  ASSERT_TRUE(eq.solve(b, 2800.0, 1e5, hi));
  ASSERT_TRUE(eq.solve(b, 2800.0, 100e5, hp));
  EXPECT_GT(hi[kCO], 5 * lo[kCO]);   // more dissociation when hotter
  EXPECT_LT(hp[kCO], hi[kCO]);       // less at high pressure (Le Chatelier)
  EXPECT_GT(hi[kO], 10 * lo[kO]);
  // Pure air at 2000 K, 1 bar: x_NO = K_NO sqrt(x_N2 x_O2) ≈ 0.8 % (textbook order of magnitude).
  std::array<double, 5> air = th.elements(kAir);
  double xa[kNumSpecies];
  ASSERT_TRUE(eq.solve(air, 2000.0, 1e5, xa));
  EXPECT_NEAR(xa[kNO], 0.0075, 0.0015);
  EXPECT_EQ(xa[kCO2] > 0, true);
}

class ZeldovichTest : public ::testing::Test {
 protected:
  void setAt(double T, double p, double lambda) {
    const auto b = productElements(th, lambda);
    ASSERT_TRUE(eq.solve(b, T, p, x));
    z.setConditions(T, p, x);
  }
  GasThermo th;
  Equilibrium eq;
  ZeldovichNO z;
  double x[kNumSpecies];
};

TEST_F(ZeldovichTest, RelaxesToEquilibriumNO) {
  setAt(2600.0, 80e5, 1.2);
  double NO = 0.0, N = 0.0;
  for (int i = 0; i < 50; ++i) z.integrate(1e-3, NO, N, i == 0);  // 50 ms, re-initialised
  EXPECT_NEAR(NO / z.equilibriumNO(), 1.0, 1e-4);
  EXPECT_NEAR(z.equilibriumNO(), x[kNO] * 80e5 / (kRu * 2600.0), 1e-12);
  // From above (super-equilibrium NO, as in the expansion stroke) it decomposes to the same value.
  NO = 3.0 * z.equilibriumNO();
  for (int i = 0; i < 50; ++i) z.integrate(1e-3, NO, N, i == 0);
  EXPECT_NEAR(NO / z.equilibriumNO(), 1.0, 1e-4);
}

TEST_F(ZeldovichTest, InitialRateIsTwiceK1fOxygenNitrogen) {
  setAt(2400.0, 60e5, 1.3);
  // Start with no NO and no N: after N has reached its quasi-steady level (~ns) the NO formation
  // rate is the classical d[NO]/dt = 2 k1f [O]e [N2]e (Heywood eq. 11.9).
  double NO = 0.0, N = 0.0;
  z.integrate(0.5e-6, NO, N, false);
  const double NO1 = NO;
  z.integrate(1.0e-6, NO, N, false);
  const double rate = (NO - NO1) / 1.0e-6;
  const double k1f = 7.6e7 * std::exp(-38000.0 / 2400.0);  // Heywood, m³/(mol s)
  const double c = 60e5 / (kRu * 2400.0);
  const double expect = 2.0 * k1f * x[kO] * c * x[kN2] * c;
  EXPECT_NEAR(rate / expect, 1.0, 2e-3);
  EXPECT_LT(NO, 1e-3 * z.equilibriumNO());  // still far from equilibrium
}

TEST_F(ZeldovichTest, NORisesSteeplyWithTemperature) {
  double formed[3];
  const double T[3] = {2200.0, 2400.0, 2600.0};
  for (int i = 0; i < 3; ++i) {
    setAt(T[i], 80e5, 1.2);
    double NO = 0.0, N = 0.0;
    z.integrate(0.5e-3, NO, N, true);
    formed[i] = NO;
  }
  // Each +200 K multiplies the NO formed in 0.5 ms by more than 4 (activation 38 000 K plus the
  // temperature dependence of [O]e), approaching the equilibrium cap only at the hottest point.
  EXPECT_GT(formed[1], 4.0 * formed[0]);
  EXPECT_GT(formed[2], 2.5 * formed[1]);
  EXPECT_GT(formed[2], 30.0 * formed[0]);
}
