// Full four-stroke cycles on the single-cylinder rig (constant-pressure reservoirs).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "cylinder/rig.hpp"
#include "support.hpp"
#include "../common/input_errors.hpp"

using namespace hbt::cylinder;

namespace {
double noxGPerKWh(const CycleResults& r) {
  return r.work_gross_J > 0 ? r.nox_no2eq_kg * 1e3 / (r.work_gross_J / 3.6e6) : 0.0;
}
void report(const char* tag, const CycleResults& r) {
  std::printf(
      "[%s] cycle %d: IMEPg %.2f bar IMEPn %.2f bar PMEP %.2f bar pmax %.1f bar @ %.1f deg, "
      "eta_g %.3f eta_n %.3f lambda %.2f trapped %.3f g xr %.3f, CA10/50/90 %.1f/%.1f/%.1f, "
      "SOC %.1f ID %.1f deg, Tmax %.0f K Tb,max %.0f K, Qwall %.0f J (%.1f %% of fuel), "
      "NO2eq %.3f mg = %.2f g/kWh(ind)\n",
      tag, r.index, r.imep_gross_Pa * 1e-5, r.imep_net_Pa * 1e-5, r.pmep_Pa * 1e-5,
      r.pmax_Pa * 1e-5, r.theta_pmax_deg, r.eta_ind_gross, r.eta_ind_net, r.lambda,
      r.trapped_mass_kg * 1e3, r.residual_frac, r.ca10_deg, r.ca50_deg, r.ca90_deg, r.soc_main_deg,
      r.ignition_delay_main_deg, r.Tmax_mean_K, r.Tmax_burned_K, r.heat_wall_J,
      100 * r.heat_wall_J / (r.fuel_injected_kg * 42.8e6), r.nox_no2eq_kg * 1e6, noxGPerKWh(r));
}
}  // namespace

namespace {
// Runs one whole cycle of the rig and checks its first law:
//   ΔU = H_in − H_out + Q_comb(LHV + h_fg) + fuel enthalpy − Q_wall − W   (relative 1e-9).
const CycleResults& runOneCycleEnergyCheck(SingleCylinderRig& rig, const CylinderParams& cp,
                                           const RigParams& rp) {
  Cylinder& c = rig.cylinder();
  auto U = [&]() {
    double m[kNumGroups];
    for (int g = 0; g < kNumGroups; ++g) m[g] = c.groupMass(Group(g));
    return mixturePoly(c.thermo(), m).u(c.temperature_K());  // single zone at the cycle boundary
  };
  const double U0 = U();
  double H = 0.0;
  const double dt = hbt::units::degToRad(rp.step_deg) / (rp.speed_rpm * M_PI / 30.0);
  const int start = c.cyclesCompleted();
  while (c.cyclesCompleted() == start) {
    const PortFlows f = rig.step();
    H += (f.intake.Hdot_W + f.exhaust.Hdot_W) * dt;
  }
  const CycleResults& r = c.lastCycle();
  const double h_inj = c.thermo().group(kFuelVap).h(cp.fuel_temperature_K) - cp.fuel.hfg_J_kg;
  const double rhs = H + r.fuel_burned_kg * (cp.fuel.lhv_J_kg + cp.fuel.hfg_J_kg) +
                     r.fuel_injected_kg * h_inj - r.heat_wall_J - r.work_net_J;
  EXPECT_NEAR((U() - U0 - rhs) / r.heat_release_J, 0.0, 1e-9);
  return r;
}
}  // namespace

