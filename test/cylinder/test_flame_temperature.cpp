// Hot-zone temperature with dissociation (flame_temperature.hpp) against a published adiabatic
// flame temperature, the frozen limit, enthalpy conservation and the damped sensitivity.
#include <gtest/gtest.h>

#include <cmath>

#include "cylinder/flame_temperature.hpp"

using namespace hbt::cylinder;

namespace {

// Products of 1 kg of fuel vapour burned with λ·AFR_st air, frozen (groups of thermo.hpp).
struct Products {
  double mB = 0, mA = 0;  // kg of stoichiometric products and of excess air per kg fuel
  std::array<double, 5> b{};
  double Y[kNumSpecies] = {};
};
Products products(const GasThermo& th, double lambda) {
  Products P;
  const double afr = th.afrStoich();
  P.mB = 1 + afr;
  P.mA = (lambda - 1) * afr;
  const double m = P.mB + P.mA;
  for (int e = 0; e < 5; ++e)
    P.b[e] = (P.mB * th.elements(kBurned)[e] + P.mA * th.elements(kAir)[e]) / m;
  for (int s = 0; s < kNumSpecies; ++s)
    P.Y[s] = (P.mB * th.massFraction(kBurned, Species(s)) + P.mA * th.massFraction(kAir, Species(s))) / m;
  return P;
}

// Frozen adiabatic flame temperature of fuel vapour + air at T_u [K] (the cylinder's energy
// balance: the products' sensible enthalpy = LHV_vap + sensible enthalpy of the reactants).
double frozenFlameTemperature(const GasThermo& th, const Products& P, double lambda, double Tu) {
  const FuelSpec& f = th.fuel();
  const double H = f.lhv_J_kg + f.hfg_J_kg + th.group(kFuelVap).h(Tu) +
                   lambda * th.afrStoich() * th.group(kAir).h(Tu);
  double T = 2000.0;
  for (int i = 0; i < 50; ++i) {
    const double F = P.mB * th.group(kBurned).h(T) + P.mA * th.group(kAir).h(T) - H;
    T -= F / (P.mB * th.group(kBurned).cp(T) + P.mA * th.group(kAir).cp(T));
  }
  return T;
}

}  // namespace

TEST(DissociatedFlame, StoichiometricDieselAirAtOneBarAgainstPublishedValue) {
  // Published: adiabatic flame temperature of stoichiometric n-dodecane / air at 1 atm and
  // 298 K, products in equilibrium: 2289 K (Turns, "An Introduction to Combustion", Table B.1;
  // heavier kerosene/diesel surrogates within ~20 K). Without dissociation the same energy
  // balance gives ~2400 K and more.
  const GasThermo th;
  const Products P = products(th, 1.0);
  const double Tf = frozenFlameTemperature(th, P, 1.0, 298.15);
  DissociatedFlame flame;
  DissociatedFlame::Result r;
  ASSERT_TRUE(flame.solve(P.b, P.Y, Tf, 1.01325e5, r));
  EXPECT_GT(Tf, 2380.0);
  EXPECT_NEAR(r.T_K, 2300.0, 40.0) << "frozen " << Tf;
  EXPECT_GT(Tf - r.T_K, 70.0);
  EXPECT_LE(flame.lastEquilibriumSolves(), 8);
  // Enthalpy conserved by the solve (formation included, NO counted as ½N2 + ½O2):
  // h_eq(T_eq) = h_f(T_f).
  const double hf = frozenEnthalpy_J_kg(P.Y, Tf);
  const double T = r.T_K;
  const double dh_NO = r.n_mol_kg * r.x[kNO] * kRu * T *
                       (hRT(kNO, T) - 0.5 * hRT(kN2, T) - 0.5 * hRT(kO2, T));
  EXPECT_NEAR(mixtureEnthalpy_J_kg(r.n_mol_kg, r.x, T) - dh_NO, hf, 1e-6 * std::fabs(hf) + 50.0);
  std::printf("stoich 1 bar 298 K: T_frozen %.1f K, T_dissociated %.1f K (%d equilibrium solves)\n",
              Tf, T, flame.lastEquilibriumSolves());
}

TEST(DissociatedFlame, ColdProductsEqualTheFrozenTemperature) {
  // Limit case: at 1200 K dissociation is negligible (T_eq = T_f within 0.05 K), at 1500 K and
  // 100 bar below 0.5 K (measured 0.2 K at λ = 1).
  const GasThermo th;
  DissociatedFlame flame;
  DissociatedFlame::Result r;
  for (double lambda : {1.0, 1.5, 3.0}) {
    const Products P = products(th, lambda);
    ASSERT_TRUE(flame.solve(P.b, P.Y, 1200.0, 1e5, r));
    EXPECT_NEAR(r.T_K, 1200.0, 0.05) << lambda;
    ASSERT_TRUE(flame.solve(P.b, P.Y, 1500.0, 100e5, r));
    EXPECT_NEAR(r.T_K, 1500.0, 0.5) << lambda;
  }
}

TEST(DissociatedFlame, PressureSuppressesAndLeanMixtureReducesDissociation) {
  const GasThermo th;
  DissociatedFlame flame;
  DissociatedFlame::Result r;
  const Products st = products(th, 1.0), lean = products(th, 1.5);
  ASSERT_TRUE(flame.solve(st.b, st.Y, 2800.0, 1e5, r));
  const double d1 = 2800.0 - r.T_K;
  ASSERT_TRUE(flame.solve(st.b, st.Y, 2800.0, 100e5, r));
  const double d100 = 2800.0 - r.T_K;
  ASSERT_TRUE(flame.solve(lean.b, lean.Y, 2800.0, 100e5, r));
  const double d100lean = 2800.0 - r.T_K;
  EXPECT_GT(d1, d100);         // Le Chatelier
  EXPECT_GT(d100, 0.0);
  EXPECT_GT(d100, d100lean);   // excess O2 shifts CO2 ⇌ CO + ½O2 back
}

TEST(DissociatedFlame, SensitivityToUnburnedTemperatureIsDamped) {
  // dT_eq/dT_u < dT_f/dT_u: stoichiometric diesel flame at 100 bar from a compressed charge
  // of 850 vs 900 K (a 20 K warmer intake gives ~50 K at TDC).
  const GasThermo th;
  const Products P = products(th, 1.0);
  DissociatedFlame flame;
  DissociatedFlame::Result r;
  const double Tf1 = frozenFlameTemperature(th, P, 1.0, 850.0);
  const double Tf2 = frozenFlameTemperature(th, P, 1.0, 900.0);
  ASSERT_TRUE(flame.solve(P.b, P.Y, Tf1, 100e5, r));
  const double Te1 = r.T_K;
  ASSERT_TRUE(flame.solve(P.b, P.Y, Tf2, 100e5, r));
  const double Te2 = r.T_K;
  const double damping = (Te2 - Te1) / (Tf2 - Tf1);
  EXPECT_LT(damping, 0.9);
  EXPECT_GT(damping, 0.3);
  std::printf("stoich 100 bar: T_f %.1f/%.1f K, T_eq %.1f/%.1f K, dT_eq/dT_f %.3f\n", Tf1, Tf2,
              Te1, Te2, damping);
}

TEST(DissociatedFlame, BadInputIsRejected) {
  const GasThermo th;
  const Products P = products(th, 1.0);
  DissociatedFlame flame;
  DissociatedFlame::Result r;
  EXPECT_FALSE(flame.solve(P.b, P.Y, std::nan(""), 1e5, r));
  EXPECT_FALSE(flame.solve(P.b, P.Y, 2000.0, -1.0, r));
}
