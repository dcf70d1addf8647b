// Battery model (src/battery) against independent references: hand-solved equivalent circuit at
// a table point, analytic RC response, coulomb counting, the two kinds of power limit (cut-off
// voltage vs matched load), energy bookkeeping, derating, bad input. The enclosure's thermal
// network: test_pack_thermal.cpp; the fan's thermostat and its energy: test_pack_fan.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

#include "battery/battery_model.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "../common/alloc_counter.hpp"
#include "../common/param_checks.hpp"

using namespace hbt;
using namespace hbt::battery;
using hbt::testing::expectInputError;
using units::celsiusToK;

namespace {

BatteryParams yamlParams() {
  BatteryParams p;
  ParamSet ps;
  p.declare(ps);
  // cosim/ keys (the node's macro step) belong to the participant base class, as in the node
  applyParams(ps, readYamlParams("config/battery.yaml"), {"cosim/"});
  return p;
}

// A synthetic cell table on SOC {0, 0.5, 1} x T {250, 350} K with the values of `f` (so that
// the bilinear interpolation reproduces any f linear in SOC and T exactly).
std::string writeTable(const std::string& name, const std::function<CellPoint(double, double)>& f,
                       const std::string& extra_rows = "") {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream o(path);
  o << "# synthetic test table\nSOC [-],T [K],OCV [V],R0 [Ohm],R1 [Ohm],tau1 [s]\n";
  o.precision(17);
  for (double s : {0.0, 0.5, 1.0})
    for (double T : {250.0, 350.0}) {
      const CellPoint c = f(s, T);
      o << s << "," << T << "," << c.ocv_V << "," << c.r0_Ohm << "," << c.r1_Ohm << "," << c.tau1_s << "\n";
    }
  o << extra_rows;
  return path;
}

// Constant R0, R1, tau1; OCV = 3.5 + 0.5 s (linear, temperature-independent).
constexpr double kR0 = 0.010, kR1 = 0.005, kTau = 30.0;
std::string constantTable(double r1 = kR1) {
  return writeTable("battery_const.csv", [r1](double s, double) { return CellPoint{3.5 + 0.5 * s, kR0, r1, kTau}; });
}

// Terminal power request that makes the cell current exactly i in the next step of length h
// (inverts the model's own step-mean voltage; used only to impose a constant current).
double requestForCellCurrent(const BatteryModel& m, double h, double i) {
  const StepEnvelope e = m.envelope(h);
  return m.cells() * i * (e.emf_V - i * e.r_eff_Ohm);
}

}  // namespace

TEST(BatteryTable, InterpolationAndClamping) {
  const BatteryParams p = yamlParams();
  const BatteryModel m(p, "config/battery.yaml");
  const CellTable& t = m.cellTable();
  // Table points (CSV rows 0.5/293 and 0.25/313).
  CellPoint c = t.at(0.5, 293.0);
  EXPECT_DOUBLE_EQ(c.ocv_V, 3.71);
  EXPECT_DOUBLE_EQ(c.r0_Ohm, 0.0082);
  EXPECT_DOUBLE_EQ(c.r1_Ohm, 0.0016);
  EXPECT_DOUBLE_EQ(c.tau1_s, 29.0);
  EXPECT_DOUBLE_EQ(t.at(0.25, 313.0).tau1_s, 61.0);
  // Bilinear by hand at SOC 0.375, T 303 K: corners (0.25, 293) 3.63, (0.25, 313) 3.64,
  // (0.5, 293) 3.71, (0.5, 313) 3.72.
  const double hand = 0.5 * (0.5 * 3.63 + 0.5 * 3.64) + 0.5 * (0.5 * 3.71 + 0.5 * 3.72);
  EXPECT_NEAR(t.ocv(0.375, 303.0), hand, 1e-14);
  // Clamped at the warm and SOC edges: 50 degC uses the 313 K column, SOC > 1 the 1 row.
  EXPECT_DOUBLE_EQ(t.at(0.9, 330.0).r1_Ohm, 0.0011);
  EXPECT_DOUBLE_EQ(t.ocv(1.2, 293.0), 4.19);
}

