// Energy manager (src/ems) against independent references: the analytic ECMS optimum of a
// Willans / quadratic fuel model, limit cases of the split, property tests over random demands
// (live limits, warm-up inhibit, battery temperature, SOC window in closed loop with an ideal
// battery), the stop-start state machine, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "common/errors.hpp"
#include "common/yaml_params.hpp"
#include "ems/ems_model.hpp"
#include "engine_map/map_engine.hpp"
#include "../common/param_checks.hpp"

using namespace hbt;
using namespace hbt::ems;

namespace {

EmsParams yamlParams() {
  EmsParams p;
  ParamSet ps;
  p.declare(ps);
  applyParams(ps, readYamlParams("config/ems.yaml"), {"cosim/"});
  p.validate("config/ems.yaml");
  return p;
}

// Fuel power = a P + b P² above the motoring torque (P = T ω brake power) [W of fuel]; b = 0 is
// a Willans line with marginal efficiency 1/a.
class QuadraticFuel : public FuelModel {
 public:
  QuadraticFuel(double a, double b, double P0_W, double lhv) : a_(a), b_(b), P0_(P0_W), lhv_(lhv) {}
  double fuelRate_kg_s(double w, double T) const override {
    if (T <= kMotoring) return 0.0;
    const double P = T * w;
    return (P0_ + a_ * P + b_ * P * P) / lhv_;
  }
  static constexpr double kMotoring = -100.0;

 private:
  double a_, b_, P0_, lhv_;
};

EmsInputs warmTraction(double Td, double w) {
  EmsInputs in;
  in.crank_torque_demand_Nm = Td;
  in.engine_speed_rad_s = w;
  in.crank_to_wheel_ratio = 20.0;
  in.engine_max_torque_Nm = 1100.0;
  in.engine_min_torque_Nm = QuadraticFuel::kMotoring;
  in.em_max_torque_Nm = 400.0;
  in.em_min_torque_Nm = -400.0;
  in.soc = 0.5;
  in.battery_T_K = 298.15;
  in.discharge_limit_W = 30000.0;
  in.charge_limit_W = 30000.0;
  in.coolant_T_K = 363.15;
  in.scr_T_K = 573.15;
  return in;
}

}  // namespace

TEST(Ecms, WillansLineGivesBangBangAtTheAnalyticThreshold) {
  // Linear fuel (Willans): J(T_em) is linear in T_em on each side of 0, so the optimum is a
  // bound. Boost pays iff s/η_m < a (a joule of crank work costs a joules of fuel); charging pays
  // iff s η_g > a. With s = s0 at SOC = target (no integral yet).
  EmsParams p = yamlParams();
  p.ecms.soc_ki_per_s = 0.0;
  const double eta = p.ecms.em_motor_efficiency;
  for (double a : {2.0, 2.5, 3.2, 4.0}) {
    QuadraticFuel fuel(a, 0.0, 5000.0, hbt::units::kDieselLhv_J_kg);
    EmsModel m(p, fuel);
    const EmsInputs in = warmTraction(500.0, 150.0);
    const EmsDecision& d = m.step(0.01, in);
    const double s = p.ecms.equivalence_factor;
    if (s / eta < a) {  // boost to the bound: the EM limit (400 Nm) or the battery (30 kW)
      // (the battery's share: its limit less battery/limit_margin)
      EXPECT_NEAR(d.em_torque_request_Nm, std::min(400.0, 30000.0 * (1.0 - p.battery.limit_margin) * eta / 150.0), 1e-9) << a;
      EXPECT_EQ(d.mode, Mode::Boost);
    } else if (s * p.ecms.em_generator_efficiency > a) {
      EXPECT_LT(d.em_torque_request_Nm, 0.0) << a;
    } else {
      EXPECT_EQ(d.em_torque_request_Nm, 0.0) << a;
    }
    EXPECT_NEAR(d.engine_torque_request_Nm + d.em_torque_request_Nm, 500.0, 1e-9);
  }
}

