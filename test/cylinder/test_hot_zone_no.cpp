// Hot-zone NO (hot_zone_no.hpp): its flame temperature against the energy balance and a published
// adiabatic flame temperature, the limits of the residence time, the exact solution of the
// Zeldovich ODE at constant temperature, and the rig's response to the charge-air temperature.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cylinder/hot_zone_no.hpp"
#include "cylinder/rig.hpp"
#include "support.hpp"

using namespace hbt::cylinder;

namespace {
constexpr double kNoMin_K = 0.0;  // no temperature cut in the unit checks
}  // namespace

TEST(HotZoneNO, FrozenFlameTemperatureClosesTheEnergyBalance) {
  // m_p h_B(T_f) = h_F(T_u) + LHV + h_fg + a_A h_A(T_u) + a_R h_B(T_u), recomputed here; residual
  // gas in the charge (y_air < 1) dilutes and cools the flame.
  GasThermo th;
  HotZoneNO hz(th);
  for (double y_air : {1.0, 0.95, 0.8}) {
    const double T_u = 850.0, T_f = hz.frozenFlameTemperature_K(T_u, y_air);
    const double a_A = th.afrStoich(), a_R = a_A * (1 / y_air - 1);
    const double H = th.group(kFuelVap).h(T_u) + th.fuel().lhv_J_kg + th.fuel().hfg_J_kg +
                     a_A * th.group(kAir).h(T_u) + a_R * th.group(kBurned).h(T_u);
    EXPECT_NEAR((1 + a_A + a_R) * th.group(kBurned).h(T_f) / H, 1.0, 1e-10) << y_air;
  }
  EXPECT_LT(hz.frozenFlameTemperature_K(850.0, 0.95), hz.frozenFlameTemperature_K(850.0, 1.0) - 30.0);
  EXPECT_TRUE(std::isnan(hz.frozenFlameTemperature_K(850.0, 0.0)));
}

TEST(HotZoneNO, StoichiometricFlameTemperatureAgainstPublished) {
  // Fuel vapour and air at 298 K, 1 atm: dissociated adiabatic flame temperature 2289 K for
  // n-dodecane / air (Turns, "An Introduction to Combustion", Table B.1); the surrogate
  // C12H22.3 is within a few kelvin of it (flame_temperature README table: 2283 K).
  GasThermo th;
  HotZoneNO hz(th);
  HotZoneNO::Packet k;
  ASSERT_GE(hz.noMoles(1e-6, 298.15, 1.0, 101325.0, 1e-4, kNoMin_K, &k), 0.0);
  EXPECT_NEAR(k.T_K, 2289.0, 15.0);
  EXPECT_GT(k.T_frozen_K - k.T_K, 100.0);  // dissociation matters at 1 atm, stoichiometric
}

TEST(HotZoneNO, ResidenceTimeLimits) {
  // τ = 0: no NO. τ ≫ τ_NO: the equilibrium NO of the stoichiometric zone, which also satisfies
  // ½N2 + ½O2 ⇌ NO with the zone's own N2 and O2: x_NO = K_p (x_N2 x_O2)^½ (Δn = 0).
  GasThermo th;
  HotZoneNO hz(th);
  HotZoneNO::Packet k;
  EXPECT_EQ(hz.noMoles(1e-6, 850.0, 0.97, 100e5, 0.0, kNoMin_K, &k), 0.0);
  const double n = hz.noMoles(1e-6, 850.0, 0.97, 100e5, 0.1, kNoMin_K, &k);
  EXPECT_NEAR(k.no_mol_m3 / k.no_eq_mol_m3, 1.0, 1e-3);
  const ZeldovichNO& z = hz.zeldovich();
  const double T = k.T_K;
  const double Kp = std::exp(-(gRT(kNO, T) - 0.5 * gRT(kN2, T) - 0.5 * gRT(kO2, T)));
  EXPECT_NEAR(z.conc(kNO) / (Kp * std::sqrt(z.conc(kN2) * z.conc(kO2))), 1.0, 1e-6);
  // moles = [NO] · volume of the packet's products
  EXPECT_NEAR(n / (k.no_mol_m3 * k.volume_m3_kg * k.products_kg_kg * 1e-6), 1.0, 1e-12);
  // a cold packet (below the NO threshold) forms none
  EXPECT_EQ(hz.noMoles(1e-6, 850.0, 0.97, 100e5, 1e-3, 3000.0, &k), 0.0);
}

