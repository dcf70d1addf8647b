// Motored engine: volumetric efficiency against the speed-density estimate; energy conservation
// of the assembly at the cylinder ports over converged cycles of a fired point.
#include <gtest/gtest.h>

#include <cstdio>

#include "support.hpp"

using namespace hbt::engine_1d;
using namespace hbt::engine_1d::test;

TEST(Engine1DMotored, VolumetricEfficiencyAndMotoringTorque) {
  Engine1D e(defaultParams(), repoRoot());
  const double rpm = 1400.0, w = rpm * kRpm;
  e.reset(w, -2000.0);
  const Engine1DOutputs& o = run(e, rpm, -2000.0, 1.0, 298.15, false);
  // speed-density: mdot = eta_v rho_im V_d n/2, rho_im from the plenum cycle means
  const double R = defaultParams().turbo.air_gas_constant;
  const double rho = o.boost_pressure_Pa / (R * o.intake_manifold_T_K);
  const double mdot_sd = rho * e.assembly().displacement_m3() * rpm / 120.0;
  const double eta_v = o.air_mass_flow_kg_s / mdot_sd;
  std::printf("motored 1400 rpm: air %.4f kg/s, p_im %.0f Pa, T_im %.1f K, eta_v %.3f, "
              "T_b %.1f Nm (reference motoring %.1f Nm), pmax %.1f bar\n",
              o.air_mass_flow_kg_s, o.boost_pressure_Pa, o.intake_manifold_T_K, eta_v,
              o.brake_torque_Nm, e.motoringTorque(w), o.peak_cylinder_pressure_Pa / 1e5);
  EXPECT_GT(eta_v, 0.85);
  EXPECT_LT(eta_v, 1.0);
  EXPECT_EQ(o.fuel_mass_flow_kg_s, 0.0);
  // motoring torque emerges from pumping + Chen-Flynn friction: same sign and magnitude class
  EXPECT_LT(o.brake_torque_Nm, 0.0);
  EXPECT_GT(o.brake_torque_Nm, 1.6 * e.motoringTorque(w));
  EXPECT_LT(o.brake_torque_Nm, 0.5 * e.motoringTorque(w));
  // compression pressure of a CR 16.8 engine at ~1 bar intake: 40-60 bar
  EXPECT_GT(o.peak_cylinder_pressure_Pa, 35e5);
  EXPECT_LT(o.peak_cylinder_pressure_Pa, 65e5);
}

TEST(Engine1DMotored, EnergyConservationAtThePortsOverConvergedCycles) {
  Engine1D e(defaultParams(), repoRoot());
  const double rpm = 1400.0, w = rpm * kRpm, tc = 120.0 / rpm;
  e.reset(w, 550.0);
  run(e, rpm, 550.0, 30 * tc, 298.15, true, tc / 36.0);  // converge
  const EnergyTotals a = e.assembly().totals();
  const Engine1DOutputs w0 = e.outputs();
  run(e, rpm, 550.0, 5 * tc, 298.15, true, tc / 36.0);   // 5 whole cycles
  const EnergyTotals b = e.assembly().totals();
  const double fuel = b.fuel_energy_J - a.fuel_energy_J;
  const double ind = b.indicated_work_J - a.indicated_work_J;
  const double fric = b.friction_work_J - a.friction_work_J;
  const double wall = b.wall_heat_J - a.wall_heat_J;
  const double hex = b.exhaust_enthalpy_J - a.exhaust_enthalpy_J;
  const double hin = b.intake_enthalpy_J - a.intake_enthalpy_J;
  const double brake = ind - fric;
  const double rhs = brake + fric + wall + hex - hin;
  std::printf("5 cycles @1400 rpm/550 Nm: fuel %.0f J = brake %.0f + friction %.0f + wall %.0f + "
              "exhaust %.0f - intake %.0f = %.0f J (%+.2f %%)\n",
              fuel, brake, fric, wall, hex, hin, rhs, 100.0 * (rhs - fuel) / fuel);
  ASSERT_GT(fuel, 0.0);
  EXPECT_NEAR(rhs / fuel, 1.0, 0.03);
  EXPECT_GT(brake / fuel, 0.30);  // brake efficiency of a HD diesel at mid load: 0.38-0.44
  EXPECT_LT(brake / fuel, 0.48);
  // The published brake-work totals (Σ T_b ω Δt of the cycle-mean torque) equal the exact
  // p dV work minus friction over whole cycles at steady state, and are all positive work.
  const double dW = e.outputs().brake_work_J - w0.brake_work_J;
  EXPECT_NEAR(dW / brake, 1.0, 0.01);
  EXPECT_DOUBLE_EQ(e.outputs().positive_work_J - w0.positive_work_J, dW);
  EXPECT_EQ(e.outputs().motoring_work_J, w0.motoring_work_J);
  // Fuel cut: once the one-cycle window holds only dragged cycles, all work goes to the motoring
  // total (T_mot w t within 5 %) and the positive total stays.
  run(e, rpm, -2000.0, 1.0, 298.15, false);
  const Engine1DOutputs before = e.outputs();
  run(e, rpm, -2000.0, 5 * tc, 298.15, false, tc / 36.0);
  const double mot0 = e.outputs().motoring_work_J;
  const Engine1DOutputs& o = run(e, rpm, -2000.0, 5 * tc, 298.15, false, tc / 36.0);
  EXPECT_EQ(o.positive_work_J, before.positive_work_J);
  EXPECT_LT(o.motoring_work_J - mot0, 0.0);
  EXPECT_NEAR((o.motoring_work_J - mot0) / (o.brake_torque_Nm * w * 5 * tc), 1.0, 0.05);
}