TEST(Ecms, QuadraticFuelGivesTheInteriorOptimumWithinTheGrid) {
  // Fuel power a P + b P²: dJ/dT_em = ω (s/η_m - a - 2 b P_e) = 0 in boost ->
  // P_e* = (s/η_m - a) / (2b), T_em* = T_d - P_e*/ω (interior if within the limits).
  EmsParams p = yamlParams();
  p.ecms.soc_ki_per_s = 0.0;
  p.ecms.candidates = 401;
  const double a = 2.2, b = 3.0e-6, w = 150.0, Td = 900.0;
  QuadraticFuel fuel(a, b, 5000.0, hbt::units::kDieselLhv_J_kg);
  EmsModel m(p, fuel);
  const double s = p.ecms.equivalence_factor, eta = p.ecms.em_motor_efficiency;
  const double Pe = (s / eta - a) / (2.0 * b);
  const double T_star = Td - Pe / w;
  const EmsInputs in = warmTraction(Td, w);
  const double hi = std::min(400.0, 30000.0 * eta / w);  // battery bound 176 Nm
  ASSERT_GT(T_star, 10.0);                                // interior (61 Nm here)
  ASSERT_LT(T_star, hi - 10.0);
  const double grid = 800.0 / 400.0;  // (hi - lo)/(n - 1) with lo >= -400
  EXPECT_NEAR(m.step(0.01, in).em_torque_request_Nm, T_star, grid);
  EXPECT_EQ(m.decision().mode, Mode::Boost);
}

TEST(Ecms, RegenFirstWithinTheLiveLimitsAndFrictionTakesTheRest) {
  const EmsParams p = yamlParams();
  QuadraticFuel fuel(2.3, 0.0, 5000.0, hbt::units::kDieselLhv_J_kg);
  EmsModel m(p, fuel);
  EmsInputs in = warmTraction(QuadraticFuel::kMotoring, 150.0);
  in.wheel_brake_demand_Nm = 4000.0;  // wheel torque; i = 20 -> 200 Nm at the crank
  const EmsDecision& d1 = m.step(0.01, in);
  EXPECT_NEAR(d1.em_torque_request_Nm, -200.0, 1e-9);
  EXPECT_NEAR(d1.friction_brake_Nm, 0.0, 1e-9);
  EXPECT_EQ(d1.mode, Mode::Regen);
  // EM derated to -120 Nm: regen 120, friction the rest (i 120 Nm at the wheels)
  in.em_min_torque_Nm = -120.0;
  const EmsDecision& d2 = m.step(0.01, in);
  EXPECT_NEAR(d2.em_torque_request_Nm, -120.0, 1e-9);
  EXPECT_NEAR(d2.friction_brake_Nm, 4000.0 - 20.0 * 120.0, 1e-9);
  EXPECT_EQ(d2.reason, Reason::EmLimit);
  // battery charge limit 9 kW less the margin: T = P (1 - m)/(ω η_g)
  in.em_min_torque_Nm = -400.0;
  in.charge_limit_W = 9000.0;
  const EmsDecision& d3 = m.step(0.01, in);
  EXPECT_NEAR(d3.em_torque_request_Nm, -9000.0 * (1.0 - p.battery.limit_margin) / (150.0 * p.ecms.em_generator_efficiency), 1e-9);
  EXPECT_EQ(d3.reason, Reason::BatteryLimit);
  // converter open (ratio 0): no regen at all
  in.crank_to_wheel_ratio = 0.0;
  const EmsDecision& d4 = m.step(0.01, in);
  EXPECT_EQ(d4.em_torque_request_Nm, 0.0);
  EXPECT_EQ(d4.friction_brake_Nm, 4000.0);
  EXPECT_EQ(d4.reason, Reason::NotConnected);
}

