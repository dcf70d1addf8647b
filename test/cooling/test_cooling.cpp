// Cooling model (src/cooling) against independent references: textbook ε-NTU, exact lumped
// warm-up, fan laws, rate-independent thermostat hysteresis, energy bookkeeping, bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "cooling/cooling_model.hpp"
#include "support.hpp"
#include "../common/param_checks.hpp"

using namespace hbt;
using namespace hbt::cooling;
using units::celsiusToK;
using units::rpmToRadps;
using hbt::testing::expectInputError;

namespace {

using test::yamlParams;

// Textbook formula written out independently of the library (Incropera Table 11.3).
double epsHand(double ntu, double cr) {
  return 1.0 - std::exp(std::pow(ntu, 0.22) / cr * (std::exp(-cr * std::pow(ntu, 0.78)) - 1.0));
}

}  // namespace

TEST(CoolingRadiator, EffectivenessMatchesPublishedExampleAndLimits) {
  // Nellis & Klein / EES heat-exchanger library example: UA = 75 W/K, C1 = 50, C2 = 30 W/K,
  // cross flow both unmixed -> ε = 0.7632.
  EXPECT_NEAR(effectivenessCrossflowUnmixed(75.0 / 30.0, 30.0 / 50.0), 0.7632, 5e-4);
  // C_r -> 0: every exchanger tends to 1 - exp(-NTU).
  EXPECT_NEAR(effectivenessCrossflowUnmixed(1.3, 1e-14), 1.0 - std::exp(-1.3), 1e-15);
  EXPECT_NEAR(effectivenessCrossflowUnmixed(1.3, 1e-6), 1.0 - std::exp(-1.3), 1e-5);
  // Inverse.
  for (double cr : {0.1, 0.4, 1.0})
    for (double ntu : {0.1, 0.8, 3.0})
      EXPECT_NEAR(ntuCrossflowUnmixed(effectivenessCrossflowUnmixed(ntu, cr), cr), ntu, 1e-9);
}

TEST(CoolingRadiator, RatedPointAndOffDesignAgainstHandEpsNtu) {
  const CoolingParams p = yamlParams();
  const CoolingModel m(p, "config/cooling.yaml");
  const Radiator& r = m.htRadiator();
  const double cpa = p.air.cp_J_kgK, cpc = p.ht.coolant_cp_J_kgK;
  const auto& rp = p.radiator;
  // Rated point reproduces the rated heat.
  {
    const double ca = rp.rated_air_mass_flow_kg_s * cpa, cc = rp.rated_coolant_mass_flow_kg_s * cpc;
    const double cmin = std::min(ca, cc), cr = cmin / std::max(ca, cc);
    const double q = epsHand(r.ratedUA_W_K() / cmin, cr) * cmin * (rp.rated_coolant_in_K - rp.rated_air_in_K);
    EXPECT_NEAR(q, rp.rated_heat_W, 1e-6 * rp.rated_heat_W);
    EXPECT_NEAR(r.conductance_W_K(rp.rated_air_mass_flow_kg_s, rp.rated_coolant_mass_flow_kg_s) *
                    (rp.rated_coolant_in_K - rp.rated_air_in_K),
                rp.rated_heat_W, 1e-6 * rp.rated_heat_W);
  }
  // Off-design: half air flow, a third of the coolant flow, coolant side now C_min.
  const double ma = 2.0, mc = 0.4;
  const double ha = r.ratedUA_W_K() / rp.air_side_resistance_fraction * std::pow(ma / rp.rated_air_mass_flow_kg_s, 0.6);
  const double hc = r.ratedUA_W_K() / (1 - rp.air_side_resistance_fraction) *
                    std::pow(mc / rp.rated_coolant_mass_flow_kg_s, 0.8);
  const double ua = 1.0 / (1.0 / ha + 1.0 / hc);
  const double ca = ma * cpa, cc = mc * cpc;
  const double cmin = std::min(ca, cc), cr = cmin / std::max(ca, cc);
  EXPECT_LT(cc, ca);
  const double q_hand = epsHand(ua / cmin, cr) * cmin * 60.0;
  EXPECT_NEAR(r.conductance_W_K(ma, mc) * 60.0, q_hand, 1e-9 * q_hand);
  EXPECT_NEAR(r.ua_W_K(ma, mc), ua, 1e-9 * ua);
  EXPECT_EQ(r.conductance_W_K(0.0, mc), 0.0);
}