TEST(BatteryTable, ColdCellsFollowTheArrheniusLawOfTheTwoColdestColumns) {
  const BatteryModel m(yamlParams(), "config/battery.yaml");
  const CellTable& t = m.cellTable();
  // CSV rows SOC 0.5 at 278 and 293 K: R0 0.0107 / 0.0082, R1 0.0034 / 0.0016 Ohm. The Arrhenius
  // law through both points, written out here: R(T) = R(278) (R(278)/R(293))^((1/T - 1/278) /
  // (1/278 - 1/293)).
  auto law = [](double r278, double r293, double T) {
    return r278 * std::pow(r278 / r293, (1.0 / T - 1.0 / 278.0) / (1.0 / 278.0 - 1.0 / 293.0));
  };
  for (double T : {273.15, 263.15, 253.15}) {
    const CellPoint c = t.at(0.5, T);
    EXPECT_NEAR(c.r0_Ohm, law(0.0107, 0.0082, T), 1e-15) << T;
    EXPECT_NEAR(c.r1_Ohm, law(0.0034, 0.0016, T), 1e-15) << T;
    EXPECT_DOUBLE_EQ(c.ocv_V, 3.71);  // OCV and tau1 held at the 278 K column
    EXPECT_DOUBLE_EQ(c.tau1_s, 36.0);
  }
  // 0 degC against 5 degC: R0 +9.7 %, R1 +30 % (activation energies 12 and 34 kJ/mol)
  EXPECT_NEAR(t.at(0.5, 273.15).r0_Ohm / 0.0107, 1.0967, 5e-4);
  EXPECT_NEAR(t.at(0.5, 273.15).r1_Ohm / 0.0034, 1.299, 5e-3);
  // continuous at the table's edge; the law returns the warmer point it was drawn through
  EXPECT_DOUBLE_EQ(t.at(0.5, 278.0).r0_Ohm, 0.0107);
  EXPECT_NEAR(t.at(0.5, 278.0 - 1e-9).r0_Ohm, 0.0107, 1e-12);
  EXPECT_NEAR(CellTable::arrhenius(0.0107, 0.0082, 278.0, 293.0, 293.0), 0.0082, 1e-15);
  // a table that falls towards the cold is held at its edge (no negative activation energy)
  EXPECT_DOUBLE_EQ(CellTable::arrhenius(0.0090, 0.0100, 278.0, 293.0, 250.0), 0.0090);
}

TEST(BatteryModel, TerminalVoltageAtTablePointMatchesHandSolvedCircuit) {
  // 10 kW from rest at SOC 0.5, 293 K (a table point): per cell, step-mean
  // v = OCV - i R0 - i R1 (1 - f), f = (tau/h)(1 - e^{-h/tau}), and P = Ns Np i v. Solved here by
  // bisection from the table values.
  const BatteryParams p = yamlParams();
  BatteryModel m(p, "config/battery.yaml");
  m.reset(293.0, 0.5);
  const double h = 0.01, P = 10e3, N = 91.0;
  const double f = 29.0 / h * (1.0 - std::exp(-h / 29.0));
  auto v = [&](double i) { return 3.71 - i * 0.0082 - i * 0.0016 * (1.0 - f); };
  double lo = 0.0, hi = 3.71 / (2 * 0.0098);
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (N * mid * v(mid) < P ? lo : hi) = mid;
  }
  const double i = 0.5 * (lo + hi);
  BatteryInputs in;
  in.power_request_W = P;
  in.air_T_K = 293.0;
  m.step(h, in);
  const BatteryOutputs& o = m.outputs();
  EXPECT_NEAR(o.current_A, 7.0 * i, 1e-9 * 7.0 * i);
  EXPECT_NEAR(o.terminal_voltage_V, 13.0 * v(i), 1e-10);
  EXPECT_NEAR(o.terminal_voltage_V * o.current_A, P, 1e-9 * P);
  EXPECT_FALSE(o.request_limited);
  // RC voltage after the step: i R1 (1 - e^{-h/tau}).
  EXPECT_NEAR(m.cellRcVoltage_V(), i * 0.0016 * (1.0 - std::exp(-h / 29.0)), 1e-15);
  std::printf("10 kW at SOC 0.5, 20 degC: I = %.3f A, V_t = %.4f V (OCV %.2f V)\n", o.current_A,
              o.terminal_voltage_V, 13 * 3.71);
}

TEST(BatteryModel, PowerRequestMetExactlyWithinLimits) {
  const BatteryParams p = yamlParams();
  BatteryModel m(p, "config/battery.yaml");
  m.reset(celsiusToK(25.0));
  BatteryInputs in;
  in.air_T_K = celsiusToK(25.0);
  double worst = 0.0;
  for (int k = 0; k < 20000; ++k) {
    // Mixed requests inside the envelope: -15..+15 kW, a change every 0.5 s.
    in.power_request_W = 15e3 * std::sin(0.37 * std::floor(k / 50.0)) * std::cos(0.011 * k);
    m.step(0.01, in);
    const BatteryOutputs& o = m.outputs();
    ASSERT_FALSE(o.request_limited) << "request " << in.power_request_W << " at step " << k;
    EXPECT_EQ(o.unmet_power_W, 0.0);
    const double err = std::abs(o.terminal_voltage_V * o.current_A - in.power_request_W);
    worst = std::max(worst, err / std::max(1.0, std::abs(in.power_request_W)));
    ASSERT_NEAR(o.power_W, in.power_request_W, 1e-9 * std::max(1.0, std::abs(in.power_request_W)));
  }
  std::printf("max |V_t I - P|/|P| over 20000 steps: %.2e\n", worst);
  EXPECT_LT(worst, 1e-12);
}