TEST(HotZoneNO, ClosedFormMatchesIntegratedZeldovichKinetics) {
  // The packet's [NO](τ) (closed form, N quasi-steady) against CVODE integrating the extended
  // Zeldovich mechanism (zeldovich.hpp, N kinetic) from [NO] = 0 at the same T, p and
  // equilibrium, at 0.1, 0.5 and 2 characteristic times τ_NO = [NO]_e/(2 R1), for a hot and a
  // cooler packet (charge 970 / 850 K at 100 bar) and a low-pressure one (850 K, 40 bar).
  struct Case { double T_u_K, p_Pa; };
  for (const Case& c : {Case{970.0, 100e5}, Case{850.0, 100e5}, Case{850.0, 40e5}}) {
    GasThermo th;
    HotZoneNO hz(th);
    HotZoneNO::Packet k;
    hz.noMoles(1e-6, c.T_u_K, 0.97, c.p_Pa, 1e-6, kNoMin_K, &k);
    const ZeldovichNO& z = hz.zeldovich();
    const double tau_NO = k.no_eq_mol_m3 / (2 * z.k1f() * z.conc(kO) * z.conc(kN2));
    double x[kNumSpecies];
    for (int s = 0; s < kNumSpecies; ++s) x[s] = z.conc(Species(s)) / (c.p_Pa / (kRu * k.T_K));
    ZeldovichNO ref;
    ref.setRelativeTolerance(1e-9);
    ref.setConditions(k.T_K, c.p_Pa, x);
    std::printf("[hot-zone] charge %.0f K, %.0f bar: T_f %.1f K, T_hz %.1f K, [NO]e %.4g mol/m3, "
                "tau_NO %.3g ms\n", c.T_u_K, c.p_Pa * 1e-5, k.T_frozen_K, k.T_K, k.no_eq_mol_m3,
                tau_NO * 1e3);
    for (double f : {0.1, 0.5, 2.0}) {
      hz.noMoles(1e-6, c.T_u_K, 0.97, c.p_Pa, f * tau_NO, kNoMin_K, &k);
      double cNO = 0.0, cN = 0.0;
      ref.integrate(f * tau_NO, cNO, cN, true);
      EXPECT_NEAR(k.no_mol_m3 / cNO, 1.0, 5e-3) << c.T_u_K << " K " << f << " tau_NO";
    }
  }
}

TEST(HotZoneNO, RigSensitivityToChargeAirTemperature) {
  // d ln(NOx)/dT_intake at fixed intake pressure, fuel and injection (rig: 1400 rpm, 64 mg,
  // ~50 % load, λ ≈ 2.4, fuel/air ≈ 0.03), intake 310 / 330 K, with the shipped hot-zone model.
  // Published: the NOx intake-temperature correction of the heavy-duty test procedures, fitted to
  // the engines of SAE 730213 (Ethyl Corp. for AMA/EMA, 1973): +0.54 %/K at fuel/air 0.02,
  // +0.33 %/K at 0.03, 0 at 0.045 (src/engine_1d/NOX.md: coefficients as recalled, not
  // re-verified). Asserted: 0 < s < 1.0 %/K, and below half of the lean burned-zone model's.
  // Measured: hot zone 0.68 %/K (~2x the published value at this fuel/air, the residual
  // discussed in NOX.md), burned zone 1.45 %/K.
  auto sensitivity = [](bool hot_zone, double& nox_mid_kg) {
    RigParams rp;
    CylinderParams cp = test::loadParams(&rp);
    cp.nox_hot_zone = hot_zone;
    return test::rigNoxSensitivityToIntake(cp, rp, nox_mid_kg);
  };
  double nox_h = 0.0, nox_b = 0.0;
  const double s_h = sensitivity(true, nox_h), s_b = sensitivity(false, nox_b);
  std::printf("[nox-dT] hot zone %.3f mg, %.2f %%/K; burned zone %.3f mg, %.2f %%/K\n",
              nox_h * 1e6, 100 * s_h, nox_b * 1e6, 100 * s_b);
  EXPECT_GT(s_h, 0.0);
  EXPECT_LT(s_h, 0.010);
  EXPECT_LT(s_h, 0.5 * s_b);
}
