// The enclosure's thermal network (src/battery/pack_thermal.hpp) against independent references:
// the energy balance of every step (housing and ventilation heat), the steady state of the
// three-node network (cells, enclosure air, wall) solved by hand from the YAML values including
// the ventilation m_dot c_p, a fine fourth-order Runge-Kutta integration of the same ODEs, the
// flat-plate correlation's continuity at the laminar/mixed transition, and the shipped packs'
// conductances.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "battery/battery_model.hpp"
#include "battery/pack_thermal.hpp"
#include "common/units.hpp"
#include "support.hpp"
#include "common/yaml_params.hpp"

using namespace hbt;
using namespace hbt::battery;
using hbt::battery::test::shippedParams;
using units::celsiusToK;

namespace {

constexpr double kSigma = 5.670374419e-8;

// The network of the shipped 13s7p pack, parameters taken through the model (as the node does).
PackThermalParams shippedNetwork(const std::string& pack_file = "") {
  const BatteryModel m(shippedParams(pack_file), "config/battery.yaml");
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
  // different temperatures: (Q_c + Q_f) h = ΔH + Q_amb + Q_vent.
  PackThermal net(shippedNetwork());
  const PackThermalParams& p = net.params();
  const double T0 = celsiusToK(5.0);
  net.reset(T0 + 3.0, T0);
  double in = 0.0, out = 0.0, vent = 0.0, scale = 0.0;
  const double h = 0.01;
  for (int k = 0; k < 300000; ++k) {  // 3000 s
    const double t = k * h;
    const double Qc = 600.0 + 500.0 * std::sin(t / 13.0);
    const bool fan = std::fmod(t, 400.0) > 150.0;
    const double Qf = fan ? 7.8 : 0.0;
    const double Ta = celsiusToK(5.0 + 10.0 * std::sin(t / 700.0));
    const double v = 8.0 + 8.0 * std::sin(t / 37.0);
    net.step(h, Qc, Qf, Ta, fan, v);
    in += (Qc + Qf) * h;
    out += net.heatToAmbient_J();
    vent += net.ventilationHeat_J();
    if (!fan) {
      EXPECT_EQ(net.ventilationHeat_J(), 0.0);
    }
    scale += std::abs(Qc + Qf) * h + std::abs(net.heatToAmbient_J()) + std::abs(net.ventilationHeat_J());
  }
  const double stored = net.storedHeat_J();
  const double residual = in - out - vent - stored;
  std::printf("3000 s varying duty: heat in %.6g J, through the housing %.6g J, ventilation %.6g J, stored "
              "%.6g J, residual %.2e J (rel %.1e), T_cells %.2f degC, T_housing %.2f degC, T_air %.2f degC\n",
              in, out, vent, stored, residual, residual / scale, units::kToCelsius(net.cellsT_K()),
              units::kToCelsius(net.housingT_K()), units::kToCelsius(net.airT_K()));
  EXPECT_LT(std::abs(residual), 1e-11 * scale);
  EXPECT_GT(vent, 0.1 * in);  // the fans ran 62 % of the time with the cells above the ambient
  // The air node lies between the ambient and the warmer of cells and wall (plus the fan's small heat).
  (void)p;
  EXPECT_LT(net.airT_K(), std::max(net.cellsT_K(), net.housingT_K()) + 1e-9);
}

TEST(PackThermal, SteadyStateIsTheThreeNodeNetworkSolvedByHand) {
  // Constant 400 W in the cells, fans off and on, at rest, 40 degC ambient. Reference: the nodal
  // equations of cells (c), enclosure air (a) and wall (w), temperatures above the ambient, with
  // every conductance written out from the YAML and the ventilation m_dot c_p from the fan line and
  // the system curve solved by the textbook quadratic formula:
  //   c: G_ca (c - a) + G_r (c - w) = Q
  //   a: G_ca (a - c) + G_aw (a - w) + G_v a = Q_f
  //   w: G_aw (w - a) + G_r (w - c) + G_o w = 0          (Cramer's rule on the 3x3 system)
  // The heat leaves by G_o w (housing) and G_v a (ventilation air); their sum is Q + Q_f.
  const BatteryParams bp = shippedParams();
  PackThermal net(shippedNetwork());
  const double Ta = celsiusToK(40.0), Q = 400.0;
  const int n = bp.pack.cells_in_series * bp.pack.cells_in_parallel;
  const auto& e = bp.enclosure;
  const auto& v = bp.ventilation;
  const double T3 = std::pow(e.radiation_mean_temperature_K, 3), Aw = bp.housing.area_m2;
  const double G_r = 4 * kSigma * T3 / (1 / e.emissivity_cells + 1 / e.emissivity_housing - 1) * Aw;
  const double G_o = Aw * (e.h_outside_natural_W_m2K + 4 * e.emissivity_housing * kSigma * T3);
  // Operating point: p_max (1 - V/(n V0)) = R V + K V^2.
  const double R = v.filter_resistance_Pa_s_m3 + bp.housing.cell_gap_resistance_Pa_s_m3;
  const double bq = R + v.fan_max_pressure_Pa / (v.fan_count * v.fan_free_flow_m3_s);
  const double K = v.minor_loss_Pa_s2_m6;
  const double V = (-bq + std::sqrt(bq * bq + 4 * K * v.fan_max_pressure_Pa)) / (2 * K);
  const double rho = v.air_pressure_Pa / (287.05 * Ta);
  for (bool fan : {false, true}) {
    const double Qf = fan ? bp.fan.rated_power_W : 0.0;
    const double G_ca = (fan ? e.h_cells_fan_W_m2K : e.h_cells_natural_W_m2K) * n * bp.cell.cooled_area_m2;
    const double G_aw = (fan ? e.h_wall_inside_fan_W_m2K : e.h_wall_inside_natural_W_m2K) * Aw;
    const double G_v = fan ? rho * V * v.air_cp_J_kgK : 0.0;
    const double M[3][3] = {{G_ca + G_r, -G_ca, -G_r},
                            {-G_ca, G_ca + G_aw + G_v, -G_aw},
                            {-G_r, -G_aw, G_aw + G_r + G_o}};
    auto det3 = [](const double A[3][3]) {
      return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
             A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
    };
    auto solve = [&](double q0, double q1, double q2, double x[3]) {
      const double rhs[3] = {q0, q1, q2}, D = det3(M);
      for (int j = 0; j < 3; ++j) {
        double A[3][3];
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) A[r][c] = c == j ? rhs[r] : M[r][c];
        x[j] = det3(A) / D;
      }
    };
    double x[3], unit[3];
    solve(Q, Qf, 0.0, x);
    solve(1.0, 0.0, 0.0, unit);  // 1 W in the cells alone: overall conductance 1/unit[0]
    const PackConductances g = net.conductances(fan, 0.0, Ta);
    EXPECT_NEAR(g.ventilation_W_K, G_v, 1e-12 * (G_v + 1));
    EXPECT_NEAR(g.overall_W_K, 1.0 / unit[0], 1e-12 / unit[0]);
    if (!fan) {
      EXPECT_NEAR(g.overall_W_K, handOverallAtRest(bp, false), 1e-12 * g.overall_W_K);
    }
    net.reset(Ta);
    for (int k = 0; k < 2000; ++k) net.step(1000.0, Q, Qf, Ta, fan, 0.0);  // 2e6 s, > 100 time constants
    std::printf("fans %s, 40 degC: G = %.3f W/K (G_v = m_dot c_p %.3f, inner %.3f, outer %.3f); 400 W -> cells "
                "+%.3f K, air +%.3f K, housing +%.3f K; out through the housing %.2f W, with the air %.2f W\n",
                fan ? "on " : "off", g.overall_W_K, g.ventilation_W_K, g.inner_W_K, g.outer_W_K,
                net.cellsT_K() - Ta, net.airT_K() - Ta, net.housingT_K() - Ta, net.heatToAmbient_J() / 1000.0,
                net.ventilationHeat_J() / 1000.0);
    EXPECT_NEAR(net.cellsT_K() - Ta, x[0], 1e-9);
    EXPECT_NEAR(net.airT_K() - Ta, x[1], 1e-9);
    EXPECT_NEAR(net.housingT_K() - Ta, x[2], 1e-9);
    EXPECT_NEAR(net.heatToAmbient_J() / 1000.0, G_o * x[2], 1e-9);
    EXPECT_NEAR(net.ventilationHeat_J() / 1000.0, G_v * x[1], 1e-9);
    EXPECT_NEAR(G_o * x[2] + G_v * x[1], Q + Qf, 1e-9);
  }
}

