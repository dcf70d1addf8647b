// The enclosure's thermal network (src/battery/pack_thermal.hpp) against independent references:
// the energy balance of every step, the steady state of the series/parallel conductances written
// out by hand, a fine fourth-order Runge-Kutta integration of the same two ODEs, the flat-plate
// correlation's continuity at the laminar/mixed transition, and the shipped packs' conductances.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "battery/battery_model.hpp"
#include "battery/pack_thermal.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"

using namespace hbt;
using namespace hbt::battery;
using units::celsiusToK;

namespace {

constexpr double kSigma = 5.670374419e-8;

BatteryParams shipped(const std::string& pack_file = "") {
  BatteryParams p;
  ParamSet ps;
  p.declare(ps);
  applyParams(ps, readYamlParams("config/battery.yaml"), {"cosim/"});
  if (!pack_file.empty()) {
    ParamSet set;
    p.declarePackSet(set);
    applyParamFile(set, pack_file);
  }
  return p;
}

// The network of the shipped 13s7p pack, parameters taken through the model (as the node does).
PackThermalParams shippedNetwork(const std::string& pack_file = "") {
  const BatteryModel m(shipped(pack_file), "config/battery.yaml");
  return m.thermal().params();
}

// Cells -> ambient conductance written out from the YAML values, at rest (no forced convection).
double handOverallAtRest(const BatteryParams& p, bool fan) {
  const int n = p.pack.cells_in_series * p.pack.cells_in_parallel;
  const double Ac = n * p.cell.cooled_area_m2, Aw = p.housing.area_m2;
  const auto& e = p.enclosure;
  const double T3 = std::pow(e.radiation_mean_temperature_K, 3);
  const double g_ca = (fan ? e.h_cells_fan_W_m2K : e.h_cells_natural_W_m2K) * Ac;
  const double g_aw = (fan ? e.h_wall_inside_fan_W_m2K : e.h_wall_inside_natural_W_m2K) * Aw;
  const double g_rad_in = 4 * kSigma * T3 / (1 / e.emissivity_cells + 1 / e.emissivity_housing - 1) * Aw;
  const double g_in = g_ca * g_aw / (g_ca + g_aw) + g_rad_in;
  const double g_out = Aw * (e.h_outside_natural_W_m2K + 4 * e.emissivity_housing * kSigma * T3);
  return g_in * g_out / (g_in + g_out);
}

}  // namespace

TEST(PackThermal, EnergyBalanceOfEveryStepToRoundOff) {
  // Varying cell heat, fan heat, ambient, fan state and air speed, from cells and housing at
  // different temperatures: (Q_c + Q_f) h = ΔH + Q_amb.
  PackThermal net(shippedNetwork());
  const PackThermalParams& p = net.params();
  const double T0 = celsiusToK(5.0);
  net.reset(T0 + 3.0, T0);
  double in = 0.0, out = 0.0, scale = 0.0;
  const double h = 0.01;
  for (int k = 0; k < 300000; ++k) {  // 3000 s
    const double t = k * h;
    const double Qc = 600.0 + 500.0 * std::sin(t / 13.0);
    const bool fan = std::fmod(t, 400.0) > 150.0;
    const double Qf = fan ? 6.0 : 0.0;
    const double Ta = celsiusToK(5.0 + 10.0 * std::sin(t / 700.0));
    const double v = 8.0 + 8.0 * std::sin(t / 37.0);
    net.step(h, Qc, Qf, Ta, fan, v);
    in += (Qc + Qf) * h;
    out += net.heatToAmbient_J();
    scale += std::abs(Qc + Qf) * h + std::abs(net.heatToAmbient_J());
  }
  const double stored = net.storedHeat_J();
  const double residual = in - out - stored;
  std::printf("3000 s varying duty: heat in %.6g J, to ambient %.6g J, stored %.6g J, residual %.2e J "
              "(rel %.1e), T_cells %.2f degC, T_housing %.2f degC, T_air %.2f degC\n",
              in, out, stored, residual, residual / scale, units::kToCelsius(net.cellsT_K()),
              units::kToCelsius(net.housingT_K()), units::kToCelsius(net.airT_K()));
  EXPECT_LT(std::abs(residual), 1e-11 * scale);
  // The air node lies between the cells and the wall (plus the fan's small heat).
  EXPECT_GT(net.airT_K(), std::min(net.cellsT_K(), net.housingT_K()) - 1e-9);
  EXPECT_LT(net.airT_K(), std::max(net.cellsT_K(), net.housingT_K()) + 6.0 / (p.h_cells_fan_W_m2K * p.cells_area_m2));
}

