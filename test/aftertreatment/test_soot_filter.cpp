// SootFilter (DPF soot, NO2 passive regeneration) against a hand calculation of the published
// rate law, the plug-flow exponential and the carbon and nitrogen balances.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "aftertreatment/soot_filter.hpp"
#include "support.hpp"

namespace hbt::aftertreatment {
namespace {

constexpr double kR = 8.314462618;  // J/(mol K)

// Shrivastava et al. (2010) by hand: 100 ppm NO2 at 1 atm and 600 K,
// [NO2] = x p / (k_B T) molecules/m^3 -> /cm^3; dd/dt = A T^0.5 [NO2] exp(-E/RT) in nm/s;
// mass-specific rate 3/d_p dd/dt.
TEST(SootFilter, RateLawEqualsTheHandCalculation) {
  const AtsParams p = test::loadParams();
  SootFilter f(p.soot, 8, 1e-3);
  const double T = 600.0, x = 100e-6, P = 101325.0;
  const double n_cm3 = x * P / (1.380649e-23 * T) * 1e-6;        // molecules/cm^3
  const double dd_nm_s = 2.4e-14 * std::sqrt(T) * n_cm3 * std::exp(-47100.0 / (kR * T));
  const double k_hand = 3.0 * dd_nm_s * 1e-9 / 25e-9;            // 1/s
  const double c = x * P / (kR * T);                             // mol/m^3
  EXPECT_NEAR(f.specificRate_1_s(T, c), k_hand, 1e-9 * k_hand);
  // temperature dependence: T^0.5 exp(-E/RT) between 550 and 700 K at the same concentration
  const double ratio = std::sqrt(700.0 / 550.0) * std::exp(47100.0 / kR * (1.0 / 550.0 - 1.0 / 700.0));
  EXPECT_NEAR(f.specificRate_1_s(700.0, c) / f.specificRate_1_s(550.0, c), ratio, 1e-12 * ratio);
  std::printf("[ats] NO2 + soot at 600 K, 100 ppm: dd/dt %.3g nm/s, k_m %.3g 1/s (%.3g %%/h); "
              "x%.2f from 550 to 700 K\n", dd_nm_s, k_hand, 3600.0 * 100.0 * k_hand, ratio);
}

// One slice: the NO2 leaving is F exp(-kappa), kappa = nu k_m/c m / (M_C Vdot), as plug flow
// through the cake gives; the soot burnt is the NO2 consumed / nu.
TEST(SootFilter, OneSliceFollowsThePlugFlowExponential) {
  AtsParams p = test::loadParams();
  p.soot.engine_out_g_per_kg_co2 = 0.0;
  SootFilter f(p.soot, 1, 0.017);
  f.setUniformLoad(2.0);  // 34 g
  const double T = 650.0, P = 110e3, n_tot = 5.0, n_NO2 = 5.0 * 150e-6, dt = 0.1;
  const double m0 = f.mass_kg();
  double qr = 0.0;
  const SootStep r = f.step(dt, 0.0, n_NO2, n_tot, P, &T, &qr);
  const double Vdot = n_tot * kR * T / P;
  const double kappa = 2.0 * f.specificRate_1_s(T, 1.0) * m0 / (12.011e-3 * Vdot);
  EXPECT_NEAR(r.n_NO2_out_mol_s, n_NO2 * std::exp(-kappa), 1e-12 * n_NO2);
  EXPECT_NEAR(r.carbon_co2_mol, 0.5 * n_NO2 * (1.0 - std::exp(-kappa)) * dt, 1e-12 * n_NO2 * dt);
  EXPECT_NEAR(qr * dt, r.carbon_co2_mol * 279.1e3, 1e-9 * qr * dt);
  EXPECT_GT(kappa, 1e-3);  // a measurable conversion
  std::printf("[ats] 2 g/L at 650 K, 150 ppm NO2: %.2f %% of the NO2 reduced on the soot\n",
              100.0 * (1.0 - std::exp(-kappa)));
}

// Carbon and nitrogen balances over a transient with both product channels: captured = stored
// change + burnt, engine-out = captured + slip, NO2 consumed = (1 + s) C burnt, NO2 out = in -
// consumed; a nearly empty filter never burns more soot than it holds.
TEST(SootFilter, CarbonAndNitrogenBalancesClose) {
  AtsParams p = test::loadParams();
  p.soot.co2_selectivity = 0.6;
  const int N = p.dpf.slices;
  SootFilter f(p.soot, N, 0.017 / N);
  f.setUniformLoad(0.05);
  const double m0 = f.mass_kg();
  std::vector<double> T(N), qr(N);
  double captured = 0.0, slip = 0.0, burnt_mol = 0.0, no2_in = 0.0, no2_out = 0.0, no2_used = 0.0;
  double co2_in = 0.0;
  for (int k = 0; k < 20000; ++k) {
    const double load = 0.5 + 0.5 * std::sin(2.0 * 3.14159265 * 0.1 * k / 60.0);
    for (int i = 0; i < N; ++i) T[i] = 550.0 + 200.0 * load - 5.0 * i;
    const double n_NO2 = 1e-4 + 1e-3 * load, co2 = 0.01 * load;
    const SootStep r = f.step(0.1, co2, n_NO2, 4.0, 105e3, T.data(), qr.data());
    captured += r.captured_kg;
    slip += r.slip_kg;
    co2_in += co2 * 0.1;
    burnt_mol += r.carbon_co2_mol + r.carbon_co_mol;
    EXPECT_NEAR(r.no2_consumed_mol, 1.6 * (r.carbon_co2_mol + r.carbon_co_mol), 1e-15);
    EXPECT_NEAR(r.carbon_co2_mol, 1.5 * r.carbon_co_mol, 1e-15);
    no2_in += n_NO2 * 0.1;
    no2_out += r.n_NO2_out_mol_s * 0.1;
    no2_used += r.no2_consumed_mol;
    for (int i = 0; i < N; ++i) ASSERT_GE(f.sliceMass_kg(i), 0.0);
  }
  const double burnt_kg = burnt_mol * 12.011e-3;
  EXPECT_NEAR(captured + slip, p.soot.engine_out_g_per_kg_co2 * 1e-3 * co2_in, 1e-12 * captured);
  EXPECT_NEAR(slip, (1.0 - p.soot.filtration_efficiency) * (captured + slip), 1e-12 * captured);
  EXPECT_NEAR(captured, f.mass_kg() - m0 + burnt_kg, 1e-12 * captured);
  EXPECT_NEAR(no2_in - no2_out, no2_used, 1e-12 * no2_in);
  EXPECT_GT(burnt_kg, 0.5 * m0);  // the soot burns down: the small load is soot-limited
  std::printf("[ats] soot balance: captured %.4g g = stored change %.4g g + burnt %.4g g; NO2 in "
              "%.4g mol, reduced to NO %.4g mol\n", 1e3 * captured, 1e3 * (f.mass_kg() - m0),
              1e3 * burnt_kg, no2_in, no2_used);
}

}  // namespace
}  // namespace hbt::aftertreatment
