// Map-based engine: scaling to exactly 1,100 Nm / 210 kW with BSFC preserved at corresponding
// points (checked against the raw reference file), PT1 torque build-up against the analytic
// first-order response, overrun fuel cut, no NaN anywhere, gas-path energy balance and
// composition, and the YAML config matching the declared parameters.
#include <gtest/gtest.h>

#include <cmath>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/params.hpp"
#include "common/units.hpp"
#include "engine_map/map_engine.hpp"
#include "common/yaml_params.hpp"
#include "../common/input_errors.hpp"

using namespace hbt;
using namespace hbt::engine_map;
using hbt::testing::expectInputError;

namespace {

const MapEngine& engine() {
  static const MapEngine e{MapEngineParams{}};
  return e;
}

// τ from the raw PT1 file at reference speed rpm_ref (independent of the engine's table code).
double rawPt1(double rpm_ref) {
  const auto t = CsvTable::read("config/data/vehicle/declaration_2015/PT1.csv");
  const auto& n = t.column("rpm");
  const auto& tau = t.column("PT1");
  for (std::size_t i = 0; i + 1 < n.size(); ++i)
    if (rpm_ref >= n[i] && rpm_ref <= n[i + 1])
      return tau[i] + (tau[i + 1] - tau[i]) * (rpm_ref - n[i]) / (n[i + 1] - n[i]);
  return tau.back();
}

}  // namespace

TEST(MapEngine, ScaledPeakTorqueAndPowerAreExact) {
  const auto& e = engine();
  EXPECT_NEAR(e.peakTorque(), 1100.0, 1e-9);
  EXPECT_NEAR(e.peakPower(), 210000.0, 1e-6);
  // Independent check: dense sampling of ω·T_fl(ω) never exceeds 210 kW and comes within 1 W.
  double pmax = 0.0, tmax = 0.0;
  for (double w = 0.0; w < e.maxMapSpeed(); w += 0.001) {
    pmax = std::max(pmax, w * e.fullLoadTorque(w));
    tmax = std::max(tmax, e.fullLoadTorque(w));
  }
  EXPECT_LE(pmax, 210000.0 + 1e-6);
  EXPECT_GT(pmax, 210000.0 - 1.0);
  EXPECT_NEAR(tmax, 1100.0, 1e-9);
  // Documented factors: f_T = 1100/1092.03, rated speed 2200 rpm -> f_n * 2200.
  EXPECT_NEAR(e.scaling().torque_factor, 1100.0 / 1092.03, 1e-12);
  double w_rated = 0.0;
  e.peakPower(&w_rated);
  EXPECT_NEAR(units::radpsToRpm(w_rated), 2200.0 * e.scaling().speed_factor, 1e-6);
  EXPECT_NEAR(units::radpsToRpm(w_rated), 2293.3, 0.1);
}

TEST(MapEngine, BsfcPreservedAtCorrespondingPoints) {
  const auto& e = engine();
  const auto raw = CsvTable::read(e.params().fuel_map_file);
  const auto& n = raw.column("engine speed");
  const auto& T = raw.column("torque");
  const auto& fc = raw.column("fuel consumption");
  const double fT = e.scaling().torque_factor, fn = e.scaling().speed_factor;
  int checked = 0;
  for (std::size_t i = 0; i < raw.rows(); ++i) {
    if (T[i] <= 50.0) continue;
    const double bsfc_ref = fc[i] / (T[i] * units::rpmToRadps(n[i]) / 1000.0);  // g/kWh
    const double w = units::rpmToRadps(n[i] * fn), t = T[i] * fT;
    const double bsfc = e.steadyFuel(w, t) * 3.6e9 / (t * w);
    EXPECT_NEAR(bsfc, bsfc_ref, 1e-9 * bsfc_ref) << n[i] << " rpm " << T[i] << " Nm";
    ++checked;
  }
  EXPECT_GT(checked, 100);
}

TEST(MapEngine, BsfcAtMidLoadIsPlausible) {
  const auto& e = engine();
  // 1400 rpm of the reference engine (plateau), half of the peak torque.
  const double w = units::rpmToRadps(1400.0 * e.scaling().speed_factor);
  const double t = 550.0;
  const double bsfc = e.steadyFuel(w, t) * 3.6e9 / (t * w);
  EXPECT_GT(bsfc, 190.0);
  EXPECT_LT(bsfc, 230.0);
  // Best point of the map: a modern HD diesel reaches ~190-200 g/kWh (≈ 43-44 % efficiency).
  double best = 1e9;
  for (double rpm = 900; rpm <= 2300; rpm += 50)
    for (double frac = 0.3; frac <= 1.0; frac += 0.05) {
      const double ww = units::rpmToRadps(rpm), tt = frac * e.fullLoadTorque(ww);
      best = std::min(best, e.steadyFuel(ww, tt) * 3.6e9 / (tt * ww));
    }
  EXPECT_GT(best, 185.0);
  EXPECT_LT(best, 200.0);
}