TEST(CoolingModel, SteadyStateRadiatorHeatEqualsHandEpsNtu) {
  CoolingParams p = yamlParams();
  CoolingModel m(p);
  const double Ta = celsiusToK(25.0);
  m.reset(Ta);
  CoolingInputs in;
  in.engine_heat_W = 60e3;
  in.pump_speed_rad_s = rpmToRadps(1500.0);
  in.vehicle_speed_m_s = 10.0;
  in.ambient_T_K = Ta;
  for (int k = 0; k < 60000; ++k) m.step(0.1, in);  // 6000 s
  const CoolingOutputs& o = m.outputs();
  // Steady: heat in = radiator + surface loss.
  EXPECT_NEAR(o.radiator_ht_heat_W + o.surface_loss_W, in.engine_heat_W, 1e-3 * in.engine_heat_W);
  EXPECT_GT(o.thermostat_opening, 0.0);
  // Hand ε-NTU at the model's flows and temperatures (LT idle: HT air inlet = ambient).
  EXPECT_NEAR(o.ht_air_in_T_K, Ta, 1e-6);
  const double ma = o.air_mass_flow_kg_s, mc = o.radiator_coolant_flow_m3_s * p.ht.coolant_density_kg_m3;
  const double ca = ma * p.air.cp_J_kgK, cc = mc * p.ht.coolant_cp_J_kgK;
  const double cmin = std::min(ca, cc), cr = cmin / std::max(ca, cc);
  const double q = epsHand(m.htRadiator().ua_W_K(ma, mc) / cmin, cr) * cmin * (o.coolant_ht_T_K - Ta);
  EXPECT_NEAR(o.radiator_ht_heat_W, q, 1e-3 * q);
  // Air density from ambient T: ṁ = ρ V̇.
  EXPECT_NEAR(ma, 101325.0 / (287.05 * Ta) * o.air_volume_flow_m3_s, 1e-9);
  std::printf("steady 60 kW @1500 rpm, 10 m/s, 25 degC: T_c = %.2f degC, opening %.3f, fan %.0f rpm, "
              "%.0f W, air %.2f kg/s\n",
              units::kToCelsius(o.coolant_ht_T_K), o.thermostat_opening,
              units::radpsToRpm(o.fan_speed_rad_s), o.fan_power_W, ma);
}

TEST(CoolingModel, ThermostatHysteresisUpVersusDown) {
  CoolingParams p = yamlParams();
  p.thermostat.wax_time_constant_s = 0.0;  // rate-independent play band only
  CoolingModel m(p);
  const double Ta = celsiusToK(25.0);
  m.reset(Ta);
  CoolingInputs in;
  in.engine_heat_W = 150e3;
  in.pump_speed_rad_s = rpmToRadps(1500.0);
  in.ambient_T_K = Ta;
  const double Tq = celsiusToK(87.0);
  // The opening published after a step is the one that acted during it (set from the play
  // state at its start); sample it at the step in which T_c crosses 87 degC.
  double y_up = -1.0, y_down = -1.0, T_prev = Ta;
  bool cooling = false;
  for (int k = 0; k < 400000 && y_down < 0.0; ++k) {
    m.step(0.01, in);
    const double T = m.outputs().coolant_ht_T_K;
    const double yo = m.outputs().thermostat_opening;
    if (!cooling && T_prev < Tq && T >= Tq) y_up = yo;
    if (cooling && T_prev > Tq && T <= Tq) y_down = yo;
    if (!cooling && T >= celsiusToK(92.0)) {  // then cool down: no heat, ram air, fan on
      cooling = true;
      in.engine_heat_W = 0.0;
      in.vehicle_speed_m_s = 20.0;
      in.fan_demand = 1.0;
    }
    T_prev = T;
  }
  std::printf("opening at 87 degC: heating %.4f, cooling %.4f\n", y_up, y_down);
  ASSERT_GE(y_up, 0.0);
  ASSERT_GE(y_down, 0.0);
  const double span = p.thermostat.full_open_K - p.thermostat.opening_start_K;
  // Heating curve: (87 - 83)/12; cooling curve shifted down by the 3 K band: (87 + 3 - 83)/12.
  EXPECT_NEAR(y_up, 4.0 / span, 0.01);
  EXPECT_NEAR(y_down, 7.0 / span, 0.01);
  EXPECT_GT(y_down - y_up, 0.2);
}

