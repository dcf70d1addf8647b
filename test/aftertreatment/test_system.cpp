// Whole system: energy balance, dosing rule, light-off, DOC, bad input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "aftertreatment/aftertreatment.hpp"
#include "common/errors.hpp"
#include "common/yaml_params.hpp"
#include "support.hpp"
#include "../common/param_checks.hpp"

namespace hbt::aftertreatment {
namespace {

// City-bus-like transient: idle / acceleration cycles of 60 s.
AtsInputs transient(double t, double Tamb) {
  AtsInputs in;
  const double load = 0.5 + 0.5 * std::sin(2.0 * 3.14159265 * t / 60.0);
  in.exhaust_mass_flow_kg_s = 0.04 + 0.16 * load;
  in.exhaust_T_K = 450.0 + 250.0 * load;
  in.nox_mass_flow_kg_s = 2e-5 + 1.5e-4 * load;
  in.co_mass_flow_kg_s = 1e-5;
  in.hc_mass_flow_kg_s = 3e-6;
  in.ambient_T_K = Tamb;
  in.vehicle_speed_m_s = 8.0 * load;
  return in;
}

TEST(Aftertreatment, EnergyAndNitrogenBalancesOverATransient) {
  const AtsParams p = test::loadParams();
  Aftertreatment ats(p);
  ats.reset(283.15);
  for (int k = 0; k < 18000; ++k) ats.step(0.1, transient(0.1 * k, 283.15));  // 30 min
  const AtsEnergy& e = ats.energy();
  EXPECT_GT(e.can_loss_J, 0.0);
  EXPECT_GT(e.line_loss_J, 0.005 * e.enthalpy_in_J);
  EXPECT_GT(e.reaction_heat_J, 0.0);
  EXPECT_GT(e.stored_change_J, 0.0);
  EXPECT_GT(e.enthalpy_in_J, e.enthalpy_out_J);
  // every term is material: none smaller than 0.5 % of the enthalpy in
  EXPECT_GT(e.can_loss_J, 0.005 * e.enthalpy_in_J);
  EXPECT_GT(e.stored_change_J, 0.005 * e.enthalpy_in_J);
  EXPECT_LT(std::abs(e.residual_J()), 0.01 * e.enthalpy_in_J);
  std::printf("[ats] 30 min transient: H_in %.4g J, H_out %.4g J, can %.4g J, line %.4g J, "
              "reaction %.4g J, stored %.4g J, residual %.3g J (%.2g of H_in)\n", e.enthalpy_in_J,
              e.enthalpy_out_J, e.can_loss_J, e.line_loss_J, e.reaction_heat_J, e.stored_change_J,
              e.residual_J(), e.residual_J() / e.enthalpy_in_J);
  // independent stored-energy check from the brick and line-wall temperatures
  double dE = 0.0;
  for (int b = 0; b < kNumBricks; ++b)
    for (int i = 0; i < ats.brick(b).slices(); ++i)
      dE += ats.brick(b).sliceHeatCapacity() * (ats.brick(b).T(i) - 283.15);
  for (int l = 0; l < kNumLineParts; ++l)
    for (int i = 0; i < ats.line(l).segments(); ++i)
      dE += ats.line(l).heatCapacity(i) * (ats.line(l).T(i) - 283.15);
  EXPECT_NEAR(e.stored_change_J, dE, 1e-9 * dE);
  const AtsNitrogen& n = ats.nitrogen();
  EXPECT_GT(n.nh3_dosed_mol, 0.0);
  EXPECT_NEAR(n.residual_mol(), 0.0, 1e-6 * n.nh3_dosed_mol);
  std::printf("[ats] NH3: dosed %.5g mol, stored %.4g, reacted %.5g, oxidised %.4g, SCR slip %.4g, "
              "residual %.3g mol (%.2g relative); NOx engine %.4g g, tailpipe %.4g g\n",
              n.nh3_dosed_mol, n.nh3_stored_change_mol, n.nh3_scr_reacted_mol,
              n.nh3_scr_oxidised_mol, n.nh3_scr_slip_mol, n.residual_mol(),
              n.residual_mol() / n.nh3_dosed_mol, 1e3 * ats.outputs().engine_nox_kg,
              1e3 * ats.outputs().tailpipe_nox_kg);
  EXPECT_NEAR(n.nh3_scr_slip_mol, n.nh3_asc_oxidised_mol + n.nh3_tailpipe_mol, 1e-9 + 1e-9 * n.nh3_scr_slip_mol);
  // the warm system converts most NOx in the second half hour
  EXPECT_LT(ats.outputs().tailpipe_nox_kg, ats.outputs().engine_nox_kg);
  // NOx reaches the SCR whole (the soot turns NO2 into NO, mole for mole); carbon balance
  EXPECT_NEAR(n.nox_scr_in_mol * kM_NO2, ats.outputs().engine_nox_kg, 1e-12 * ats.outputs().engine_nox_kg);
  const AtsSoot& c = ats.soot();
  EXPECT_GT(c.burnt_kg, 0.0);
  EXPECT_NEAR(c.residual_kg(), 0.0, 1e-12 * c.captured_kg);
  EXPECT_NEAR(c.no2_to_no_mol, 2.0 * c.carbon_co2_mol + c.carbon_co_mol, 1e-12 * c.no2_to_no_mol);
  std::printf("[ats] soot: engine-out %.4g g, captured %.4g g, burnt by NO2 %.4g g, NO2 -> NO "
              "%.4g mol, residual %.2g kg\n", 1e3 * c.engine_out_kg, 1e3 * c.captured_kg,
              1e3 * c.burnt_kg, c.no2_to_no_mol, c.residual_kg());
}

// Warm DPF at constant load: the soot settles where it burns as fast as it is deposited, and
// then the NO2 missing between the DOC outlet and the SCR inlet is 2 NO2 per carbon deposited
// (C + 2 NO2 -> CO2 + 2 NO), whatever the rate constant: eta_f EF mdot_CO2 / M_C x 2.
TEST(Aftertreatment, PassiveRegenerationAtBalanceTakesTwoNo2PerSootCarbon) {
  const AtsParams p = test::loadParams();
  Aftertreatment ats(p);
  ats.reset(623.15);
  AtsInputs in;
  in.exhaust_mass_flow_kg_s = 0.15;
  in.exhaust_T_K = 650.0;
  in.nox_mass_flow_kg_s = 1.5e-4;
  in.ambient_T_K = 293.15;
  in.vehicle_speed_m_s = 8.0;
  for (int k = 0; k < 36000; ++k) ats.step(0.1, in);  // 1 h
  const double m1 = ats.outputs().soot_mass_kg;
  for (int k = 0; k < 600; ++k) ats.step(0.1, in);
  const AtsOutputs& o = ats.outputs();
  EXPECT_NEAR(o.soot_mass_kg, m1, 1e-3 * m1);  // settled
  const double n_NOx = in.nox_mass_flow_kg_s / kM_NO2;
  const double no2_taken = (o.doc_no2_fraction - o.scr_inlet_no2_fraction) * n_NOx;
  const double carbon_in = p.soot.filtration_efficiency * p.soot.engine_out_g_per_kg_co2 * 1e-3 *
                           in.comp.y_CO2 * in.exhaust_mass_flow_kg_s / kM_C;
  EXPECT_NEAR(no2_taken, 2.0 * carbon_in, 0.01 * 2.0 * carbon_in);
  EXPECT_GT(o.doc_no2_fraction - o.scr_inlet_no2_fraction, 0.005);
  std::printf("[ats] 650 K gas at balance (%.4f g/L): NO2/NOx %.3f after the DOC, %.3f at the SCR; "
              "NO2 taken %.4g mol/s = %.4f x 2 C deposited\n", o.soot_load_g_L, o.doc_no2_fraction,
              o.scr_inlet_no2_fraction, no2_taken, no2_taken / (2.0 * carbon_in));
}

TEST(Aftertreatment, NoUreaBelowReleaseTemperature) {
  const AtsParams p = test::loadParams();
  AtsInputs in;
  in.exhaust_mass_flow_kg_s = 0.12;
  in.nox_mass_flow_kg_s = 1e-4;
  in.ambient_T_K = 293.15;
  Aftertreatment cold(p);
  cold.reset(293.15);
  in.exhaust_T_K = p.dosing_release_T_K - 10.0;  // the SCR inlet can never reach release
  for (int k = 0; k < 7200; ++k) cold.step(0.5, in);  // 1 h
  EXPECT_EQ(cold.outputs().adblue_kg, 0.0);
  EXPECT_EQ(cold.nitrogen().nh3_dosed_mol, 0.0);
  EXPECT_LT(cold.outputs().nox_conversion, 1e-12);
  EXPECT_LT(cold.outputs().light_off_time_s, 0.0);
  Aftertreatment warm(p);
  warm.reset(293.15);
  in.exhaust_T_K = p.dosing_release_T_K + 80.0;
  for (int k = 0; k < 7200; ++k) warm.step(0.5, in);
  EXPECT_GT(warm.outputs().adblue_kg, 0.0);
  // AdBlue = urea / 0.325, urea = NH3 / 2
  EXPECT_NEAR(warm.outputs().urea_kg, 0.5 * warm.nitrogen().nh3_dosed_mol * kM_urea, 1e-12);
  EXPECT_NEAR(warm.outputs().adblue_kg * 0.325, warm.outputs().urea_kg, 1e-12);
}

// Light-off emerges from the thermal model: later with a colder start, never before the SCR is
// warm, and after it the SCR converts most of the NOx.
TEST(Aftertreatment, LightOffFromTheThermalModel) {
  const AtsParams p = test::loadParams();
  double t_lo[2];
  const double Tamb[2] = {273.15, 313.15};
  for (int c = 0; c < 2; ++c) {
    Aftertreatment ats(p);
    ats.reset(Tamb[c]);
    AtsInputs in;
    in.exhaust_mass_flow_kg_s = 0.12;
    in.exhaust_T_K = 600.0;
    in.nox_mass_flow_kg_s = 1e-4;
    in.ambient_T_K = Tamb[c];
    in.vehicle_speed_m_s = 8.0;
    double scr_T_at_lo = 0.0;
    for (int k = 0; k < 12000; ++k) {
      ats.step(0.1, in);
      if (ats.outputs().light_off && scr_T_at_lo == 0.0) scr_T_at_lo = ats.outputs().brick_T_K[kSCR];
    }
    t_lo[c] = ats.outputs().light_off_time_s;
    std::printf("[ats] start at %.0f K: SCR light-off at %.1f s (SCR mean wall %.1f K), conversion "
                "after 20 min %.3f\n", Tamb[c], t_lo[c], scr_T_at_lo, ats.outputs().nox_conversion);
    ASSERT_GT(t_lo[c], 30.0);
    EXPECT_GE(scr_T_at_lo, p.dosing_release_T_K);
    EXPECT_GT(ats.outputs().nox_conversion, 0.8);
    // the DOC lights off first and converts the CO at 600 K inlet
    EXPECT_GT(ats.outputs().brick_T_K[kDOC], ats.outputs().brick_T_K[kSCR]);
  }
  // colder start: later light-off (the warm-up is dominated by the thermal front through the
  // line's walls, DOC and DPF, so the difference is ~15 %: 349 s at 0 degC vs 305 s at 40 degC)
  EXPECT_GT(t_lo[0], t_lo[1] + 2.0);
}

TEST(Aftertreatment, DocConversionRisesWithTemperatureAndFallsWithSpaceVelocity) {
  const AtsParams p = test::loadParams();
  auto co = [&](double T, double mdot) {
    Aftertreatment ats(p);
    ats.reset(T);
    AtsInputs in;
    in.exhaust_mass_flow_kg_s = mdot;
    in.exhaust_T_K = T;
    in.co_mass_flow_kg_s = 1e-5;
    in.nox_mass_flow_kg_s = 5e-5;
    in.ambient_T_K = T;  // no can loss: isothermal brick
    ats.step(0.01, in);
    return std::make_pair(ats.outputs().doc_co_conversion, ats.outputs().doc_no2_fraction);
  };
  EXPECT_LT(co(373.15, 0.1).first, 0.05);
  EXPECT_GT(co(473.15, 0.1).first, co(423.15, 0.1).first);
  EXPECT_GT(co(573.15, 0.1).first, 0.99);
  EXPECT_GT(co(473.15, 0.05).first, co(473.15, 0.2).first);  // lower space velocity
  // NO2/NOx: kinetic rise, then equilibrium-limited fall at high temperature
  const double f250 = co(523.15, 0.1).second, f350 = co(623.15, 0.1).second,
               f550 = co(823.15, 0.1).second;
  EXPECT_GT(f350, f250 * 0.9);
  EXPECT_GT(f350, 0.3);
  EXPECT_LT(f550, f350);
  EXPECT_LT(f550, 0.35);
}

TEST(Aftertreatment, BackPressureAtRatedFlow) {
  const AtsParams p = test::loadParams();
  Aftertreatment ats(p);
  ats.reset(700.0);
  AtsInputs in;
  in.exhaust_mass_flow_kg_s = 0.30;  // ~ rated power of a 7.7 L, 220 kW engine
  in.exhaust_T_K = 700.0;
  in.ambient_T_K = 293.15;
  ats.step(0.1, in);
  ats.step(0.1, in);
  const double dp = ats.outputs().back_pressure_Pa - in.ambient_p_Pa;
  const auto& o = ats.outputs();
  std::printf("[ats] 0.30 kg/s at 700 K: back-pressure +%.0f Pa (DOC %.0f, DPF %.0f, SCR %.0f, "
              "ASC %.0f, muffler %.0f)\n", dp, o.brick_dp_Pa[kDOC], o.brick_dp_Pa[kDPF],
              o.brick_dp_Pa[kSCR], o.brick_dp_Pa[kASC], o.muffler_dp_Pa);
  EXPECT_GT(dp, 10e3);
  EXPECT_LT(dp, 40e3);
  double sum = ats.outputs().muffler_dp_Pa;
  for (double d : ats.outputs().brick_dp_Pa) sum += d;
  EXPECT_NEAR(sum, dp, 1e-6);
  in.exhaust_mass_flow_kg_s = 0.03;  // idle
  ats.step(0.1, in);
  EXPECT_LT(ats.outputs().back_pressure_Pa - in.ambient_p_Pa, 0.1 * dp);
}

TEST(Aftertreatment, ConfigFileLoadsAndBadInputIsRejected) {
  const std::string file = test::sourceDir() + "/config/aftertreatment.yaml";
  ParamSource src = readYamlParams(file);
  AtsParams p;
  ParamSet ps;
  p.declare(ps);
  EXPECT_NO_THROW(applyParams(ps, src, {"cosim/"}));  // cosim/: the participant base class's
  EXPECT_EQ(p.scr.slices, 10);
  ASSERT_EQ(src.file, file);  // the errors below name it
  auto expectError = [&](const ParamSource& s, const std::string& key) {
    hbt::testing::expectRejected<AtsParams>(s, key, {"cosim/"});
  };
  ParamSource s = src;
  s.set("scr/lenght_m", 0.3);  // typo
  expectError(s, "scr/lenght_m");
  s = src;
  s.set("dosing/release_T_K", std::numeric_limits<double>::quiet_NaN());
  expectError(s, "dosing/release_T_K");
  s = src;
  s.set("doc/cpsi", 5000.0);
  expectError(s, "doc/cpsi");
  s = src;
  s.set("dpf/cpsi", 900.0);
  s.set("dpf/wall_thickness_mil", 30.0);  // thicker than the 900 cpsi pitch allows
  expectError(s, "dpf/wall_thickness_mil");
  // the YAML reader passes NaN through to the range check
  const ParamSource y = parseYamlParams("asc:\n  length_m: .nan\n", "aftertreatment.yaml");
  AtsParams q;
  ParamSet qs;
  q.declare(qs);
  EXPECT_THROW(applyParams(qs, y), InputError);
}

TEST(Aftertreatment, AWarmSystemWithoutFlowCoolsThroughItsCanOnly) {
  // A warm one-box at an engine stop: no exhaust flow. The gas temperature it is told has no
  // effect (no enthalpy flux), every brick cools towards ambient through its can alone, and the
  // energy balance closes with stored change = -(can loss + line-wall loss).
  const double Tamb = 313.15, Twarm = 623.15;
  AtsInputs off;
  off.exhaust_mass_flow_kg_s = 0.0;
  off.ambient_T_K = Tamb;
  off.comp.y_O2 = 0.232;
  off.comp.y_CO2 = off.comp.y_H2O = 0.0;
  off.comp.y_N2 = 0.768;
  Aftertreatment a(test::loadParams()), b(test::loadParams());
  a.reset(Twarm);
  b.reset(Twarm);
  std::array<double, kNumBricks> before{};
  for (int k = 0; k < 600; ++k) {  // a 60 s stop
    for (int i = 0; i < kNumBricks; ++i) before[i] = a.outputs().brick_T_K[i];
    off.exhaust_T_K = Tamb;
    a.step(0.1, off);
    off.exhaust_T_K = 900.0;  // any gas temperature: nothing flows
    b.step(0.1, off);
    for (int i = 0; i < kNumBricks; ++i) {
      ASSERT_EQ(a.outputs().brick_T_K[i], b.outputs().brick_T_K[i]) << i;
      ASSERT_LT(a.outputs().brick_T_K[i], before[i]) << i;  // cooling
      ASSERT_GT(a.outputs().brick_T_K[i], Tamb) << i;       // never below ambient
    }
  }
  const AtsEnergy& e = a.energy();
  EXPECT_EQ(e.enthalpy_in_J, 0.0);
  EXPECT_EQ(e.enthalpy_out_J, 0.0);
  EXPECT_GT(e.can_loss_J, 0.0);
  EXPECT_GT(e.line_loss_J, 0.0);
  EXPECT_NEAR(e.stored_change_J, -(e.can_loss_J + e.line_loss_J), 1e-9 * e.can_loss_J);
  EXPECT_EQ(a.nitrogen().nh3_dosed_mol, 0.0);  // no NOx, no flow: no dosing
  EXPECT_EQ(a.outputs().tailpipe_nox_kg, 0.0);
}

TEST(Aftertreatment, AWarmStartHasItsBricksAndNh3StoreAtTheStatedLevel) {
  // start:=warm: every brick at warm_start/brick_K, the SCR's NH3 store at nh3_fill_of_target x
  // the dosing's storage target (storageTarget_mol at that temperature: an independent sum of
  // equilibrium coverages), balances counting from there; lit off within the light-off filter
  // time at the first NOx-carrying flow.
  const AtsParams p = test::loadParams();
  Aftertreatment ats(p);
  ats.resetWarm(p.warm_brick_T_K, p.warm_nh3_fill);
  for (int b = 0; b < kNumBricks; ++b)
    for (int i = 0; i < ats.brick(b).slices(); ++i) ASSERT_EQ(ats.brick(b).T(i), p.warm_brick_T_K);
  const Brick& scr = ats.brick(kSCR);
  const double c_ref = p.dosing_ref_nh3_ppm * 1e-6 * units::kStandardAtmosphere_Pa / (kRu * p.warm_brick_T_K);
  const double target = scr.slices() * ats.scr().equilibriumCoverage(p.warm_brick_T_K, c_ref) *
                        p.scr_site_density_mol_m3 * scr.sliceVolume();
  EXPECT_GT(target, 0.0);
  EXPECT_NEAR(ats.outputs().nh3_stored_mol, p.warm_nh3_fill * target, 1e-12 * target);
  EXPECT_NEAR(ats.scr().storedMol(), p.warm_nh3_fill * target, 1e-12 * target);
  EXPECT_EQ(ats.energy().stored_change_J, 0.0);
  EXPECT_EQ(ats.nitrogen().nh3_stored_change_mol, 0.0);
  double t = 0.0;
  for (; t < 60.0 && !ats.outputs().light_off; t += 0.1) ats.step(0.1, transient(t, 298.15));
  EXPECT_TRUE(ats.outputs().light_off);
  EXPECT_LE(t, 4.0 * p.lightoff_filter_s);
  EXPECT_LT(std::abs(ats.energy().residual_J()), 1e-6 * ats.energy().enthalpy_in_J);
}

TEST(Aftertreatment, NonPhysicalInputStopsNamingTheQuantity) {
  Aftertreatment ats(test::loadParams());
  AtsInputs in;
  in.exhaust_mass_flow_kg_s = 0.1;
  in.exhaust_T_K = std::numeric_limits<double>::quiet_NaN();
  try {
    ats.step(0.1, in);
    FAIL();
  } catch (const ModelDivergence& e) {
    EXPECT_NE(std::string(e.what()).find("exhaust temperature"), std::string::npos);
  }
}

}  // namespace
}  // namespace hbt::aftertreatment