TEST(MapEngine, Pt1StepResponseMatchesAnalytic) {
  MapEngine e{MapEngineParams{}};
  const double rpm_ref = 1200.0;  // PT1 = 0.53 s at reference speed
  const double w = units::rpmToRadps(rpm_ref * e.scaling().speed_factor);
  const double tau = rawPt1(rpm_ref);
  EXPECT_NEAR(tau, 0.53, 1e-12);
  const double tfl = e.fullLoadTorque(w);
  for (double dt : {0.01, 0.001}) {
    e.reset(w, 0.0);
    MapEngineInputs in;
    in.speed_rad_s = w;
    in.torque_request_Nm = 5000.0;  // above full load: the PT1 limit governs
    const int n = static_cast<int>(std::lround(2.0 / dt));
    for (int k = 1; k <= n; ++k) {
      const double t = e.step(dt, in).brake_torque_Nm;
      const double ref = tfl * (1.0 - std::exp(-k * dt / tau));
      ASSERT_NEAR(t, ref, 1e-9 * tfl) << "dt " << dt << " step " << k;
    }
  }
  // A request below the dynamic limit is served at once (idle-governor corrections).
  e.reset(w, 100.0);
  MapEngineInputs in;
  in.speed_rad_s = w;
  in.torque_request_Nm = 105.0;
  EXPECT_NEAR(e.step(0.01, in).brake_torque_Nm, 105.0, 1e-12);
  // Decrease is instantaneous (fuel cut), to the motoring torque.
  in.torque_request_Nm = -1000.0;
  EXPECT_NEAR(e.step(0.01, in).brake_torque_Nm, e.motoringTorque(w), 1e-12);
}

TEST(MapEngine, FuelIsZeroWhenMotoring) {
  MapEngine e{MapEngineParams{}};
  for (double rpm : {700.0, 1000.0, 1500.0, 2200.0, 2600.0}) {
    const double w = units::rpmToRadps(rpm);
    e.reset(w, 0.0);
    MapEngineInputs in;
    in.speed_rad_s = w;
    in.torque_request_Nm = -2000.0;
    const auto& o = e.step(0.01, in);
    EXPECT_EQ(o.fuel_mass_flow_kg_s, 0.0);
    EXPECT_TRUE(o.fuel_cut);
    EXPECT_NEAR(o.brake_torque_Nm, e.motoringTorque(w), 1e-12);
    EXPECT_LT(o.brake_torque_Nm, 0.0);
    in.torque_request_Nm = e.motoringTorque(w);  // exactly at the drag torque
    EXPECT_EQ(e.step(0.01, in).fuel_mass_flow_kg_s, 0.0);
    in.torque_request_Nm = 200.0;
    in.fuel_enabled = false;  // engine off: drag, no fuel
    EXPECT_EQ(e.step(0.01, in).fuel_mass_flow_kg_s, 0.0);
    EXPECT_EQ(e.steadyFuel(w, e.motoringTorque(w) - 1.0), 0.0);
    EXPECT_GT(e.steadyFuel(w, 0.0), 0.0);  // idle fuel at zero brake torque
  }
}

TEST(MapEngine, NoNanAndMonotoneOverTheOperatingRange) {
  const auto& e = engine();
  for (double w = 0.0; w <= 1.2 * e.maxMapSpeed(); w += 2.0) {
    double prev = -1.0;
    for (double T = -400.0; T <= 1300.0; T += 5.0) {
      const double f = e.steadyFuel(w, T);
      ASSERT_TRUE(std::isfinite(f)) << w << " " << T;
      ASSERT_GE(f, 0.0);
      const bool inRange = w >= e.minMapSpeed() && w <= e.maxMapSpeed() &&
                           T >= e.motoringTorque(w) && T <= e.fullLoadTorque(w);
      if (inRange && w < 0.99 * e.maxMapSpeed()) {  // more torque needs more fuel
        EXPECT_GE(f, prev - 1e-12) << w << " " << T;
        prev = f;
      }
    }
  }
}