TEST(CoolingModel, WaxLagWidensTheLoop) {
  // With the first-order wax lag the opening at 87 degC on heating is below the static curve.
  CoolingParams p = yamlParams();
  CoolingModel m(p);
  const double Ta = celsiusToK(25.0);
  m.reset(Ta);
  CoolingInputs in;
  in.engine_heat_W = 150e3;
  in.pump_speed_rad_s = rpmToRadps(1500.0);
  in.ambient_T_K = Ta;
  double T_prev = Ta;
  for (int k = 0; k < 100000; ++k) {
    m.step(0.01, in);
    const double T = m.outputs().coolant_ht_T_K;
    if (T_prev < celsiusToK(87.0) && T >= celsiusToK(87.0)) {
      EXPECT_LT(m.outputs().thermostat_opening, 4.0 / 12.0 - 0.05);
      return;
    }
    T_prev = T;
  }
  FAIL() << "87 degC not reached";
}

TEST(CoolingFan, WindmillingSignAtHighRamAirAndPositiveAtStandstill) {
  const CoolingParams p = yamlParams();
  const CoolingModel m(p);
  const auto& f = p.fan;
  const double n = rpmToRadps(250.0);  // disengaged fan at engine idle
  EXPECT_GT(m.airPath(n, 0.0).power_W, 0.0);
  EXPECT_LT(m.airPath(n, 25.0).power_W, 0.0);
  EXPECT_LT(m.airPath(n, 25.0).dp_Pa, 0.0);
  // Sign change exactly where the ram flow equals the fan's free delivery at its speed.
  const double q_free = f.free_delivery_ratio * f.rated_flow_m3_s * n / f.rated_speed_rad_s;
  const double v_star = q_free / (f.ram_recovery * f.grille_area_m2);
  EXPECT_GT(m.airPath(n, 0.999 * v_star).power_W, 0.0);
  EXPECT_LT(m.airPath(n, 1.001 * v_star).power_W, 0.0);
  EXPECT_NEAR(m.airPath(n, v_star).flow_m3_s, q_free, 1e-9);
  // Fan at rest: pure ram flow r v A, no power.
  EXPECT_NEAR(m.airPath(0.0, 12.0).flow_m3_s, f.ram_recovery * 12.0 * f.grille_area_m2, 1e-12);
  EXPECT_EQ(m.airPath(0.0, 12.0).power_W, 0.0);

  // Through the full model: cold engine at idle, 25 m/s -> the published fan power is negative.
  CoolingModel mm(p);
  mm.reset(celsiusToK(25.0));
  CoolingInputs in;
  in.pump_speed_rad_s = rpmToRadps(700.0);
  in.ambient_T_K = celsiusToK(25.0);
  in.vehicle_speed_m_s = 25.0;
  mm.step(0.01, in);
  EXPECT_LT(mm.outputs().fan_power_W, 0.0);
  EXPECT_NEAR(mm.outputs().fan_speed_rad_s, rpmToRadps(700.0) * f.drive_ratio * f.min_speed_ratio, 1e-12);
  EXPECT_EQ(mm.outputs().fan_drive_power_W, mm.outputs().fan_power_W);  // windmilling: no slip booked
  in.vehicle_speed_m_s = 0.0;
  mm.step(0.01, in);
  EXPECT_GT(mm.outputs().fan_power_W, 0.0);
  // Through the disengaged viscous clutch the crank delivers the same torque at the input speed.
  EXPECT_NEAR(mm.outputs().fan_drive_power_W, mm.outputs().fan_power_W / f.min_speed_ratio, 1e-9);
}

TEST(CoolingFan, FanLawsAtZeroRamAir) {
  const CoolingParams p = yamlParams();
  const CoolingModel m(p);
  const double nr = p.fan.rated_speed_rad_s;
  const auto r = m.airPath(nr, 0.0);
  EXPECT_NEAR(r.power_W, p.fan.rated_power_W, 1e-9 * p.fan.rated_power_W);
  EXPECT_NEAR(r.flow_m3_s, p.fan.rated_flow_m3_s, 1e-12);
  for (double x : {0.2, 0.5, 0.8, 1.3}) {
    const auto a = m.airPath(x * nr, 0.0);
    EXPECT_NEAR(a.power_W, p.fan.rated_power_W * x * x * x, 1e-9 * p.fan.rated_power_W);
    EXPECT_NEAR(a.flow_m3_s, p.fan.rated_flow_m3_s * x, 1e-12);
    EXPECT_NEAR(a.dp_Pa, r.dp_Pa * x * x, 1e-9 * r.dp_Pa);
  }
  // Density: P ∝ ρ at the same speed, volume flow unchanged (also with ram air).
  const double rho_r = p.fan.rated_air_density_kg_m3;
  for (double v : {0.0, 10.0}) {
    const auto a = m.airPath(0.6 * nr, v, rho_r), b = m.airPath(0.6 * nr, v, 1.1 * rho_r);
    EXPECT_NEAR(b.power_W, 1.1 * a.power_W, 1e-9 * std::abs(a.power_W));
    EXPECT_NEAR(b.flow_m3_s, a.flow_m3_s, 1e-12);
  }
}