TEST(BatteryModel, ConstantCurrentSocDropIsCoulombCount) {
  // 1C per cell (27 A, 189 A pack) for 1800 s: ΔSOC = I t/(3600 C) = 0.5 exactly.
  BatteryParams p = yamlParams();
  p.limits.soc_min = 0.0;  // let the discharge go through the window (voltage limit far away)
  p.limits.soc_taper = 1e-3;
  p.cell.min_voltage_V = 2.5;
  p.fan.rated_power_W = 0.0;  // its draw would change the current when it switches (test_pack_fan)
  BatteryModel m(p);
  m.reset(celsiusToK(25.0), 0.9);
  BatteryInputs in;
  in.air_T_K = celsiusToK(25.0);
  const double h = 0.01, i = 27.0;
  for (int k = 0; k < 180000; ++k) {
    in.power_request_W = requestForCellCurrent(m, h, i);
    m.step(h, in);
    ASSERT_NEAR(m.outputs().current_A, 7.0 * i, 1e-9);
  }
  const double dsoc = 0.9 - m.outputs().soc;
  std::printf("1C for 1800 s: SOC drop %.15f (expected 0.5), throughput %.9f Ah\n", dsoc,
              m.outputs().charge_throughput_Ah);
  // 180000 subtractions of 2.8e-6 from ~0.5: rounding accumulates to a few 1e-12.
  EXPECT_NEAR(dsoc, 7.0 * i * 1800.0 / (3600.0 * 7.0 * 27.0), 1e-10);
  EXPECT_NEAR(m.outputs().charge_throughput_Ah, 7.0 * i * 1800.0 / 3600.0, 1e-8);
}

TEST(BatteryModel, RcVoltageFollowsAnalyticStepResponse) {
  // Constant R1 = 5 mOhm, tau = 30 s: v1(t) = i R1 (1 - e^{-t/tau}) under a constant current,
  // then free decay v1(t1) e^{-(t - t1)/tau} at rest (zero request -> i = 0 exactly).
  BatteryParams p = yamlParams();
  p.cell.table_file = constantTable();
  p.fan.rated_power_W = 0.0;  // its draw would change the current when it switches (test_pack_fan)
  BatteryModel m(p);
  m.reset(celsiusToK(25.0), 0.5);
  BatteryInputs in;
  in.air_T_K = celsiusToK(25.0);
  const double h = 0.01, i = 40.0;
  double worst = 0.0;
  for (int k = 1; k <= 6000; ++k) {
    in.power_request_W = requestForCellCurrent(m, h, i);
    m.step(h, in);
    const double ref = i * kR1 * (1.0 - std::exp(-k * h / kTau));
    worst = std::max(worst, std::abs(m.cellRcVoltage_V() - ref));
  }
  const double v_60 = m.cellRcVoltage_V();
  in.power_request_W = 0.0;
  for (int k = 1; k <= 6000; ++k) {
    m.step(h, in);
    ASSERT_EQ(m.outputs().current_A, 0.0);
    worst = std::max(worst, std::abs(m.cellRcVoltage_V() - v_60 * std::exp(-k * h / kTau)));
  }
  std::printf("RC step response vs i R1 (1 - e^-t/tau): max error %.2e V (of %.3f V)\n", worst, i * kR1);
  EXPECT_LT(worst, 1e-13);
  // At rest the step-mean terminal voltage is Ns (OCV - mean v1), mean v1 over the last step =
  // v1_end (tau/h)(e^{h/tau} - 1).
  const BatteryOutputs& o = m.outputs();
  EXPECT_NEAR(o.terminal_voltage_V, o.ocv_V - 13.0 * m.cellRcVoltage_V() * kTau / h * std::expm1(h / kTau), 1e-12);
}