TEST(Rig, MidLoadOperatingPointIsPlausible) {
  RigParams rp;
  const CylinderParams cp = test::loadParams(&rp);  // 1400 rpm, 64 mg: ~50 % load
  SingleCylinderRig rig(cp, rp);
  const CycleResults r = rig.runToPeriodic(8, 2e-3);
  report("1400rpm 64mg", r);
  EXPECT_GT(r.imep_gross_Pa, 10.0e5);  // BMEP ≈ 10 bar + FMEP ≈ 1.5 bar
  EXPECT_LT(r.imep_gross_Pa, 13.5e5);
  EXPECT_GT(r.pmax_Pa, 90e5);
  EXPECT_LT(r.pmax_Pa, 150e5);
  EXPECT_GT(r.eta_ind_gross, 0.42);  // HD diesel gross indicated efficiency 42–48 %
  EXPECT_LT(r.eta_ind_gross, 0.50);
  EXPECT_GT(r.lambda, 1.6);
  EXPECT_LT(r.lambda, 3.2);
  EXPECT_NEAR(r.fuel_burned_kg / r.fuel_injected_kg, 1.0, 2e-3);
  EXPECT_GT(noxGPerKWh(r), 2.0);  // engine-out NOx of a Euro VI SCR engine without EGR
  EXPECT_LT(noxGPerKWh(r), 25.0);
}

TEST(Rig, FullLoadPeakPressure) {
  RigParams rp;
  const CylinderParams cp = test::loadParams(&rp);
  rp.fuel_per_cycle_kg = 125e-6;  // 1100 N m at 1400 rpm
  rp.p_intake_Pa = 2.7e5;
  rp.T_intake_K = 325.0;
  rp.p_exhaust_Pa = 2.4e5;
  rp.T_exhaust_K = 850.0;
  SingleCylinderRig rig(cp, rp);
  const CycleResults r = rig.runToPeriodic(8, 2e-3);
  report("1400rpm full", r);
  EXPECT_GT(r.pmax_Pa, 120e5);  // HD diesel at full load: 120–180 bar
  EXPECT_LT(r.pmax_Pa, 185e5);
  EXPECT_GT(r.imep_gross_Pa, 20e5);
  EXPECT_GT(r.lambda, 1.3);
}

TEST(Rig, CycleEnergyBalanceCloses) {
  RigParams rp;
  const CylinderParams cp = test::loadParams(&rp);
  SingleCylinderRig rig(cp, rp);
  rig.runCycles(4);
  // Over one cycle: ΔU = H_in − H_out + Q_comb(LHV+h_fg) + fuel enthalpy − Q_wall − W.
  const CycleResults& r = runOneCycleEnergyCheck(rig, cp, rp);
  // Exhaust enthalpy is the largest loss after the work (~30 % of the fuel energy).
  EXPECT_GT(r.exhaust_enthalpy_J, 0.2 * r.heat_release_J);
}

TEST(Rig, HohenbergCorrelationClosesEnergyWithPlausibleWallHeat) {
  RigParams rp;
  CylinderParams cp = test::loadParams(&rp);
  const CylinderParams woschni = cp;
  cp.heat_transfer_correlation = "hohenberg";
  cp.finalize();
  ASSERT_TRUE(cp.woschni.hohenberg);
  SingleCylinderRig rig(cp, rp), ref(woschni, rp);
  rig.runCycles(4);
  ref.runCycles(4);
  const CycleResults& r = runOneCycleEnergyCheck(rig, cp, rp);
  ref.runCycles(1);
  const CycleResults& w = ref.cylinder().lastCycle();
  // Same fuel, same gas exchange: the two correlations give wall losses of the same order
  // (HD DI diesel at mid load: 10-25 % of the fuel energy); the first law closes.
  const double share = r.heat_wall_J / r.heat_release_J;
  EXPECT_GT(share, 0.08);
  EXPECT_LT(share, 0.30);
  EXPECT_NEAR(r.heat_wall_J / w.heat_wall_J, 1.0, 0.5);
  // More wall heat -> less work for the same fuel (both cycles burn the same fuel).
  EXPECT_NEAR(r.fuel_burned_kg / w.fuel_burned_kg, 1.0, 1e-3);
  EXPECT_EQ(r.heat_wall_J > w.heat_wall_J, r.work_net_J < w.work_net_J);
}