TEST(CoolingModel, ClosedThermostatWarmupIsExactLumpedHeating) {
  CoolingParams p = yamlParams();
  p.ht.surface_loss_UA_W_K = 0.0;
  p.thermostat.leak_fraction = 0.0;
  CoolingModel m(p);
  const double Ta = celsiusToK(25.0);  // above the heater balance point: no heater
  m.reset(Ta);
  CoolingInputs in;
  in.engine_heat_W = 45e3;      // into the metal
  in.engine_oil_heat_W = 5e3;   // friction heat into the oil
  in.pump_speed_rad_s = rpmToRadps(1200.0);
  in.ambient_T_K = Ta;
  // ΣmC by hand from the parameters. Thermostat and heater valve shut (no heating at 25 degC):
  // only the engine loop's coolant takes part, as if the radiator and convector volumes did not
  // exist.
  const double Cm = p.ht.metal_mass_kg * p.ht.metal_cp_J_kgK;
  const double Co = p.ht.oil_mass_kg * p.ht.oil_cp_J_kgK;
  const double Q = in.engine_heat_W + in.engine_oil_heat_W;
  const double Cc = p.ht.engine_loop_volume_m3 * p.ht.coolant_density_kg_m3 * p.ht.coolant_cp_J_kgK;
  const double dt = 0.01;
  int k = 0;
  for (; k < 25000; ++k) {  // 250 s: still below the opening start
    m.step(dt, in);
    ASSERT_EQ(m.outputs().radiator_ht_heat_W, 0.0);
    ASSERT_EQ(m.outputs().heater_loop_flow_m3_s, 0.0);
  }
  const CoolingOutputs& o = m.outputs();
  const double t = k * dt;
  const double sumC = Cm + Co + Cc;
  const double mean_rise = (Cm * (o.metal_T_K - Ta) + Co * (o.oil_T_K - Ta) + Cc * (o.coolant_ht_T_K - Ta)) / sumC;
  EXPECT_NEAR(mean_rise, Q * t / sumC, 1e-9 * mean_rise);
  // Metal and oil lead the coolant by the ramp offsets (support.hpp) once the initial
  // transients are over (the oil's, τ ~ 40 s, leaves ~5 mK after 250 s).
  const double r = Q / sumC;
  const test::RampOffsets lead = test::rampOffsets(p.ht.metal_to_coolant_UA_W_K, p.ht.oil_to_metal_UA_W_K,
                                                   p.ht.oil_cooler_UA_W_K, Co, in.engine_oil_heat_W, r, Cc * r);
  EXPECT_NEAR(o.metal_T_K - o.coolant_ht_T_K, lead.metal_K, 1e-3);
  EXPECT_NEAR(o.oil_T_K - o.coolant_ht_T_K, lead.oil_K, 1e-2);
  // Warm-up time: T_c(t) = T_a + r t - (C_m a + C_o b)/ΣC -> t_w.
  for (; o.warmup_time_s < 0.0 && k < 100000; ++k) m.step(dt, in);
  const double t_w = (p.thermostat.opening_start_K - Ta) / r + (Cm * lead.metal_K + Co * lead.oil_K) / (sumC * r);
  EXPECT_NEAR(o.warmup_time_s, t_w, 0.05);
  EXPECT_EQ(o.radiator_coolant_T_K, Ta);  // the shut-off volumes kept their temperature
  EXPECT_EQ(o.convector_coolant_T_K, Ta);
  std::printf("warm-up 50 kW from 25 degC: %.2f s (analytic %.2f s)\n", o.warmup_time_s, t_w);
}