TEST(PackThermal, SteadyStateIsTheSeriesConductanceSolution) {
  // Constant 400 W in the cells, fan off and on, at rest: after many time constants
  // T_c - T_amb = Q/G (G = 1/(1/G_i + 1/G_o) written out from the YAML), T_w - T_amb = Q/G_o,
  // and the heat to the ambient equals Q. Fan heat Q_f adds Q_f/G_o to both and a_c Q_f/G_i to the cells.
  const BatteryParams bp = shipped();
  PackThermal net(shippedNetwork());
  const double Ta = celsiusToK(25.0), Q = 400.0;
  for (bool fan : {false, true}) {
    const double Qf = fan ? 6.0 : 0.0;
    const PackConductances g = net.conductances(fan, 0.0);
    const double G_hand = handOverallAtRest(bp, fan);
    EXPECT_NEAR(g.overall_W_K, G_hand, 1e-12 * G_hand);
    net.reset(Ta);
    for (int k = 0; k < 2000; ++k) net.step(1000.0, Q, Qf, Ta, fan, 0.0);  // 2e6 s, > 100 time constants
    const double a_c = g.cells_to_air_W_K / (g.cells_to_air_W_K + g.air_to_wall_W_K);
    const double dTw = (Q + Qf) / g.outer_W_K, dTc = dTw + (Q + a_c * Qf) / g.inner_W_K;
    std::printf("fan %s: G = %.3f W/K (inner %.3f, outer %.3f), 400 W -> cells +%.3f K, housing +%.3f K\n",
                fan ? "on " : "off", g.overall_W_K, g.inner_W_K, g.outer_W_K, net.cellsT_K() - Ta, net.housingT_K() - Ta);
    EXPECT_NEAR(net.cellsT_K() - Ta, dTc, 1e-9);
    EXPECT_NEAR(net.housingT_K() - Ta, dTw, 1e-9);
    if (!fan) {
      EXPECT_NEAR(net.cellsT_K() - Ta, Q / G_hand, 1e-9);
    }
    EXPECT_NEAR(net.heatToAmbient_J() / 1000.0, Q + Qf, 1e-9);
  }
}

TEST(PackThermal, TransientMatchesFineRungeKutta) {
  // The exact step against RK4 with 0.05 s steps of the same ODEs (error ~ (l dt)^4 ~ 1e-16),
  // 4000 s from 0 degC with 700 W in the cells, fan on, 10 m/s, ambient 10 degC.
  PackThermal net(shippedNetwork());
  const PackThermalParams& p = net.params();
  const double T0 = celsiusToK(0.0), Ta = celsiusToK(10.0), Qc = 700.0, Qf = 6.0, v = 10.0;
  const PackConductances g = net.conductances(true, v);
  const double a_c = g.cells_to_air_W_K / (g.cells_to_air_W_K + g.air_to_wall_W_K);
  auto f = [&](double Tc, double Tw, double& dTc, double& dTw, double& dQ) {
    dTc = (Qc + a_c * Qf - g.inner_W_K * (Tc - Tw)) / p.cells_heat_capacity_J_K;
    dTw = (g.inner_W_K * (Tc - Tw) + (1 - a_c) * Qf - g.outer_W_K * (Tw - Ta)) / p.housing_heat_capacity_J_K;
    dQ = g.outer_W_K * (Tw - Ta);
  };
  double Tc = T0, Tw = T0, Qa = 0.0;
  const double dt = 0.05;
  for (int k = 0; k < 80000; ++k) {
    double k1c, k1w, k1q, k2c, k2w, k2q, k3c, k3w, k3q, k4c, k4w, k4q;
    f(Tc, Tw, k1c, k1w, k1q);
    f(Tc + 0.5 * dt * k1c, Tw + 0.5 * dt * k1w, k2c, k2w, k2q);
    f(Tc + 0.5 * dt * k2c, Tw + 0.5 * dt * k2w, k3c, k3w, k3q);
    f(Tc + dt * k3c, Tw + dt * k3w, k4c, k4w, k4q);
    Tc += dt / 6 * (k1c + 2 * k2c + 2 * k3c + k4c);
    Tw += dt / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
    Qa += dt / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
  }
  net.reset(T0);
  double Qa_net = 0.0;
  for (int k = 0; k < 400000; ++k) {  // the model's own 0.01 s steps
    net.step(0.01, Qc, Qf, Ta, true, v);
    Qa_net += net.heatToAmbient_J();
  }
  std::printf("4000 s, 700 W, fan on, 10 m/s: cells %.9f / %.9f degC (exact / RK4), housing %.9f / %.9f, "
              "heat to ambient %.6f / %.6f kJ\n", units::kToCelsius(net.cellsT_K()), units::kToCelsius(Tc),
              units::kToCelsius(net.housingT_K()), units::kToCelsius(Tw), Qa_net / 1e3, Qa / 1e3);
  EXPECT_NEAR(net.cellsT_K(), Tc, 1e-8);
  EXPECT_NEAR(net.housingT_K(), Tw, 1e-8);
  EXPECT_NEAR(Qa_net, Qa, 1e-9 * std::abs(Qa) + 1e-6);
  // One 4000 s step of the exact solution gives the same state.
  PackThermal one(net.params());
  one.reset(T0);
  one.step(4000.0, Qc, Qf, Ta, true, v);
  EXPECT_NEAR(one.cellsT_K(), net.cellsT_K(), 1e-9);
  EXPECT_NEAR(one.heatToAmbient_J(), Qa_net, 1e-9 * Qa_net);
}