TEST(Ecms, PropertiesOverRandomDemands) {
  // Never beyond the live EM limits or the battery's power limits (with the controller's own
  // efficiency), never boost or stop while cold, friction >= 0 and regen + friction = demand,
  // no boost with the battery at 45 degC, no boost below soc_min, no charging above soc_max.
  const EmsParams p = yamlParams();
  engine_map::MapEngineParams mp;
  ParamSet mps;
  mp.declare(mps);
  applyParams(mps, readYamlParams("config/engine_map.yaml"), {"cosim/"});
  const engine_map::MapEngine eng(mp, ".");
  struct MapFuel : FuelModel {
    const engine_map::MapEngine& e;
    explicit MapFuel(const engine_map::MapEngine& x) : e(x) {}
    double fuelRate_kg_s(double w, double T) const override { return e.steadyFuel(w, T); }
  } fuel(eng);
  EmsModel m(p, fuel);
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  int boosts = 0, charges = 0, regens = 0, stops = 0;
  for (int k = 0; k < 20000; ++k) {
    EmsInputs in;
    const double w = 60.0 + 170.0 * U(rng);
    in.engine_speed_rad_s = w;
    in.engine_max_torque_Nm = eng.fullLoadTorque(w);
    in.engine_min_torque_Nm = eng.motoringTorque(w);
    in.crank_torque_demand_Nm = in.engine_min_torque_Nm + (in.engine_max_torque_Nm + 300.0 - in.engine_min_torque_Nm) * U(rng);
    in.wheel_brake_demand_Nm = U(rng) < 0.2 ? 20000.0 * U(rng) : 0.0;
    in.crank_to_wheel_ratio = U(rng) < 0.8 ? 4.0 + 20.0 * U(rng) : 0.0;
    in.stopped = U(rng) < 0.05;
    in.start_request = U(rng) < 0.5;
    in.em_max_torque_Nm = 430.0 * U(rng);
    in.em_min_torque_Nm = -430.0 * U(rng);
    in.soc = 0.2 + 0.6 * U(rng);
    in.battery_T_K = 273.15 + 50.0 * U(rng);
    in.discharge_limit_W = 25000.0 * U(rng);
    in.charge_limit_W = 25000.0 * U(rng);
    in.coolant_T_K = 273.15 + 95.0 * U(rng);
    in.scr_T_K = 273.15 + 350.0 * U(rng);
    const EmsDecision& d = m.step(0.01, in);
    const double T = d.em_torque_request_Nm;
    const bool warm = in.coolant_T_K >= p.warmup.coolant_warm_K && in.scr_T_K >= p.warmup.scr_warm_K;
    ASSERT_TRUE(std::isfinite(T) && std::isfinite(d.engine_torque_request_Nm) && std::isfinite(d.friction_brake_Nm));
    ASSERT_LE(T, in.em_max_torque_Nm + 1e-9);
    ASSERT_GE(T, in.em_min_torque_Nm - 1e-9);
    ASSERT_GE(d.friction_brake_Nm, 0.0);
    if (d.mode == Mode::Cranking) continue;  // cranking: EM torque bounded by its limits (above)
    if (T > 0.0) {
      ++boosts;
      ASSERT_TRUE(warm);
      ASSERT_GE(in.soc, p.ecms.soc_min);
      ASSERT_LT(in.battery_T_K, p.battery.assist_zero_K);
      ASSERT_LE(T * w / p.ecms.em_motor_efficiency, in.discharge_limit_W * (1.0 + 1e-9));
    }
    if (T < 0.0) {
      ASSERT_LE(-T * w * p.ecms.em_generator_efficiency, in.charge_limit_W * (1.0 + 1e-9));
      if (in.wheel_brake_demand_Nm > 0.0) {
        ++regens;
        ASSERT_NEAR(d.friction_brake_Nm - T * in.crank_to_wheel_ratio, in.wheel_brake_demand_Nm, 1e-6);
      } else {
        ++charges;
        ASSERT_LE(in.soc, p.ecms.soc_max);
      }
    }
    if (!d.engine_on) {
      ++stops;
      ASSERT_TRUE(warm || d.mode == Mode::Cranking);
    }
    if (d.mode != Mode::Regen) {
      ASSERT_NEAR(d.friction_brake_Nm, in.wheel_brake_demand_Nm, 1e-9);
    }
  }
  // the random drive exercised every branch
  EXPECT_GT(boosts, 100);
  EXPECT_GT(charges, 100);
  EXPECT_GT(regens, 100);
  EXPECT_GT(stops, 10);
}

TEST(Ecms, BatteryTemperatureFadesAssistLinearly) {
  EmsParams p = yamlParams();
  QuadraticFuel fuel(4.0, 0.0, 5000.0, hbt::units::kDieselLhv_J_kg);  // boost always pays
  EmsModel m(p, fuel);
  EmsInputs in = warmTraction(800.0, 150.0);
  in.em_max_torque_Nm = 1000.0;  // battery-bound
  const double full = in.discharge_limit_W * (1.0 - p.battery.limit_margin) * p.ecms.em_motor_efficiency / 150.0;
  in.battery_T_K = 0.5 * (p.battery.assist_derate_start_K + p.battery.assist_zero_K);
  EXPECT_NEAR(m.step(0.01, in).em_torque_request_Nm, 0.5 * full, 1e-9);
  EXPECT_EQ(m.decision().reason, Reason::BatteryHot);
  in.battery_T_K = p.battery.assist_zero_K;
  EXPECT_EQ(m.step(0.01, in).em_torque_request_Nm, 0.0);
  in.battery_T_K = p.battery.assist_derate_start_K - 1.0;
  EXPECT_NEAR(m.step(0.01, in).em_torque_request_Nm, full, 1e-9);
}