TEST(BatteryModel, RequestAboveLimitDeliversTheCutOffVoltageLimit) {
  // Which limit binds: P(i) = Ns Np i (E - i R) peaks at i* = E/(2R) with P* = Ns Np E^2/(4R) and
  // v = E/2 ~ 1.86 V. The cut-off V_min = 3.0 V > E/2 is reached at i_v = (E - V_min)/R < i*, so
  // the delivered maximum is Ns Np V_min (E - V_min)/R < P*, at a terminal voltage of Ns V_min.
  const BatteryParams p = yamlParams();
  BatteryModel m(p, "config/battery.yaml");
  m.reset(293.0, 0.5);
  const double h = 0.01;
  const double f = 29.0 / h * (1.0 - std::exp(-h / 29.0));
  const double E = 3.71, R = 0.0082 + 0.0016 * (1.0 - f);
  const double P_v = 91.0 * 3.0 * (E - 3.0) / R, P_star = 91.0 * E * E / (4.0 * R);
  EXPECT_NEAR(m.outputs().discharge_power_limit_W, P_v, 1e-9 * P_v);
  BatteryInputs in;
  in.air_T_K = 293.0;
  in.power_request_W = 1e6;
  m.step(h, in);
  const BatteryOutputs& o = m.outputs();
  EXPECT_TRUE(o.request_limited);
  EXPECT_NEAR(o.power_W, P_v, 1e-9 * P_v);
  EXPECT_NEAR(o.terminal_voltage_V, 13.0 * 3.0, 1e-12);
  EXPECT_NEAR(o.unmet_power_W, 1e6 - P_v, 1e-6);
  EXPECT_LT(P_v, P_star);
  std::printf("discharge limit at 39 V cut-off: %.1f W (< matched-load %.1f W), I = %.1f A\n", P_v,
              P_star, o.current_A);

  // Charging beyond the limit: V_max binds (voltage limit (4.2 - 3.71)/R = 59.7 A < 81 A), the
  // step-mean terminal voltage is exactly Ns V_max.
  BatteryModel c(p, "config/battery.yaml");
  c.reset(293.0, 0.5);
  in.power_request_W = -1e6;
  c.step(h, in);
  EXPECT_TRUE(c.outputs().request_limited);
  EXPECT_NEAR(c.outputs().terminal_voltage_V, 13.0 * 4.2, 1e-12);
  const double P_c = 91.0 * 4.2 * (4.2 - E) / R;
  EXPECT_NEAR(c.outputs().power_W, -P_c, 1e-9 * P_c);

  // With a cut-off below E/2 (1.5 V, large current limit) the matched-load maximum binds
  // instead: P* delivered at V_t = Ns E/2.
  BatteryParams q = p;
  q.cell.min_voltage_V = 1.5;
  q.cell.max_discharge_current_A = 1000.0;
  BatteryModel mq(q);
  mq.reset(293.0, 0.5);
  in.power_request_W = 1e6;
  mq.step(h, in);
  EXPECT_TRUE(mq.outputs().request_limited);
  EXPECT_NEAR(mq.outputs().power_W, P_star, 1e-9 * P_star);
  EXPECT_NEAR(mq.outputs().terminal_voltage_V, 13.0 * E / 2.0, 1e-12);
  // A request just below P* is met (quadratic root at the apex, no NaN).
  BatteryModel mr(q);
  mr.reset(293.0, 0.5);
  in.power_request_W = P_star * (1.0 - 1e-12);
  mr.step(h, in);
  EXPECT_FALSE(mr.outputs().request_limited);
  EXPECT_TRUE(std::isfinite(mr.outputs().current_A));
  EXPECT_NEAR(mr.outputs().power_W, in.power_request_W, 1e-6 * P_star);
}

