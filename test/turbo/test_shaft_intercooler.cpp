// Rotor dynamics against analytic solutions (free run-down, spin-up, steady speed with drag)
// and intercooler limit cases, pressure-drop scaling and parameter errors.
#include <gtest/gtest.h>

#include <cmath>

#include "common/errors.hpp"
#include "turbo/intercooler.hpp"
#include "turbo/shaft.hpp"
#include "../common/input_errors.hpp"

using namespace hbt::turbo;

TEST(TurboShaft, FreeRunDownMatchesAnalyticExponential) {
  ShaftParams p;  // J = 1.5e-4, drag 300 W at 100 krpm
  const double w0 = 12000.0;
  TurboShaft s(p, w0);
  const double kf = 300.0 / (10471.975511965978 * 10471.975511965978);
  EXPECT_NEAR(s.frictionCoefficient(), kf, 1e-18);
  // J ω dω/dt = −k ω²  →  ω = ω0 exp(−k t / J)
  const double dt = 1e-4;
  for (int i = 1; i <= 200000; ++i) {
    s.step(dt, 0.0, 0.0);
    if (i % 20000 == 0) {
      const double t = i * dt;
      EXPECT_NEAR(s.omega(), w0 * std::exp(-kf * t / p.inertia_kg_m2), 1e-9 * w0) << t;
    }
  }
  // explicit form: dω/dt = −k ω / J
  TurboShaft s2(p, w0);
  EXPECT_NEAR(s2.derivative(0.0, 0.0), -kf * w0 / p.inertia_kg_m2, 1e-9);
  // energy lost over the run-down equals the drag work ∫ k ω² dt (trapezoid, fine steps)
  double work = 0.0, E0 = s2.kineticEnergy();
  for (int i = 0; i < 100000; ++i) {
    const double a = s2.frictionPower();
    s2.step(1e-4, 0.0, 0.0);
    work += 0.5 * (a + s2.frictionPower()) * 1e-4;
  }
  EXPECT_NEAR(E0 - s2.kineticEnergy(), work, 1e-6 * E0);
}

TEST(TurboShaft, SpinUpAndSteadySpeedWithDrag) {
  ShaftParams p;
  p.friction_ref_power_W = 0.0;
  p.eta_mech = 0.95;
  TurboShaft s(p, 0.0);
  // no drag, constant net power F: ½ J ω² = F t
  const double Pt = 20000.0, Pc = 15000.0, F = 0.95 * Pt - Pc;
  for (int i = 0; i < 1000; ++i) s.step(1e-3, Pt, Pc);
  EXPECT_NEAR(s.omega(), std::sqrt(2.0 * F * 1.0 / p.inertia_kg_m2), 1e-6 * s.omega());
  // with drag: ω → √(F/k)
  ShaftParams q;
  TurboShaft d(q, 0.0);
  for (int i = 0; i < 4000; ++i) d.step(0.1, 1000.0 / q.eta_mech, 0.0);
  EXPECT_NEAR(d.omega(), std::sqrt(1000.0 / d.frictionCoefficient()), 1e-6 * d.omega());
  EXPECT_NEAR(d.netPower(1000.0 / q.eta_mech, 0.0), 0.0, 1e-2);  // 1e-5 of the input
  // braking at standstill: speed stays 0, never negative or NaN
  TurboShaft z(q, 0.0);
  z.step(0.01, 0.0, 5000.0);
  EXPECT_EQ(z.omega(), 0.0);
  EXPECT_TRUE(std::isfinite(z.derivative(0.0, 5000.0)));
  EXPECT_NEAR(z.derivative(0.0, 5000.0), -5000.0 / (q.inertia_kg_m2 * q.omega_min_rad_s), 1e-6);
}

TEST(Intercooler, EffectivenessLimitCases) {
  IntercoolerParams p;
  p.effectiveness_flow_kg_s = {0.1};
  p.effectiveness = {0.0};
  const Intercooler none(p);
  EXPECT_DOUBLE_EQ(none.outletTemperature(420.0, 300.0, 0.2), 420.0);
  p.effectiveness = {1.0};
  const Intercooler ideal(p);
  EXPECT_DOUBLE_EQ(ideal.outletTemperature(420.0, 300.0, 0.2), 300.0);
  p.cooling_air_offset_K = 5.0;
  EXPECT_DOUBLE_EQ(Intercooler(p).outletTemperature(420.0, 300.0, 0.2), 305.0);
  // default table: ε falls with flow, interpolated linearly, clamped at the ends
  const Intercooler ic{IntercoolerParams{}};
  EXPECT_NEAR(ic.effectiveness(0.225), 0.5 * (0.90 + 0.86), 1e-12);
  EXPECT_NEAR(ic.effectiveness(2.0), 0.83, 1e-12);
  EXPECT_NEAR(ic.outletTemperature(430.0, 298.0, 0.30), 430.0 - 0.86 * (430.0 - 298.0), 1e-9);
  // hotter ambient → hotter charge (same compressor outlet)
  EXPECT_GT(ic.outletTemperature(430.0, 313.0, 0.3), ic.outletTemperature(430.0, 298.0, 0.3));
}

TEST(Intercooler, PressureDropScalesWithFlowSquaredTemperatureOverPressure) {
  const Intercooler ic{IntercoolerParams{}};
  EXPECT_NEAR(ic.pressureDrop(0.30, 440.0, 260000.0), 10000.0, 1e-9);
  EXPECT_NEAR(ic.pressureDrop(0.15, 440.0, 260000.0), 2500.0, 1e-9);
  EXPECT_NEAR(ic.pressureDrop(0.30, 880.0, 520000.0), 10000.0, 1e-9);
  EXPECT_NEAR(ic.pressureDrop(0.30, 440.0, 130000.0), 20000.0, 1e-9);
  EXPECT_NEAR(ic.massFlowForDrop(2500.0, 440.0, 260000.0), 0.15, 1e-12);
  EXPECT_EQ(ic.massFlowForDrop(-10.0, 440.0, 260000.0), 0.0);
}

TEST(Intercooler, BadParametersNameFileAndKey) {
  IntercoolerParams p;
  p.effectiveness = {0.9, 0.8};
  hbt::testing::expectInputError([&] { Intercooler(p, "engine_1d_turbo.yaml", "turbo/intercooler/"); },
                                 "engine_1d_turbo.yaml", "turbo/intercooler/effectiveness");
  p = IntercoolerParams{};
  p.effectiveness_flow_kg_s = {0.1, 0.05, 0.3, 0.4};
  EXPECT_THROW(Intercooler(p, "f.yaml"), hbt::InputError);
}