TEST(Params, UnknownHeatTransferCorrelationNamesFileAndKey) {
  CylinderParams cp = test::loadParams();
  cp.heat_transfer_correlation = "annand";
  hbt::testing::expectInputError([&] { cp.finalize("cyl.yaml"); }, "cyl.yaml",
                                 "cylinder/heat_transfer/correlation");
}

TEST(Params, UnknownNoxModelNamesFileAndKey) {
  CylinderParams cp = test::loadParams();
  cp.nox_model = "zeldovich";
  hbt::testing::expectInputError([&] { cp.finalize("cyl.yaml"); }, "cyl.yaml", "cylinder/nox/model");
  cp.nox_model = "burned_zone";
  cp.finalize("cyl.yaml");
  EXPECT_FALSE(cp.nox_hot_zone);
}

TEST(Rig, FlameConsumingTheWholeUnburnedZoneKeepsEnergyBalance) {
  // Limit case: a flame air excess (3.0) above the global one (full-load fuel, lambda ~1.7): the
  // burned zone takes nearly all the air of the unburned zone; energy must still be conserved
  // and all fuel burned. (The exact emptying of the unburned zone, handled by a zone merge in
  // Cylinder::advance, is exercised by the coupled Urban run in test/scenario/test_engine_1d.py
  // past t = 40 s, where it first occurred.)
  RigParams rp;
  CylinderParams cp = test::loadParams(&rp);
  cp.flame_lambda = 3.0;
  rp.fuel_per_cycle_kg = 125e-6;
  rp.p_intake_Pa = 2.7e5;
  rp.p_exhaust_Pa = 2.4e5;
  SingleCylinderRig rig(cp, rp);
  ASSERT_NO_THROW(rig.runCycles(3));
  const CycleResults& r = runOneCycleEnergyCheck(rig, cp, rp);
  EXPECT_NEAR(r.fuel_burned_kg / r.fuel_injected_kg, 1.0, 2e-3);
}

TEST(Rig, PhysicalTrends) {
  RigParams rp;
  const CylinderParams cp0 = test::loadParams(&rp);
  auto run = [&](const CylinderParams& cp, const RigParams& r) {
    SingleCylinderRig rig(cp, r);
    return rig.runToPeriodic(8, 2e-3);
  };
  const CycleResults base = run(cp0, rp);
  // Hotter charge air: less trapped mass, lower λ (SPEC §3 ambient-temperature trend).
  RigParams hot = rp;
  hot.T_intake_K += 25.0;
  const CycleResults h = run(cp0, hot);
  EXPECT_LT(h.trapped_mass_kg, 0.95 * base.trapped_mass_kg);
  EXPECT_LT(h.lambda, base.lambda);
  // Advanced injection: higher peak pressure and more NO, the direction of the classic timing
  // lever (Khair, DieselNet "Engine Design for NOx Control"): the fuel burns nearer TDC, with
  // hotter, denser charge. Size: retarding the injection of a turbocharged DI diesel with a
  // low-heat-rejection (coated) chamber from 20 to 18 and 16 deg bTDC cut its NOx by 11 % (Sakarya
  // University repository, handle 20.500.12619/49693, Elsevier Masson 2007); the hot-zone model
  // gives +14 % for these 4 deg, required: > +8 % (the published 11 % with a margin).
  // From a fixed SOI of 5 deg bTDC to 9 deg bTDC (independent of the calibrated map, whose SOI
  // here is after TDC: there the peak pressure is the compression peak either way).
  CylinderParams early = cp0, adv = cp0;
  for (double& s : early.soi_main_deg) s = -5.0;
  for (double& s : adv.soi_main_deg) s = -9.0;
  early.finalize();
  adv.finalize();
  const CycleResults b5 = run(early, rp);
  const CycleResults a = run(adv, rp);
  EXPECT_GT(a.pmax_Pa, b5.pmax_Pa + 5e5);
  EXPECT_GT(a.nox_no2eq_kg, 1.08 * b5.nox_no2eq_kg);
  // Halving the time step changes IMEP by < 0.3 % (converged integration).
  RigParams fine = rp;
  fine.step_deg = 0.05;
  const CycleResults f = run(cp0, fine);
  EXPECT_NEAR(f.imep_net_Pa / base.imep_net_Pa, 1.0, 3e-3);
}