TEST(Ecms, ChargeSustainingInClosedLoopWithAnIdealBattery) {
  // 2 h of random traction/braking with an ideal 2 kWh battery (P_el integrated exactly with
  // the controller's own efficiencies) and 1.8 kW of DC/DC load: SOC stays in the window
  // [soc_restart, soc_max + 0.05] and ends near the target.
  const EmsParams p = yamlParams();
  QuadraticFuel fuel(2.4, 2.0e-6, 6000.0, hbt::units::kDieselLhv_J_kg);
  EmsModel m(p, fuel);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  const double E_Wh = 2000.0, dt = 0.1;
  double soc = 0.5, Td = 300.0, brake = 0.0, w = 120.0, lo = 1.0, hi = 0.0;
  for (int k = 0; k < 72000; ++k) {
    if (k % 100 == 0) {  // a new 10 s phase
      const double r = U(rng);
      brake = r < 0.3 ? 3000.0 + 6000.0 * U(rng) : 0.0;
      Td = r < 0.3 ? -90.0 : 100.0 + 900.0 * U(rng);
      w = 70.0 + 150.0 * U(rng);
    }
    EmsInputs in = warmTraction(Td, w);
    in.wheel_brake_demand_Nm = brake;
    in.soc = soc;
    const EmsDecision& d = m.step(dt, in);
    const double T = d.em_torque_request_Nm;
    const double P_el = (T >= 0.0 ? T * w / p.ecms.em_motor_efficiency : T * w * p.ecms.em_generator_efficiency) + 1800.0;
    soc -= P_el * dt / (E_Wh * 3600.0);
    lo = std::min(lo, soc);
    hi = std::max(hi, soc);
  }
  EXPECT_GE(lo, p.stop_start.soc_restart);
  EXPECT_LE(hi, p.ecms.soc_max + 0.05);
  EXPECT_NEAR(soc, p.ecms.soc_target, 0.1);
}

TEST(StopStart, StopsOnlyWhenWarmCranksAndFires) {
  const EmsParams p = yamlParams();
  QuadraticFuel fuel(2.3, 0.0, 5000.0, hbt::units::kDieselLhv_J_kg);
  EmsModel m(p, fuel);
  EmsInputs in = warmTraction(40.0, 62.8);
  in.stopped = true;
  in.coolant_T_K = p.warmup.coolant_warm_K - 1.0;  // cold: stays on
  for (int k = 0; k < 500; ++k) ASSERT_TRUE(m.step(0.01, in).engine_on);
  EXPECT_EQ(m.decision().engine_stops, 0);
  in.coolant_T_K = 363.15;
  in.scr_T_K = p.warmup.scr_warm_K - 1.0;  // ATS cold: stays on
  for (int k = 0; k < 500; ++k) ASSERT_TRUE(m.step(0.01, in).engine_on);
  in.scr_T_K = 573.15;
  EXPECT_FALSE(m.step(0.01, in).engine_on);
  EXPECT_EQ(m.decision().mode, Mode::Stopped);
  EXPECT_EQ(m.decision().engine_stops, 1);
  in.engine_speed_rad_s = 0.0;
  for (int k = 0; k < 100; ++k) ASSERT_FALSE(m.step(0.01, in).engine_on);
  // drive-off: cranking with the crank torque until the firing speed
  in.start_request = true;
  const EmsDecision& c = m.step(0.01, in);
  EXPECT_EQ(c.mode, Mode::Cranking);
  EXPECT_EQ(c.reason, Reason::DriveOff);
  EXPECT_NEAR(c.em_torque_request_Nm, std::min(p.stop_start.crank_torque_Nm, in.em_max_torque_Nm), 1e-12);
  EXPECT_EQ(c.engine_torque_request_Nm, 0.0);
  in.engine_speed_rad_s = 0.5 * p.stop_start.firing_speed_rad_s;
  EXPECT_FALSE(m.step(0.01, in).engine_on);
  in.engine_speed_rad_s = p.stop_start.firing_speed_rad_s;
  EXPECT_TRUE(m.step(0.01, in).engine_on);
  EXPECT_EQ(m.decision().engine_starts, 1);
  // min_on_time: standing again at once does not stop the engine before min_on_time_s
  in.start_request = false;
  in.engine_speed_rad_s = 62.8;
  const int n_on = static_cast<int>(p.stop_start.min_on_time_s / 0.01) - 2;
  for (int k = 0; k < n_on; ++k) ASSERT_TRUE(m.step(0.01, in).engine_on) << k;
}