TEST(BatteryModel, EnergyBalanceClosesOverMixedDutyWithLimits) {
  // 2000 s of charge/discharge pulses, including requests beyond both limits, from 0 degC.
  const BatteryParams p = yamlParams();
  BatteryModel m(p, "config/battery.yaml");
  m.reset(celsiusToK(0.0));
  BatteryInputs in;
  in.air_T_K = celsiusToK(0.0);
  const double h = 0.01;
  double W_t_test = 0.0, throughput = 0.0;
  int limited = 0;
  for (int k = 0; k < 200000; ++k) {
    const double t = k * h;
    in.power_request_W = 30e3 * std::sin(2 * units::kPi * t / 47.0) + 8e3 * std::sin(2 * units::kPi * t / 9.1);
    m.step(h, in);
    W_t_test += m.outputs().power_W * h;  // the test's own integral of the published power
    throughput += std::abs(m.outputs().power_W) * h;
    limited += m.outputs().request_limited;
  }
  const BatteryOutputs& o = m.outputs();
  const double elec = o.chemical_energy_J - o.terminal_energy_J - o.ohmic_loss_J - o.rc_loss_J -
                      o.rc_stored_energy_change_J;
  const double therm = o.loss_energy_J + o.fan_energy_J - o.heat_to_air_J - o.ventilation_heat_J - o.stored_heat_change_J;
  std::printf("2000 s mixed duty at 0 degC: throughput %.4g J, losses %.4g J, residual %.2e J (rel %.1e), "
              "electrical %.2e J, thermal %.2e J, limited steps %d, T_end %.2f degC, SOC %.4f\n",
              throughput, o.loss_energy_J, o.energy_residual_J, o.energy_residual_J / throughput, elec, therm,
              limited, units::kToCelsius(o.cell_T_K), o.soc);
  EXPECT_GT(limited, 0);
  EXPECT_NEAR(o.terminal_energy_J, W_t_test, 1e-9 * throughput);
  EXPECT_LT(std::abs(o.energy_residual_J), 1e-9 * throughput);
  EXPECT_LT(std::abs(elec), 1e-9 * throughput);
  EXPECT_LT(std::abs(therm), 1e-9 * throughput);
  EXPECT_NEAR(o.loss_energy_J, o.ohmic_loss_J + o.rc_loss_J, 1e-9 * o.loss_energy_J);
  EXPECT_NE(o.unmet_energy_J, 0.0);
  // Present RC stored energy vs the sum of per-step changes: differ only by the parameter drift.
  const CellPoint c = m.cellTable().at(o.soc, o.cell_T_K);
  const double E_C = 91.0 * 0.5 * c.tau1_s / c.r1_Ohm * m.cellRcVoltage_V() * m.cellRcVoltage_V();
  std::printf("RC stored energy: sum of step changes %.3f J, present C1 v1^2/2 %.3f J (C1 varies with SOC, T)\n",
              o.rc_stored_energy_change_J, E_C);
  EXPECT_LT(std::abs(o.rc_stored_energy_change_J - E_C), 1e-3 * o.loss_energy_J);
}

TEST(BatteryModel, ChemicalEnergyOfFullDischargeIsTheOcvIntegral) {
  // Linear OCV = 3.5 + 0.5 s: energy released from s0 to s1 = Ns Np Q ∫ OCV ds
  // = Ns Np Q [3.5 (s0 - s1) + 0.25 (s0^2 - s1^2)]; OCV is held per 0.01 s step (left sum).
  BatteryParams p = yamlParams();
  p.cell.table_file = constantTable();
  p.limits.soc_min = 0.05;
  p.limits.soc_taper = 0.01;
  p.cell.min_voltage_V = 2.0;  // constant current to SOC 0.12 (terminal ~2.3 V there)
  // Keep the 9 kW of losses from reaching the hot derating: a large, well-cooled housing
  // (~1 kW/K cells -> ambient), a fan that draws nothing (it would change the current).
  p.enclosure.h_cells_natural_W_m2K = p.enclosure.h_wall_inside_natural_W_m2K = 300.0;
  p.enclosure.h_cells_fan_W_m2K = p.enclosure.h_wall_inside_fan_W_m2K = 300.0;
  p.enclosure.h_outside_natural_W_m2K = 100.0;
  p.housing.area_m2 = 20.0;
  p.fan.rated_power_W = 0.0;
  BatteryModel m(p);
  m.reset(celsiusToK(25.0), 0.95);
  BatteryInputs in;
  in.air_T_K = celsiusToK(25.0);
  const double h = 0.01;
  for (int k = 0; k < 100000; ++k) {  // 1000 s at 81 A per cell (3C): ΔSOC = 0.833
    in.power_request_W = requestForCellCurrent(m, h, 81.0);
    m.step(h, in);
  }
  const double s0 = 0.95, s1 = m.outputs().soc;
  const double ref = 91.0 * 27.0 * 3600.0 * (3.5 * (s0 - s1) + 0.25 * (s0 * s0 - s1 * s1));
  std::printf("chemical energy %.6f MJ vs OCV integral %.6f MJ (rel %.1e)\n", m.outputs().chemical_energy_J / 1e6,
              ref / 1e6, m.outputs().chemical_energy_J / ref - 1.0);
  EXPECT_NEAR(s0 - s1, 81.0 * 1000.0 / (27.0 * 3600.0), 1e-10);  // rounding over 1e5 steps
  // OCV held per step = left Riemann sum: Σ OCV(s_k) Δs - ∫ OCV ds = (slope/2) K Δs^2 exactly
  // for a linear OCV (K steps of Δs): the model's error is that and nothing else.
  const double ds = 81.0 * h / (27.0 * 3600.0);
  const double left_sum_excess = 91.0 * 27.0 * 3600.0 * 0.25 * 100000 * ds * ds;
  std::printf("excess %.6f J, left-sum estimate %.6f J\n", m.outputs().chemical_energy_J - ref, left_sum_excess);
  EXPECT_NEAR(m.outputs().chemical_energy_J - ref, left_sum_excess, 1e-3 * left_sum_excess);
  EXPECT_NEAR(m.outputs().chemical_energy_J, ref, 1e-6 * ref);
}