TEST(Rig, CostPerCylinderStep) {
  // Times Cylinder::advance alone (flows recorded from a rig run) at 0.1 and 1 deg steps.
  for (double step : {0.1, 1.0}) {
    RigParams rp;
    const CylinderParams cp = test::loadParams(&rp);
    rp.step_deg = step;
    SingleCylinderRig rig(cp, rp);
    rig.runCycles(2);
    const double omega = rp.speed_rpm * M_PI / 30.0, dt = hbt::units::degToRad(rp.step_deg) / omega;
    const int n = static_cast<int>(std::lround(4 * 720 / rp.step_deg));
    std::vector<PortFlows> flows;
    flows.reserve(n);
    for (int i = 0; i < n; ++i) flows.push_back(rig.step());
    SingleCylinderRig rig2(cp, rp);
    rig2.runCycles(2);
    const long nox0 = rig2.cylinder().noxCvodeSteps();
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i) rig2.cylinder().advance(dt, omega, flows[i]);
    const auto t1 = std::chrono::steady_clock::now();
    const double ns = std::chrono::duration<double, std::nano>(t1 - t0).count() / n;
    std::printf("[cost] step %.1f deg: %.0f ns per cylinder step, %.0f us per cycle, %ld CVODE "
                "steps/cycle, CPU/simulated = %.4f per cylinder at 1400 rpm\n",
                step, ns, ns * 720 / step * 1e-3, (rig2.cylinder().noxCvodeSteps() - nox0) / 4,
                ns * 1e-9 / dt);
    EXPECT_LT(ns, 20000.0);  // generous bound (shared machine); the measured value is reported
    EXPECT_NEAR(rig2.cylinder().lastCycle().imep_net_Pa / rig.cylinder().lastCycle().imep_net_Pa, 1.0, 1e-12);
  }
}

TEST(Rig, LowLambdaFullLoadFuelBurnsBeforeExhaustValveOpening) {
  // Smoke-limit corner (lambda ~1.25 < flame_lambda 1.5, long main injection at full-load fuel):
  // the flame must leave the unburned zone stoichiometric air for the fuel still to be injected.
  // Regression: the air reserve once counted only the vapour present, so late-injected fuel
  // waited air-limited until the zones merged at EVO and burned there in one step (in this rig
  // case 4.2 % of the fuel: 0.958 burned at EVO before the fix, 1.000 after it).
  RigParams rp;
  CylinderParams cp = test::loadParams(&rp);
  for (double& d : cp.diffusion_tail_deg) d *= 0.5;  // fast diffusion burn: flame takes air early
  cp.finalize();
  rp.speed_rpm = 1100.0;
  rp.fuel_per_cycle_kg = 137e-6;
  rp.p_intake_Pa = 2.25e5;
  rp.p_exhaust_Pa = 2.1e5;
  SingleCylinderRig rig(cp, rp);
  rig.runCycles(4);
  Cylinder& c = rig.cylinder();
  const int cycle = c.cyclesCompleted();
  while (c.crankAngle_deg() < cp.evo_deg - 0.5 || c.crankAngle_deg() > cp.evo_deg)
    rig.step();
  ASSERT_EQ(c.cyclesCompleted(), cycle);
  const double lambda = c.lastCycle().lambda;
  EXPECT_GT(lambda, 1.1);
  EXPECT_LT(lambda, cp.flame_lambda);  // the case under test: global air excess below the flame's
  EXPECT_GT(c.fuelBurnedThisCycle_kg() / rp.fuel_per_cycle_kg, 0.995);
}