TEST(CoolingModel, EnergyBalanceOverColdTransientWithHeaterAndLt) {
  CoolingParams p = yamlParams();
  CoolingModel m(p);
  const double Ta = celsiusToK(0.0);
  m.reset(Ta);
  const double dt = 0.05;  // one substep per step: the published fluxes are those integrated
  double e_in = 0, e_out = 0, heater_max = 0;
  CoolingInputs in;
  in.ambient_T_K = Ta;
  for (int k = 0; k < 80000; ++k) {  // 4000 s
    const double t = k * dt;
    in.engine_heat_W = 40e3 + 30e3 * std::sin(2 * units::kPi * t / 120.0);
    in.engine_oil_heat_W = 4e3 + 3e3 * std::sin(2 * units::kPi * t / 50.0);
    in.pump_speed_rad_s = rpmToRadps(900.0 + 500.0 * std::sin(2 * units::kPi * t / 60.0));
    in.vehicle_speed_m_s = 8.0 + 8.0 * std::sin(2 * units::kPi * t / 90.0);
    in.lt_heat_W = 3e3 * (1.0 + std::sin(2 * units::kPi * t / 45.0));
    in.em_engine_heat_W = 1.2e3 * (0.5 + 0.5 * std::sin(2 * units::kPi * t / 70.0));  // metal -> P1 flange
    in.gearbox_cooler_heat_W = t > 2000.0 ? 2.5e3 * (0.5 + 0.5 * std::sin(2 * units::kPi * t / 33.0)) : 0.0;
    m.step(dt, in);
    const CoolingOutputs& o = m.outputs();
    e_in += (in.engine_heat_W + in.engine_oil_heat_W + in.lt_heat_W - in.em_engine_heat_W + in.gearbox_cooler_heat_W) * dt;
    e_out += (o.radiator_ht_heat_W + o.radiator_lt_heat_W + o.heater_heat_W + o.surface_loss_W) * dt;
    heater_max = std::max(heater_max, o.heater_heat_W);
  }
  const CoolingOutputs& o = m.outputs();
  const NetworkCapacities& C = m.capacities();
  const double stored = C.metal * (o.metal_T_K - Ta) + C.engine_loop * (o.coolant_ht_T_K - Ta) +
                        C.radiator * (o.radiator_coolant_T_K - Ta) + C.convector * (o.convector_coolant_T_K - Ta) +
                        C.lt * (o.coolant_lt_T_K - Ta) + C.oil * (o.oil_T_K - Ta);
  EXPECT_NEAR(e_in - e_out - stored, 0.0, 1e-6 * e_in);
  EXPECT_NEAR(o.energy_residual_J, 0.0, 1e-6 * e_in);
  EXPECT_NEAR(o.engine_heat_J + o.engine_oil_heat_J + o.lt_heat_J - o.em_engine_heat_J + o.gearbox_cooler_J, e_in,
              1e-9 * e_in);
  EXPECT_GT(o.em_engine_heat_J, 0.0);
  EXPECT_GT(o.gearbox_cooler_J, 0.0);
  // Heater at 0 degC: demand UA (15 - 0) K = 12 kW once the coolant is warm.
  EXPECT_NEAR(heater_max, p.heater.cabin_UA_W_K * 15.0, 1e-6);
  EXPECT_GT(o.heater_J, 0.0);
  EXPECT_GT(o.warmup_time_s, 0.0);
  std::printf("0 degC transient: warm-up %.0f s, heat in %.1f MJ, heater %.1f MJ, radiator %.1f MJ, "
              "residual %.3g J (own bookkeeping %.3g J)\n",
              o.warmup_time_s, e_in / 1e6, o.heater_J / 1e6, o.radiator_ht_J / 1e6, o.energy_residual_J,
              e_in - e_out - stored);
}

TEST(CoolingModel, HeaterOffAboveBalanceAndCapacityLimitedWhenCool) {
  CoolingParams p = yamlParams();
  CoolingModel m(p);
  CoolingInputs in;
  in.engine_heat_W = 80e3;
  in.pump_speed_rad_s = rpmToRadps(1200.0);
  in.ambient_T_K = celsiusToK(20.0);
  m.reset(in.ambient_T_K);
  for (int k = 0; k < 20000; ++k) m.step(0.05, in);
  EXPECT_EQ(m.outputs().heater_J, 0.0);
  // At -20 degC the 28 kW demand exceeds the convectors' G (T_v - T_a) <= 24 kW once their
  // water is just above their 40 degC lockout.
  in.ambient_T_K = celsiusToK(-20.0);
  m.reset(in.ambient_T_K);
  while (m.outputs().convector_coolant_T_K < celsiusToK(40.5)) m.step(0.05, in);
  m.step(0.05, in);
  ASSERT_TRUE(m.outputs().heater_valve_open);
  const double T = m.outputs().convector_coolant_T_K;  // the convectors' water
  EXPECT_NEAR(m.outputs().heater_heat_W, p.heater.conductance_W_K * (T - in.ambient_T_K), 1.0);
  EXPECT_LT(m.outputs().heater_heat_W, p.heater.cabin_UA_W_K * 35.0);
}