TEST(MapEngine, GasPathBalanceCompositionAndAmbientTrend) {
  MapEngine e{MapEngineParams{}};
  const auto& g0 = e.params().gas;
  // Stoichiometric AFR of EN 590 diesel ≈ 14.5-14.6.
  EXPECT_NEAR(stoichiometricAfr(g0.fuel_h_to_c_molar), 14.56, 0.05);
  const double w = units::rpmToRadps(1600.0);
  MapEngineInputs in;
  in.speed_rad_s = w;
  auto run = [&](double T_amb, double Treq) {
    e.reset(w, Treq);
    in.ambient_T_K = T_amb;
    in.torque_request_Nm = Treq;
    return e.step(0.01, in).gas;
  };
  for (double Treq : {0.0, 300.0, 700.0, 1100.0}) {
    const auto g = run(298.15, Treq);
    const double sum = g.brake_power_W + g.coolant_heat_W + g.misc_heat_W + g.intercooler_heat_W +
                       g.exhaust_mass_flow_kg_s * g0.exhaust_cp_J_kgK * (g.exhaust_T_K - 298.15);
    EXPECT_NEAR(sum, g.fuel_power_W, 1e-9 * g.fuel_power_W);
    EXPECT_NEAR(g.comp.y_O2 + g.comp.y_CO2 + g.comp.y_H2O + g.comp.y_N2, 1.0, 1e-12);
    // Carbon balance: CO2 mass flow = fuel carbon (C mass fraction of CH_1.86 = 12.011/13.886);
    // 1e-5: rounding of the tabulated molar masses (reactant vs product mass differs ~1e-6).
    const double co2 = g.comp.y_CO2 * g.exhaust_mass_flow_kg_s;
    EXPECT_NEAR(co2, e.outputs().fuel_mass_flow_kg_s * 12.011 / (12.011 + 1.86 * 1.008) * 44.01 / 12.011,
                1e-5 * co2);
    EXPECT_GT(g.exhaust_T_K, 298.15);
    EXPECT_LT(g.exhaust_T_K, 273.15 + 750.0);
  }
  const auto full = run(298.15, 1100.0);
  EXPECT_GT(full.lambda, 1.2);
  EXPECT_LT(full.lambda, 2.0);
  EXPECT_GT(full.exhaust_T_K, run(298.15, 300.0).exhaust_T_K);
  // Hot ambient -> less dense charge -> lower λ (SPEC §3 trend).
  EXPECT_LT(run(313.15, 1100.0).lambda, run(273.15, 1100.0).lambda);
  // Motoring: the exhaust is air (O2 mass fraction of dry air 0.2314).
  const auto mot = run(298.15, -1000.0);
  EXPECT_NEAR(mot.comp.y_O2, 0.2314, 0.0005);
  EXPECT_EQ(mot.comp.y_CO2, 0.0);
  EXPECT_GT(mot.exhaust_mass_flow_kg_s, 0.05);
  // Heat to coolant: a fraction of the fuel power between the full- and light-load values.
  const auto part = run(298.15, 300.0);
  EXPECT_GT(part.coolant_heat_W, 0.19 * part.fuel_power_W);
  EXPECT_LT(part.coolant_heat_W, 0.31 * part.fuel_power_W);
}

TEST(MapEngine, CumulativeFuelAndWork) {
  MapEngine e{MapEngineParams{}};
  const double w = units::rpmToRadps(1500.0);
  e.reset(w, 600.0);
  MapEngineInputs in;
  in.speed_rad_s = w;
  in.torque_request_Nm = 600.0;
  for (int k = 0; k < 1000; ++k) e.step(0.01, in);
  const auto& o = e.outputs();
  EXPECT_NEAR(o.fuel_mass_kg, 10.0 * e.steadyFuel(w, 600.0), 1e-12);
  EXPECT_NEAR(o.brake_work_J, 10.0 * 600.0 * w, 1e-6);
  EXPECT_NEAR(o.fuel_energy_J, o.fuel_mass_kg * units::kDieselLhv_J_kg, 1e-3);
  // NOx: the NOx map's emission index at this point x the fuel (steady: exact).
  EXPECT_NEAR(o.nox_mass_kg, e.noxEmissionIndex(w, 600.0) * o.fuel_mass_kg, 1e-12);
  EXPECT_GT(o.nox_mass_kg, 0.0);
}