TEST(BatteryLimits, ChargeLimitFallsAtLowTemperatureAndBothAtHighTemperature) {
  const BatteryParams p = yamlParams();
  BatteryModel m(p, "config/battery.yaml");
  double prev = 1e9;
  for (double Tc : {25.0, 15.0, 10.0, 5.0, 0.0, -5.0, -10.0, -20.0}) {
    m.reset(celsiusToK(Tc), 0.5);
    const BatteryOutputs& o = m.outputs();
    std::printf("T %6.1f degC: charge limit %7.1f A %8.1f W, discharge limit %7.1f A %8.1f W\n", Tc,
                o.charge_current_limit_A, o.charge_power_limit_W, o.discharge_current_limit_A,
                o.discharge_power_limit_W);
    EXPECT_LE(o.charge_power_limit_W, prev);
    prev = o.charge_power_limit_W;
    if (Tc <= 0.0 && Tc > -10.0) {  // the derated current limit binds: 81 A x (T + 10)/25 x Np
      EXPECT_NEAR(o.charge_current_limit_A, 7.0 * 81.0 * (Tc + 10.0) / 25.0, 1e-9);
    }
    if (Tc <= -10.0) {
      EXPECT_EQ(o.charge_power_limit_W, 0.0);
    }
    EXPECT_GT(o.discharge_power_limit_W, 10e3);
  }
  // Charging at -15 degC: nothing accepted, flagged, no NaN.
  m.reset(celsiusToK(-15.0), 0.5);
  BatteryInputs in;
  in.air_T_K = celsiusToK(-15.0);
  in.power_request_W = -5e3;
  m.step(0.01, in);
  EXPECT_TRUE(m.outputs().request_limited);
  EXPECT_EQ(m.outputs().current_A, 0.0);
  // Hot: half the current limits at 55 degC, none at 60 degC.
  m.reset(celsiusToK(55.0), 0.5);
  EXPECT_NEAR(m.outputs().discharge_current_limit_A, 7.0 * 135.0 * 0.5, 1e-9);
  EXPECT_NEAR(m.outputs().charge_current_limit_A, 7.0 * 81.0 * 0.5, 1e-9);
  m.reset(celsiusToK(60.0), 0.5);
  EXPECT_EQ(m.outputs().discharge_power_limit_W, 0.0);
  EXPECT_EQ(m.outputs().charge_power_limit_W, 0.0);
}

TEST(BatteryLimits, SocWindowTapersAndHoldsTheWindow) {
  const BatteryParams p = yamlParams();
  BatteryModel m(p, "config/battery.yaml");
  m.reset(celsiusToK(25.0), 0.2);
  EXPECT_EQ(m.outputs().discharge_power_limit_W, 0.0);
  EXPECT_GT(m.outputs().charge_power_limit_W, 10e3);
  m.reset(celsiusToK(25.0), 0.8);
  EXPECT_EQ(m.outputs().charge_power_limit_W, 0.0);
  m.reset(celsiusToK(25.0), 0.21);  // taper: 20 % of 5C = 27 A per cell, below the voltage limit
  EXPECT_NEAR(m.outputs().discharge_current_limit_A, 7.0 * 135.0 * 0.2, 1e-9);
  // A long 20 kW discharge from SOC 0.3 never takes the SOC below the window.
  m.reset(celsiusToK(25.0), 0.3);
  BatteryInputs in;
  in.air_T_K = celsiusToK(25.0);
  in.power_request_W = 20e3;
  for (int k = 0; k < 300000; ++k) m.step(0.01, in);
  EXPECT_GE(m.outputs().soc, 0.2);
  EXPECT_LT(m.outputs().soc, 0.2 + 1e-3);
  EXPECT_TRUE(m.outputs().request_limited);
  std::printf("20 kW from SOC 0.3 for 3000 s: SOC %.6f, delivered %.1f W\n", m.outputs().soc, m.outputs().power_W);
}