TEST(StopStart, FailedStartStopsTheRunAndSocRestart) {
  const EmsParams p = yamlParams();
  QuadraticFuel fuel(2.3, 0.0, 5000.0, hbt::units::kDieselLhv_J_kg);
  {
    EmsModel m(p, fuel);
    EmsInputs in = warmTraction(40.0, 62.8);
    in.stopped = true;
    m.step(0.01, in);
    in.soc = p.stop_start.soc_restart - 0.01;  // battery low: restart
    in.engine_speed_rad_s = 0.0;
    EXPECT_EQ(m.step(0.01, in).reason, Reason::SocRestart);
    EXPECT_THROW(for (int k = 0; k < 1000; ++k) m.step(0.01, in), ModelDivergence);  // never fires
  }
  {  // stop-start switched off in the config: stays on, says why
    EmsParams off = p;
    off.stop_start.enabled = false;
    EmsModel m(off, fuel);
    EmsInputs in = warmTraction(40.0, 62.8);
    in.stopped = true;
    EXPECT_TRUE(m.step(0.01, in).engine_on);
    EXPECT_EQ(m.decision().reason, Reason::StopStartDisabled);
  }
}

// The HVAC's belt-driven A/C asks the engine to run (hvac:=on): a standing warm engine is not
// stopped while the request holds, a stopped one is restarted by it, and stops once it ends.
TEST(StopStart, ClimateRunRequestKeepsOrRestartsTheEngine) {
  const EmsParams p = yamlParams();
  QuadraticFuel fuel(2.3, 0.0, 5000.0, hbt::units::kDieselLhv_J_kg);
  EmsModel m(p, fuel);
  EmsInputs in = warmTraction(40.0, 62.8);
  in.stopped = true;
  in.climate_run_request = true;
  for (int k = 0; k < 500; ++k) ASSERT_TRUE(m.step(0.01, in).engine_on);
  EXPECT_EQ(m.decision().reason, Reason::ClimateRequest);
  EXPECT_EQ(m.decision().engine_stops, 0);
  in.climate_run_request = false;  // cabin cooled down: the engine stops
  EXPECT_FALSE(m.step(0.01, in).engine_on);
  EXPECT_EQ(m.decision().engine_stops, 1);
  in.engine_speed_rad_s = 0.0;
  for (int k = 0; k < 100; ++k) ASSERT_FALSE(m.step(0.01, in).engine_on);
  in.climate_run_request = true;  // the cabin warmed again: restart while standing
  const EmsDecision& c = m.step(0.01, in);
  EXPECT_EQ(c.mode, Mode::Cranking);
  EXPECT_EQ(c.reason, Reason::ClimateRequest);
  EXPECT_EQ(m.decision().engine_starts, 1);
}

TEST(EmsParams, BadInputNamesTheKey) {
  auto expectKey = [](const std::string& key, ParamValue v) {
    ParamSource src = readYamlParams("config/ems.yaml");
    ASSERT_EQ(src.file, "config/ems.yaml");
    src.set(key, v);
    hbt::testing::expectRejected<EmsParams>(src, key, {"cosim/"});
  };
  expectKey("ecms/equivalence_factor", -1.0);
  expectKey("ecms/soc_max", 0.2);            // below soc_min
  expectKey("stop_start/soc_restart", 0.45); // above soc_min_to_stop
  expectKey("ecms/candidates", 1.5);
  expectKey("ecms/typo_key", 1.0);
  expectKey("battery/assist_zero_K", 300.0);
}

TEST(EmsModel, RejectsNonFiniteInput) {
  const EmsParams p = yamlParams();
  QuadraticFuel fuel(2.3, 0.0, 5000.0, hbt::units::kDieselLhv_J_kg);
  EmsModel m(p, fuel);
  EmsInputs in = warmTraction(100.0, 100.0);
  in.soc = std::nan("");
  EXPECT_THROW(m.step(0.01, in), ModelDivergence);
}