TEST(CoolingLt, PumpSpeedRuleLimitsAndPreheatOfHtAir) {
  CoolingParams p = yamlParams();
  CoolingModel m(p);
  const double Ta = celsiusToK(25.0);
  m.reset(Ta);
  CoolingInputs in;
  in.pump_speed_rad_s = rpmToRadps(1000.0);
  in.ambient_T_K = Ta;
  for (int k = 0; k < 2000; ++k) m.step(0.05, in);
  const double w_idle = p.lt.pump_idle_speed_rad_s, w_max = p.lt.pump_max_speed_rad_s;
  EXPECT_NEAR(units::radpsToRpm(w_idle), 200.0, 1e-3);  // SPEC §5: 200 rpm idle ...
  EXPECT_NEAR(units::radpsToRpm(w_max), 600.0, 1e-3);   // ... up to ~600 rpm
  EXPECT_NEAR(m.outputs().lt_pump_speed_rad_s, w_idle, 1e-9);  // LT cold: idle
  EXPECT_NEAR(m.ltPumpTarget(celsiusToK(50.0)), 0.5 * (w_idle + w_max), 1e-9);
  EXPECT_NEAR(m.ltPumpTarget(celsiusToK(90.0)), w_max, 1e-12);
  EXPECT_NEAR(m.ltPumpTarget(celsiusToK(-20.0)), w_idle, 1e-12);
  // Heat into the LT circuit: the coolant passes 60 degC, the pump reaches 600 rpm.
  in.lt_heat_W = 12e3;
  in.vehicle_speed_m_s = 0.0;
  for (int k = 0; k < 40000 && m.outputs().coolant_lt_T_K < celsiusToK(62.0); ++k) m.step(0.05, in);
  for (int k = 0; k < 2000; ++k) m.step(0.05, in);  // 100 s >> 5 s clutch lag
  const CoolingOutputs& o = m.outputs();
  ASSERT_GT(o.coolant_lt_T_K, celsiusToK(60.0));
  EXPECT_NEAR(o.lt_pump_speed_rad_s, w_max, 1e-6);
  EXPECT_GT(o.lt_pump_power_W, 0.0);
  EXPECT_GT(o.lt_pump_energy_J, 0.0);
  // LT radiator pre-heats the HT radiator air: ΔT_air = Q_LT/(ṁ_air c_p).
  EXPECT_NEAR(o.ht_air_in_T_K - Ta, o.radiator_lt_heat_W / (o.air_mass_flow_kg_s * p.air.cp_J_kgK), 1e-9);
  EXPECT_GT(o.ht_air_in_T_K - Ta, 0.5);
  // Hydraulic power at 600 rpm = rated head x rated flow; input = shaft (clutch input 1000 rpm):
  EXPECT_NEAR(o.lt_pump_hydraulic_power_W, p.lt.pump_rated_head_Pa * p.lt.pump_rated_flow_m3_s, 1e-6);
  EXPECT_NEAR(o.lt_pump_power_W,
              o.lt_pump_hydraulic_power_W / p.lt.pump_efficiency * rpmToRadps(1000.0) / o.lt_pump_speed_rad_s, 1e-9);
  // Capped by the clutch input speed (crank at 300 rpm).
  in.pump_speed_rad_s = rpmToRadps(300.0);
  m.step(0.05, in);
  EXPECT_NEAR(units::radpsToRpm(m.outputs().lt_pump_speed_rad_s), 300.0, 1e-9);
}

TEST(CoolingModel, HtPumpAffinityAndDeterminism) {
  const CoolingParams p = yamlParams();
  CoolingModel a(p), b(p);
  CoolingInputs in;
  in.pump_speed_rad_s = p.ht.pump_rated_speed_rad_s;
  in.engine_heat_W = 70e3;
  in.ambient_T_K = celsiusToK(40.0);
  a.reset(in.ambient_T_K);
  b.reset(in.ambient_T_K);
  a.step(0.01, in);
  EXPECT_NEAR(a.outputs().pump_power_W, p.ht.pump_rated_head_Pa * p.ht.pump_rated_flow_m3_s / p.ht.pump_efficiency, 1e-9);
  in.pump_speed_rad_s *= 0.5;
  a.step(0.01, in);
  EXPECT_NEAR(a.outputs().pump_power_W, p.ht.pump_rated_head_Pa * p.ht.pump_rated_flow_m3_s / p.ht.pump_efficiency / 8.0, 1e-9);
  a.reset(in.ambient_T_K);
  for (int k = 0; k < 5000; ++k) {
    in.vehicle_speed_m_s = (k % 700) * 0.02;
    a.step(0.1, in);
    b.step(0.1, in);
  }
  EXPECT_EQ(a.outputs().coolant_ht_T_K, b.outputs().coolant_ht_T_K);
  EXPECT_EQ(a.outputs().fan_energy_J, b.outputs().fan_energy_J);
}