TEST(MapEngine, ColdOilAndBackPressureCostFuelAsDocumented) {
  // Steady 1200 rpm, 400 Nm brake torque (settled PT1): the extra indicated torque of the cold
  // oil and of a back-pressure above the map's reference, each against its formula by hand.
  MapEngineParams p;
  const double w = units::rpmToRadps(1200.0), T = 400.0, dt = 0.01;
  auto run = [&](double oil_K, double back_Pa) {
    MapEngine e{p};
    e.reset(w, T);
    MapEngineInputs in;
    in.speed_rad_s = w;
    in.torque_request_Nm = T;
    in.oil_T_K = oil_K;
    in.back_pressure_Pa = back_Pa;
    for (int k = 0; k < 300; ++k) e.step(dt, in);
    return e.outputs();
  };
  const auto warm = run(0.0, 0.0);
  EXPECT_DOUBLE_EQ(warm.friction_correction_Nm, 0.0);
  EXPECT_DOUBLE_EQ(warm.pumping_correction_Nm, 0.0);
  // Oil at its reference temperature: no correction, the warm map's fuel.
  const auto ref = run(p.oil_ref_K, 0.0);
  EXPECT_NEAR(ref.friction_correction_Nm, 0.0, 1e-12);
  EXPECT_DOUBLE_EQ(ref.fuel_mass_flow_kg_s, warm.fuel_mass_flow_kg_s);
  // Oil at 30 degC: Vogel viscosity ratio by hand.
  const double Toil = 303.15;
  const double phi = std::pow(std::exp(1170.0 / (Toil - 150.0) - 1170.0 / (363.15 - 150.0)), 0.25);
  const double dT = 0.75 * std::fabs(engine().motoringTorque(w)) * (phi - 1.0);
  const auto cold = run(Toil, 0.0);
  EXPECT_GT(phi, 1.5);
  EXPECT_NEAR(cold.friction_correction_Nm, dT, 1e-9 * dT);
  EXPECT_DOUBLE_EQ(cold.brake_torque_Nm, T);  // the driver still gets the torque asked for
  EXPECT_NEAR(cold.fuel_mass_flow_kg_s, engine().steadyFuel(w, T + dT), 1e-15);
  EXPECT_GT(cold.fuel_mass_flow_kg_s, warm.fuel_mass_flow_kg_s * 1.02);
  // Back-pressure 20 kPa above the reference at this flow: + 20 kPa pi_T V_d / (4 pi).
  const double x = warm.gas.exhaust_mass_flow_kg_s;
  MapEngine rated{p};
  double w_r = 0.0;
  rated.peakPower(&w_r);
  const double x_r = computeGasPath(p.gas, w_r, rated.fullLoadTorque(w_r), 1.0,
                                    rated.steadyFuel(w_r, rated.fullLoadTorque(w_r)),
                                    rated.steadyFuel(w_r, rated.fullLoadTorque(w_r)), 298.15,
                                    101325.0, 0.0, 0.0).exhaust_mass_flow_kg_s;
  const double p_ref = 101325.0 + p.back_pressure_ref_rated_Pa * std::pow(x / x_r, p.back_pressure_ref_exponent);
  const auto bp = run(0.0, p_ref + 20000.0);
  const double dT_pump = 20000.0 * warm.gas.pressure_ratio * p.gas.displacement_m3 / (4.0 * units::kPi);
  EXPECT_NEAR(bp.pumping_correction_Nm, dT_pump, 0.02 * dT_pump);  // flow moves slightly with the fuel
  EXPECT_GT(bp.fuel_mass_flow_kg_s, warm.fuel_mass_flow_kg_s);
  const auto at_ref = run(0.0, p_ref);
  EXPECT_NEAR(at_ref.pumping_correction_Nm, 0.0, 1e-9);
}

TEST(MapEngine, ConfigYamlMatchesDeclaredParameters) {
  MapEngineParams p;
  ParamSet ps;
  p.declare(ps);
  const ParamSource src = readYamlParams("config/engine_map.yaml");
  EXPECT_NO_THROW(applyParams(ps, src));  // no unknown key, every value in range
  for (const auto& entry : ps.entries())
    EXPECT_TRUE(src.values.count(entry.key)) << "declared key missing from YAML: " << entry.key;
  MapEngine e(p);
  EXPECT_NEAR(e.peakPower(), 210000.0, 1e-6);
}

TEST(MapEngine, BadParametersNameFileAndKey) {
  MapEngineParams p;
  ParamSet ps;
  p.declare(ps);
  ParamSource src;
  src.file = "engine_map.yaml";
  src.set("displacment_m3", 6.7e-3);  // misspelt
  expectInputError([&] { applyParams(ps, src); }, "engine_map.yaml", "displacment_m3");
  ParamSource src2;
  src2.file = "engine_map.yaml";
  src2.set("volumetric_efficiency", NAN);
  EXPECT_THROW(applyParams(ps, src2), InputError);
  MapEngineParams bad;
  bad.fuel_map_file = "/nonexistent/map.vmap";
  expectInputError([&] { MapEngine e(bad); }, "/nonexistent/map.vmap", "(file)");
}