TEST(PackThermal, TransientMatchesFineRungeKutta) {
  // The exact step against RK4 with 0.05 s steps (error ~ (l dt)^4 ~ 1e-16) of the network with
  // the air node explicit: T_air from its balance at every stage, the ventilation heat
  // G_v (T_air - T_amb) integrated alongside. 4000 s from 0 degC with 700 W in the cells, fans on,
  // 10 m/s, ambient 10 degC.
  PackThermal net(shippedNetwork());
  const PackThermalParams& p = net.params();
  const double T0 = celsiusToK(0.0), Ta = celsiusToK(10.0), Qc = 700.0, Qf = 7.8, v = 10.0;
  const PackConductances g = net.conductances(true, v, Ta);
  const double Gca = g.cells_to_air_W_K, Gaw = g.air_to_wall_W_K, Gv = g.ventilation_W_K, Gr = g.radiation_in_W_K;
  auto f = [&](double Tc, double Tw, double& dTc, double& dTw, double& dQ, double& dQv) {
    const double Tair = (Gca * Tc + Gaw * Tw + Gv * Ta + Qf) / (Gca + Gaw + Gv);
    dTc = (Qc - Gca * (Tc - Tair) - Gr * (Tc - Tw)) / p.cells_heat_capacity_J_K;
    dTw = (Gaw * (Tair - Tw) + Gr * (Tc - Tw) - g.outer_W_K * (Tw - Ta)) / p.housing_heat_capacity_J_K;
    dQ = g.outer_W_K * (Tw - Ta);
    dQv = Gv * (Tair - Ta);
  };
  double Tc = T0, Tw = T0, Qa = 0.0, Qv = 0.0;
  const double dt = 0.05;
  for (int k = 0; k < 80000; ++k) {
    double k1c, k1w, k1q, k1v, k2c, k2w, k2q, k2v, k3c, k3w, k3q, k3v, k4c, k4w, k4q, k4v;
    f(Tc, Tw, k1c, k1w, k1q, k1v);
    f(Tc + 0.5 * dt * k1c, Tw + 0.5 * dt * k1w, k2c, k2w, k2q, k2v);
    f(Tc + 0.5 * dt * k2c, Tw + 0.5 * dt * k2w, k3c, k3w, k3q, k3v);
    f(Tc + dt * k3c, Tw + dt * k3w, k4c, k4w, k4q, k4v);
    Tc += dt / 6 * (k1c + 2 * k2c + 2 * k3c + k4c);
    Tw += dt / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
    Qa += dt / 6 * (k1q + 2 * k2q + 2 * k3q + k4q);
    Qv += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  net.reset(T0);
  double Qa_net = 0.0, Qv_net = 0.0;
  for (int k = 0; k < 400000; ++k) {  // the model's own 0.01 s steps
    net.step(0.01, Qc, Qf, Ta, true, v);
    Qa_net += net.heatToAmbient_J();
    Qv_net += net.ventilationHeat_J();
  }
  std::printf("4000 s, 700 W, fans on, 10 m/s: cells %.9f / %.9f degC (exact / RK4), housing %.9f / %.9f, "
              "through the housing %.6f / %.6f kJ, ventilation %.6f / %.6f kJ\n", units::kToCelsius(net.cellsT_K()),
              units::kToCelsius(Tc), units::kToCelsius(net.housingT_K()), units::kToCelsius(Tw), Qa_net / 1e3,
              Qa / 1e3, Qv_net / 1e3, Qv / 1e3);
  EXPECT_NEAR(net.cellsT_K(), Tc, 1e-8);
  EXPECT_NEAR(net.housingT_K(), Tw, 1e-8);
  EXPECT_NEAR(Qa_net, Qa, 1e-9 * std::abs(Qa) + 1e-6);
  EXPECT_NEAR(Qv_net, Qv, 1e-9 * std::abs(Qv) + 1e-6);
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

TEST(PackThermal, ConductanceOfTheShippedPacks) {
  // Fans off at rest: the closed pack is limited by free convection and radiation on its housing:
  // a few W/K. Fans on: the ventilation air carries the heat past the housing: tens of W/K, below
  // the cells' own surface (h_c A_cells + radiation), which bounds any path from the cells.
  for (const char* f : {"", "config/battery_pack/production_13s2p.yaml"}) {
    PackThermal net(shippedNetwork(f));
    const BatteryParams bp = shippedParams(f);
    for (double ambient_c : {0.0, 40.0}) {
      const double Ta = celsiusToK(ambient_c);
      const PackConductances gon = net.conductances(true, 0.0, Ta);
      const double off = net.conductances(false, 0.0, Ta).overall_W_K, on = gon.overall_W_K;
      const double off30 = net.conductances(false, 30 / 3.6, Ta).overall_W_K;
      const double on30 = net.conductances(true, 30 / 3.6, Ta).overall_W_K;
      const double C = net.params().cells_heat_capacity_J_K + net.params().housing_heat_capacity_J_K;
      std::printf("%s, %.0f degC: G fans off %.2f W/K, on %.2f W/K (m_dot c_p %.2f W/K, V %.4f m^3/s at %.2f Pa) "
                  "at rest; at 30 km/h %.2f / %.2f W/K; C %.1f kJ/K, C/G off %.0f s, on %.0f s\n",
                  *f ? f : "13s7p (battery.yaml)", ambient_c, off, on, gon.ventilation_W_K,
                  net.ventilation().flow_m3_s(), net.ventilation().pressure_Pa(), off30, on30, C / 1e3, C / off, C / on);
      EXPECT_NEAR(off, handOverallAtRest(bp, false), 1e-12 * off);
      EXPECT_GT(off, 2.0);
      EXPECT_LT(off, 20.0);
      EXPECT_GT(on, 10.0 * 2.0);
      EXPECT_LT(on, gon.cells_to_air_W_K + gon.radiation_in_W_K);
      EXPECT_GT(off30, off);
      EXPECT_GT(on30, on);
    }
  }
}