TEST(BatteryModel, ZeroRequestAndRestGiveNoNaN) {
  // 30 degC: below the fan's threshold (at 40 degC the pack would power its fan: test_pack_fan).
  const BatteryParams p = yamlParams();
  BatteryModel m(p, "config/battery.yaml");
  const double Ta = celsiusToK(30.0);
  m.reset(Ta);
  EXPECT_NEAR(m.outputs().soc, 0.5, 0);
  BatteryInputs in;
  in.air_T_K = Ta;
  for (int k = 0; k < 1000; ++k) m.step(0.01, in);
  const BatteryOutputs& o = m.outputs();
  EXPECT_EQ(o.current_A, 0.0);
  EXPECT_EQ(o.soc, 0.5);
  EXPECT_EQ(o.cell_T_K, Ta);
  EXPECT_EQ(o.loss_power_W, 0.0);
  EXPECT_EQ(o.energy_residual_J, 0.0);
  EXPECT_NEAR(o.terminal_voltage_V, o.ocv_V, 1e-12);
  // Pulse then rest: everything finite, RC relaxes, voltage returns toward the OCV.
  in.power_request_W = 15e3;
  for (int k = 0; k < 1000; ++k) m.step(0.01, in);
  in.power_request_W = 0.0;
  const double v1 = m.cellRcVoltage_V();
  for (int k = 0; k < 30000; ++k) m.step(0.01, in);
  EXPECT_LT(m.cellRcVoltage_V(), 0.01 * v1);
  for (double x : {o.terminal_voltage_V, o.ocv_V, o.soc, o.cell_T_K, o.energy_residual_J,
                   o.discharge_power_limit_W, o.charge_power_limit_W})
    EXPECT_TRUE(std::isfinite(x));
}

TEST(BatteryModel, NonFiniteInputsAreDivergence) {
  const BatteryParams p = yamlParams();
  BatteryModel m(p, "config/battery.yaml");
  BatteryInputs in;
  in.power_request_W = std::nan("");
  try {
    m.step(0.01, in);
    FAIL();
  } catch (const ModelDivergence& e) {
    EXPECT_NE(std::string(e.what()).find("power request"), std::string::npos) << e.what();
  }
  in.power_request_W = 0.0;
  in.air_T_K = INFINITY;
  EXPECT_THROW(m.step(0.01, in), ModelDivergence);
  in.air_T_K = 300.0;
  EXPECT_THROW(m.step(0.0, in), ModelDivergence);
  EXPECT_THROW(m.step(std::nan(""), in), ModelDivergence);
}

TEST(BatteryParams, YamlMatchesDeclarationAndBadValuesRejected) {
  BatteryParams p;
  ParamSet ps;
  p.declare(ps);
  const ParamSource src = readYamlParams("config/battery.yaml");
  EXPECT_NO_THROW(applyParams(ps, src, {"cosim/"}));
  for (const auto& e : ps.entries()) EXPECT_TRUE(src.values.count(e.key)) << "missing in YAML: " << e.key;
  EXPECT_TRUE(src.values.count("cosim/macro_step_s"));
  auto expectKey = [](const ParamSource& s, const std::string& key) {
    hbt::testing::expectRejected<BatteryParams>(s, key);
  };
  ParamSource bad;
  bad.file = "battery.yaml";
  bad.set("cell/capacity_ah", 27.0);  // unknown (typo)
  expectKey(bad, "cell/capacity_ah");
  bad.values.clear();
  bad.set("enclosure/h_cells_fan_W_m2K", std::nan(""));
  expectKey(bad, "enclosure/h_cells_fan_W_m2K");
  bad.values.clear();
  bad.set("pack/cells_in_parallel", 0.0);  // out of range
  expectKey(bad, "pack/cells_in_parallel");
  bad.values.clear();
  bad.set("pack/cells_in_series", 13.5);  // not an integer
  expectKey(bad, "pack/cells_in_series");

  auto expectModelKey = [&](const BatteryParams& q, const std::string& file, const std::string& key) {
    expectInputError([&] { BatteryModel m(q, "battery.yaml"); }, file, key);
  };
  const BatteryParams y = yamlParams();
  BatteryParams q = y;
  q.pack.cells_in_series = 14;
  q.cell.max_voltage_V = 4.3;  // 60.2 V: not a 48 V pack any more
  expectModelKey(q, "battery.yaml", "pack/cells_in_series");
  q = y;
  q.cell.table_file = "config/data/battery/no_such_table.csv";
  expectModelKey(q, "battery.yaml", "cell/table_file");
  q = y;
  q.cell.min_voltage_V = 3.6;  // above the OCV at 20 % SOC (3.6-3.61 V)
  expectModelKey(q, "battery.yaml", "cell/min_voltage_V");
  q = y;
  q.limits.max_temperature_K = q.limits.hot_derate_start_K - 1.0;
  expectModelKey(q, "battery.yaml", "limits/max_temperature_K");
  q = y;
  q.limits.soc_min = 0.6;
  q.limits.soc_max = 0.65;
  expectModelKey(q, "battery.yaml", "limits/soc_max");

  // Bad tables: the error names the CSV and the column.
  auto ok = [](double s, double) { return CellPoint{3.5 + 0.5 * s, kR0, kR1, kTau}; };
  q = y;
  q.cell.table_file = writeTable("bad_ocv.csv", [](double s, double) { return CellPoint{4.0 - 0.5 * s, kR0, kR1, kTau}; });
  expectModelKey(q, q.cell.table_file, "OCV");
  q.cell.table_file = writeTable("bad_r0.csv", [](double s, double T) { return CellPoint{3.5 + 0.5 * s, T > 300 ? -0.01 : 0.01, kR1, kTau}; });
  expectModelKey(q, q.cell.table_file, "R0");
  q.cell.table_file = writeTable("bad_tau.csv", [](double s, double) { return CellPoint{3.5 + 0.5 * s, kR0, kR1, 0.0}; });
  expectModelKey(q, q.cell.table_file, "tau1");
  q.cell.table_file = writeTable("bad_grid.csv", ok, "0.25,250,3.6,0.01,0.005,30\n");  // incomplete grid
  expectModelKey(q, q.cell.table_file, "SOC");
  q.cell.table_file = writeTable("bad_dup.csv", ok, "0.5,250,3.75,0.01,0.005,30\n");  // wrong row count
  expectModelKey(q, q.cell.table_file, "SOC");
  q.cell.table_file = writeTable("bad_nan.csv", ok, "0.25,250,nan,0.01,0.005,30\n");
  expectInputError([&] { BatteryModel m(q); }, q.cell.table_file, "OCV");
}