TEST(CoolingParams, YamlMatchesDeclarationAndBadValuesRejected) {
  CoolingParams p;
  ParamSet ps;
  p.declare(ps);
  const ParamSource src = readYamlParams("config/cooling.yaml");
  EXPECT_NO_THROW(applyParams(ps, src, {"cosim/"}));
  for (const auto& e : ps.entries()) EXPECT_TRUE(src.values.count(e.key)) << "missing in YAML: " << e.key;
  for (const auto& kv : src.values) {
    bool known = false;
    for (const auto& e : ps.entries()) known |= e.key == kv.first;
    bool participants = false;  // cosim/, diagnostics/: read by the participant, not the model
    for (const auto& section : kParticipantSections) participants |= kv.first.rfind(section, 0) == 0;
    EXPECT_TRUE(known || participants) << kv.first;
  }
  auto expectKey = [](const ParamSource& s, const std::string& key) {
    hbt::testing::expectRejected<CoolingParams>(s, key);
  };
  ParamSource bad;
  bad.file = "cooling.yaml";
  bad.set("fan/rated_powr_W", 1.0);  // unknown (typo)
  expectKey(bad, "fan/rated_powr_W");
  bad.values.clear();
  bad.set("radiator/rated_heat_W", std::nan(""));
  expectKey(bad, "radiator/rated_heat_W");
  bad.values.clear();
  bad.set("thermostat/hysteresis_K", 40.0);  // out of range
  expectKey(bad, "thermostat/hysteresis_K");

  CoolingParams q = p;
  q.thermostat.full_open_K = q.thermostat.opening_start_K - 1.0;
  expectInputError([&] { CoolingModel m(q, "cooling.yaml"); }, "cooling.yaml", "thermostat/full_open_K");
  CoolingParams r = p;
  r.radiator.rated_heat_W = 5e5;  // would need ε > 1
  expectInputError([&] { CoolingModel m(r, "cooling.yaml"); }, "cooling.yaml", "radiator/rated_heat_W");
}

TEST(CoolingModel, BadStepInputAndDivergenceNamed) {
  const CoolingParams p = yamlParams();
  CoolingModel m(p);
  m.reset(celsiusToK(25.0));
  CoolingInputs in;
  in.ambient_T_K = celsiusToK(25.0);
  in.engine_heat_W = std::nan("");
  expectInputError([&] { m.step(0.01, in); }, "cooling step input", "engine_heat_W");
  in.engine_heat_W = 1e9;  // absurd heat: the metal leaves the physical range
  try {
    for (int k = 0; k < 1000; ++k) m.step(0.01, in);
    FAIL();
  } catch (const ModelDivergence& e) {
    EXPECT_NE(std::string(e.what()).find("temperature"), std::string::npos) << e.what();
  }
}