TEST(Rig, NoxBatchIntervalConverges) {
  // The NO forms in batches of nox_interval_deg: one hot-zone packet per batch of burned fuel at
  // its fuel-weighted reactant state (shipped model). Against 0.5-deg batches (the converged
  // reference), NO per cycle from 6-deg batches (the engine's setting) must agree within 2 % and
  // from 12-deg batches within 8 % at mid and full load (measured, hot zone: 6 deg -0.14 / -0.15 %,
  // 12 deg -0.53 / -0.52 %; the burned-zone model, Zeldovich at the batch's mean burned-zone
  // state: 6 deg -1.6 / -0.8 %, 12 deg -6.9 / -3.4 %, as its rate is convex in T).
  struct Case { double fuel_kg, p_in_Pa, p_ex_Pa; };
  for (const Case& k : {Case{64e-6, 1.9e5, 1.75e5}, Case{125e-6, 2.7e5, 2.4e5}}) {
    auto no = [&](double interval_deg) {
      RigParams rp;
      CylinderParams cp = test::loadParams(&rp);
      cp.nox_interval_deg = interval_deg;
      rp.fuel_per_cycle_kg = k.fuel_kg;
      rp.p_intake_Pa = k.p_in_Pa;
      rp.p_exhaust_Pa = k.p_ex_Pa;
      SingleCylinderRig rig(cp, rp);
      return rig.runCycles(4).no_mass_kg;
    };
    const double ref = no(0.5);
    ASSERT_GT(ref, 0.0);
    std::printf("fuel %.0f mg: NO 0.5 deg %.4g mg, 6 deg %+.2f %%, 12 deg %+.2f %%\n", k.fuel_kg * 1e6,
                ref * 1e6, 100 * (no(6.0) / ref - 1), 100 * (no(12.0) / ref - 1));
    EXPECT_NEAR(no(6.0) / ref, 1.0, 0.02);
    EXPECT_NEAR(no(12.0) / ref, 1.0, 0.08);
  }
}

TEST(Rig, NoxSensitivityToIntakeTemperature) {
  // d ln(NOx)/dT_intake at fixed intake pressure, fuel and injection (1400 rpm, 64 mg, ~50 %
  // load), intake 310 / 330 K, NO kinetics at the dissociated and at the frozen burned-zone
  // temperature. Published (SAE 730213 correction, 40 CFR 86.1342-90 / UN R49 k_h,D): +0.0…0.54 %/K
  // for fuel/air 0.045…0.02 (src/engine_1d/README.md "Engine-out NOx"). Measured here:
  // dissociated 1.45 %/K, frozen 1.50 %/K: dissociation at λ_flame 1.5 and ~90 bar lowers the NO
  // by 12 % but damps the sensitivity by only ~3 % — the model stays ~3x above the published
  // band (the burned zone is too lean for dissociation to matter; see src/cylinder/README.md).
  auto sensitivity = [](bool dissociation, double& nox_mid_kg) {
    RigParams rp;
    CylinderParams cp = test::loadParams(&rp);
    cp.nox_hot_zone = false;  // the burned-zone model (the hot zone: test_hot_zone_no.cpp)
    cp.nox_dissociation = dissociation;
    return test::rigNoxSensitivityToIntake(cp, rp, nox_mid_kg);
  };
  double nox_d = 0.0, nox_f = 0.0;
  const double s_d = sensitivity(true, nox_d), s_f = sensitivity(false, nox_f);
  std::printf("[nox-dT] dissociated %.3f mg, %.2f %%/K; frozen %.3f mg, %.2f %%/K\n", nox_d * 1e6,
              100 * s_d, nox_f * 1e6, 100 * s_f);
  EXPECT_LT(nox_d, 0.95 * nox_f);  // the dissociated hot zone is cooler
  EXPECT_GT(nox_d, 0.70 * nox_f);  // but at λ 1.5 and ~90 bar only by ~30–50 K
  EXPECT_LT(s_d, s_f);             // and responds less to the charge temperature
  EXPECT_GT(s_d, 0.0);
  EXPECT_LT(s_d, 0.02);  // guard: the 1D engine's frozen model measured +2.2–2.6 %/K
}