TEST(BatteryModel, StepDoesNotAllocate) {
  const BatteryParams p = yamlParams();
  BatteryModel m(p, "config/battery.yaml");
  BatteryInputs in;
  in.air_T_K = celsiusToK(25.0);
  const long a0 = hbt::testing::allocations();
  for (int k = 0; k < 1000; ++k) {
    in.power_request_W = 40e3 * std::sin(0.01 * k);  // within and beyond the limits
    m.step(0.01, in);
  }
  EXPECT_EQ(hbt::testing::allocations() - a0, 0);
}

TEST(BatteryModel, Deterministic) {
  const BatteryParams p = yamlParams();
  BatteryModel a(p), b(p);
  BatteryInputs in;
  in.air_T_K = celsiusToK(10.0);
  a.reset(in.air_T_K);
  b.reset(in.air_T_K);
  for (int k = 0; k < 5000; ++k) {
    in.power_request_W = 25e3 * std::sin(0.003 * k);
    a.step(0.01, in);
    b.step(0.01, in);
  }
  EXPECT_EQ(a.outputs().soc, b.outputs().soc);
  EXPECT_EQ(a.outputs().cell_T_K, b.outputs().cell_T_K);
  EXPECT_EQ(a.outputs().energy_residual_J, b.outputs().energy_residual_J);
}

TEST(BatterySizing, EnvelopeOfTheChosenPack) {
  // The numbers quoted in config/battery.yaml and the README (0.01 s step, at rest).
  const BatteryParams p = yamlParams();
  BatteryModel m(p, "config/battery.yaml");
  const int ns = p.pack.cells_in_series;
  EXPECT_LT(ns * p.cell.max_voltage_V, 60.0);
  std::printf("13s7p: %.0f Ah, %.2f kWh nominal (3.7 V), %.1f-%.1f V, cell mass %.1f kg\n",
              7 * 27.0, 91 * 27.0 * 3.7 / 1e3, ns * p.cell.min_voltage_V, ns * p.cell.max_voltage_V,
              91 * p.cell.mass_kg);
  for (double Tc : {25.0, 5.0, 0.0})
    for (double s : {0.2, 0.25, 0.5, 0.75, 0.8}) {
      m.reset(celsiusToK(Tc), s);
      const BatteryOutputs& o = m.outputs();
      std::printf("T %4.0f degC SOC %.2f: OCV %.2f V, discharge %.1f kW (%.0f A), charge %.1f kW (%.0f A)\n", Tc, s,
                  o.ocv_V, o.discharge_power_limit_W / 1e3, o.discharge_current_limit_A,
                  o.charge_power_limit_W / 1e3, o.charge_current_limit_A);
    }
  m.reset(celsiusToK(25.0), 0.25);  // bottom of the full-power window
  EXPECT_GT(m.outputs().discharge_power_limit_W, 17e3);
  m.reset(celsiusToK(25.0), 0.5);
  EXPECT_GT(m.outputs().discharge_power_limit_W, 20e3);
  EXPECT_GT(m.outputs().charge_power_limit_W, 20e3);
}