TEST(PackThermal, FlatPlateCorrelationIsContinuousAtTheTransition) {
  // Incropera's laminar (0.664 Re^1/2) and mixed ((0.037 Re^4/5 - 871)) average Nusselt numbers
  // meet at Re = 5e5 (871 is chosen for that); the forced coefficient grows with speed.
  PackThermal net(shippedNetwork());
  const PackThermalParams& p = net.params();
  const double v_tr = 5e5 * p.air_viscosity_m2_s / p.flow_length_m;
  const double below = net.forcedOutsideH(v_tr * (1 - 1e-9)), above = net.forcedOutsideH(v_tr * (1 + 1e-9));
  std::printf("transition at %.2f m/s: h %.4f / %.4f W/(m^2 K); at 30 km/h %.2f, 50 km/h %.2f W/(m^2 K)\n",
              v_tr, below, above, net.forcedOutsideH(30 / 3.6), net.forcedOutsideH(50 / 3.6));
  EXPECT_NEAR(below, above, 2e-3 * below);
  EXPECT_EQ(net.forcedOutsideH(0.0), 0.0);
  EXPECT_GT(net.forcedOutsideH(10.0), net.forcedOutsideH(5.0));
  // Laminar value by hand at 5 m/s.
  const double Re = 5.0 * p.flow_length_m / p.air_viscosity_m2_s;
  EXPECT_NEAR(net.forcedOutsideH(5.0),
              0.664 * std::sqrt(Re) * std::cbrt(p.air_prandtl) * p.air_conductivity_W_mK / p.flow_length_m, 1e-12);
}

TEST(PackThermal, EnclosedPackConductanceOfTheShippedPacks) {
  // Fan off at rest: an enclosed pack is limited by free convection and radiation on its housing:
  // a few W/K to ~20 W/K (the lumped h A of every cell face in ambient air, 93 W/K, is not
  // an enclosed pack). The fan raises the inner conductance, the ram air the outer one.
  for (const char* f : {"", "config/battery_pack/production_13s2p.yaml"}) {
    PackThermal net(shippedNetwork(f));
    const BatteryParams bp = shipped(f);
    const double off = net.conductances(false, 0.0).overall_W_K, on = net.conductances(true, 0.0).overall_W_K;
    const double off30 = net.conductances(false, 30 / 3.6).overall_W_K, on30 = net.conductances(true, 30 / 3.6).overall_W_K;
    const double C = net.params().cells_heat_capacity_J_K + net.params().housing_heat_capacity_J_K;
    std::printf("%s: G fan off %.2f W/K, on %.2f W/K at rest; at 30 km/h %.2f / %.2f W/K; C %.1f kJ/K, "
                "C/G (off, rest) %.0f s\n", *f ? f : "13s7p (battery.yaml)", off, on, off30, on30, C / 1e3, C / off);
    EXPECT_NEAR(off, handOverallAtRest(bp, false), 1e-12 * off);
    EXPECT_GT(off, 2.0);
    EXPECT_LT(off, 20.0);
    EXPECT_GT(on, off);
    EXPECT_GT(off30, off);
    EXPECT_LT(on30, 93.0 * 0.5);  // far from the open-air lumped value
  }
}