TEST(CoolingModel, HeaterValveCyclesWithHysteresisAtLowHeat) {
  // 0 degC, idling engine (8 kW) below the 12 kW cabin demand: the coolant cannot stay warm;
  // the heater valve opens at 40 degC and shuts below 35 degC. Each opening lets the cold
  // convector volume (25 L) into the 10 L engine loop, which then falls 5 K within seconds;
  // the convectors draw only once their own water is at 40 degC (their lockout), so the engine
  // loop first climbs above 40 degC: the valve cycles, each phase lasting hundreds of steps
  // (no chatter), and the engine loop never falls below the valve's 35 degC.
  CoolingParams p = yamlParams();
  CoolingModel m(p);
  CoolingInputs in;
  in.engine_heat_W = 8e3;
  in.pump_speed_rad_s = rpmToRadps(700.0);
  in.ambient_T_K = celsiusToK(0.0);
  m.reset(in.ambient_T_K);
  while (m.outputs().coolant_ht_T_K < celsiusToK(40.0)) m.step(0.01, in);
  int switches = 0;
  bool on = m.outputs().heater_valve_open;
  double Tmin = 1e9, Tmax = 0, t_switch = 0.0, shortest = 1e9;
  for (int k = 0; k < 300000; ++k) {  // 3000 s
    m.step(0.01, in);
    const bool now = m.outputs().heater_valve_open;
    if (now != on) {
      ++switches;
      if (switches > 1) shortest = std::min(shortest, k * 0.01 - t_switch);
      t_switch = k * 0.01;
    }
    on = now;
    if (m.outputs().heater_heat_W > 0.0) {  // heat only from warm convector water (their lockout)
      EXPECT_GT(m.outputs().convector_coolant_T_K, celsiusToK(35.0 - 0.5)) << k;
    }
    Tmin = std::min(Tmin, m.outputs().coolant_ht_T_K);
    Tmax = std::max(Tmax, m.outputs().coolant_ht_T_K);
  }
  std::printf("heater cycling at 0 degC, 8 kW: %d switches in 3000 s, shortest phase %.1f s, T_c %.2f..%.2f degC, "
              "convectors %.2f degC\n",
              switches, shortest, units::kToCelsius(Tmin), units::kToCelsius(Tmax),
              units::kToCelsius(m.outputs().convector_coolant_T_K));
  EXPECT_GE(switches, 2);
  EXPECT_GT(shortest, 2.0);  // > 200 steps
  EXPECT_GT(Tmin, celsiusToK(35.0 - 0.5));
}

// The hvac participant's cabin (hvac:=on): its demand served up to the convectors' capacity
// G_h (T_v - T_cabin) at the convector water temperature once that water is warm (whatever the
// valve to the engine), the fuel-fired heater's heat (into the heating loop) counted as heat in,
// the balance closed.
TEST(CoolingModel, HvacDemandToTheCabinAndFuelHeaterHeatCloseTheBalance) {
  CoolingParams p = yamlParams();
  CoolingModel m(p);
  const double Ta = celsiusToK(0.0);
  m.reset(Ta);
  CoolingInputs in;
  in.ambient_T_K = Ta;
  in.engine_heat_W = 15e3;
  in.pump_speed_rad_s = rpmToRadps(800.0);
  in.cabin_from_hvac = true;
  in.cabin_T_K = celsiusToK(10.0);
  in.cabin_heat_demand_W = 30e3;
  in.aux_heater_heat_W = 30e3;
  const double dt = 0.1;
  double e_in = 0, e_out = 0;
  bool capacity_seen = false, demand_seen = false;
  for (int k = 0; k < 30000; ++k) {
    in.cabin_heat_demand_W = k < 15000 ? 30e3 : 8e3;
    const double T_c = m.outputs().coolant_ht_T_K, T_v = m.outputs().convector_coolant_T_K;
    m.step(dt, in);
    const CoolingOutputs& o = m.outputs();
    const double T_v1 = o.convector_coolant_T_K;
    if (T_c >= p.heater.min_coolant_K + 1.0) {
      ASSERT_TRUE(o.heater_valve_open);
    }
    if (T_v >= p.heater.min_coolant_K + 1.0) {  // convectors warm: the demand if they can at their
      // water temperature (at the step's start), else the conductance branch of the implicit
      // update G_h (T_v,new - T_cab)
      if (p.heater.conductance_W_K * (T_v - in.cabin_T_K) < in.cabin_heat_demand_W) {
        EXPECT_NEAR(o.heater_heat_W, p.heater.conductance_W_K * (T_v1 - in.cabin_T_K), 1e-6);
        capacity_seen = true;
      } else {
        EXPECT_NEAR(o.heater_heat_W, in.cabin_heat_demand_W, 1e-6);
        demand_seen = true;
      }
    }
    if (T_v < p.heater.min_coolant_K - p.heater.lockout_hysteresis_K) {
      EXPECT_EQ(o.heater_heat_W, 0.0);
    }
    e_in += (in.engine_heat_W + in.aux_heater_heat_W) * dt;
    e_out += (o.radiator_ht_heat_W + o.radiator_lt_heat_W + o.heater_heat_W + o.surface_loss_W) * dt;
  }
  EXPECT_TRUE(capacity_seen);
  EXPECT_TRUE(demand_seen);
  const CoolingOutputs& o = m.outputs();
  EXPECT_NEAR(o.aux_heater_J, 30e3 * 3000.0, 1e-6);
  EXPECT_NEAR(o.energy_residual_J, 0.0, 1e-9 * e_in);
  EXPECT_NEAR(e_in - e_out - o.stored_change_J, 0.0, 1e-9 * e_in);
}
