// Brick thermal model and pressure drop against independent references.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "aftertreatment/aftertreatment.hpp"
#include "aftertreatment/brick.hpp"
#include "support.hpp"

namespace hbt::aftertreatment {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Geometry from first principles (square cells), independent of Brick.
struct Geo {
  double V, d, p, ofa, gsa, C;
};
Geo geometry(const BrickParams& b) {
  Geo g;
  g.V = kPi * b.diameter_m * b.diameter_m / 4.0 * b.length_m;
  g.p = 0.0254 / std::sqrt(b.cpsi);
  g.d = g.p - b.wall_thickness_mil * 25.4e-6;
  g.ofa = g.d * g.d / (g.p * g.p);
  g.gsa = 4.0 * g.d / (g.p * g.p);
  g.C = g.V * (1.0 - g.ofa) * b.wall_density_kg_m3 * b.wall_cp_J_kgK +
        g.V * b.washcoat_g_L * b.washcoat_cp_J_kgK + b.can_mass_kg * b.can_cp_J_kgK;
  return g;
}

HeatTransferParams noCanLoss() {
  HeatTransferParams h;
  h.h_natural_W_m2K = 0.0;
  h.can_emissivity = 0.0;
  h.underbody_air_factor = 0.0;
  return h;
}

// The inlet slice sees a constant gas inlet: its wall follows exactly
// T(t) = Tin + (T0 - Tin) exp(-t/tau), tau = C_1 / (mdot cp (1 - exp(-NTU_1))).
TEST(Brick, InletSliceFollowsExactExponential) {
  const AtsParams p = test::loadParams();
  const HeatTransferParams h = noCanLoss();
  Brick b("DOC", p.doc, h, false);
  const double T0 = 293.15, Tin = 573.15, mdot = 0.12, cp = 1080.0;
  b.setUniformTemperature(T0);
  const Geo g = geometry(p.doc);
  const int N = p.doc.slices;
  const double k = 0.0241 * std::pow(Tin / 273.15, 0.81);
  const double hA = h.nusselt * k / g.d * g.gsa * g.V / N;
  const double tau = (g.C / N) / (mdot * cp * (1.0 - std::exp(-hA / (mdot * cp))));
  EXPECT_GT(tau, 1.0);  // a real transient (20 steps per tau), not an instantaneous jump
  BrickEnergy e;
  double t = 0.0, max_err = 0.0;
  for (int s = 0; s < 600; ++s) {
    b.stepThermal(0.05, mdot, cp, Tin, nullptr, 293.15, 0.0, e);
    t += 0.05;
    const double ref = Tin + (T0 - Tin) * std::exp(-t / tau);
    max_err = std::max(max_err, std::abs(b.T(0) - ref));
  }
  EXPECT_LT(max_err, 1e-6);
  std::printf("[ats] DOC inlet slice: tau %.3f s, max |T - exact| %.3g K over 30 s\n", tau, max_err);
  // the downstream slices lag behind the inlet slice
  EXPECT_LT(b.T(N - 1), b.T(0));
}

// Lumped limit (NTU << 1, no can loss): the brick-mean wall temperature follows the exponential
// with tau = C / (mdot cp (1 - exp(-NTU))).
TEST(Brick, LumpedLimitTimeConstant) {
  BrickParams bp;
  bp.diameter_m = 0.267;
  bp.length_m = 0.02;
  bp.cpsi = 50.0;
  bp.wall_thickness_mil = 10.0;
  bp.slices = 5;
  const HeatTransferParams h = noCanLoss();
  Brick b("lumped", bp, h, false);
  const double T0 = 293.15, Tin = 593.15, mdot = 0.5, cp = 1100.0;
  b.setUniformTemperature(T0);
  const Geo g = geometry(bp);
  const double hA = h.nusselt * 0.0241 * std::pow(Tin / 273.15, 0.81) / g.d * g.gsa * g.V;
  const double NTU = hA / (mdot * cp);
  ASSERT_LT(NTU, 0.1);
  const double tau = g.C / (mdot * cp * (1.0 - std::exp(-NTU)));
  BrickEnergy e;
  double t = 0.0, max_rel = 0.0;
  for (int s = 0; s < 5000; ++s) {
    b.stepThermal(0.5, mdot, cp, Tin, nullptr, T0, 0.0, e);
    t += 0.5;
    const double ref = Tin + (T0 - Tin) * std::exp(-t / tau);
    max_rel = std::max(max_rel, std::abs(b.meanT() - ref) / (Tin - T0));
  }
  EXPECT_GT(t, 3.0 * tau);  // the transient is covered
  EXPECT_LT(max_rel, 0.01);
  std::printf("[ats] lumped limit: NTU %.3f, tau %.1f s, max deviation from exp %.3g of the step\n",
              NTU, tau, max_rel);
  // energy of the step sequence: gas heat = stored (no can loss, no reaction)
  EXPECT_NEAR(e.gas_to_wall_J, e.stored_J, 1e-9 * e.stored_J);
  EXPECT_NEAR(e.stored_J, g.C * (b.meanT() - T0), 1e-6 * e.stored_J);
}

TEST(Brick, CanLossCoolsAndGrowsWithVehicleSpeed) {
  const AtsParams p = test::loadParams();
  HeatTransferParams h;
  Brick b("SCR", p.scr, h, false);
  const double h0 = b.externalH(600.0, 293.15, 0.0), h1 = b.externalH(600.0, 293.15, 15.0);
  EXPECT_GT(h1, h0 + 5.0);
  EXPECT_GT(b.canUA(600.0, 293.15, 15.0), b.canUA(600.0, 293.15, 0.0));
  // a hot brick without flow cools towards ambient, losing exactly what the can rejects
  b.setUniformTemperature(600.0);
  BrickEnergy e;
  for (int s = 0; s < 100; ++s) b.stepThermal(1.0, 0.0, 1100.0, 600.0, nullptr, 293.15, 10.0, e);
  EXPECT_LT(b.meanT(), 600.0);
  EXPECT_GT(b.meanT(), 293.15);
  EXPECT_NEAR(e.stored_J, -e.can_loss_J, 1e-9 * e.can_loss_J);
}

// Laminar channel pressure drop: dp_lam ~ mu(T) Vdot.
TEST(PressureDrop, LaminarPartScalesWithViscosityAndVolumeFlow) {
  const AtsParams p = test::loadParams();
  Aftertreatment ats(p);
  auto mu = [](double T) {
    return 1.716e-5 * std::pow(T / 273.15, 1.5) * (273.15 + 110.4) / (T + 110.4);
  };
  for (int b = 0; b < kNumBricks; ++b) {
    const PressureDrop a = ats.brickPressureDrop(b, 0.1, 600.0, 1.1e5);
    const PressureDrop a2 = ats.brickPressureDrop(b, 0.2, 600.0, 1.1e5);
    EXPECT_GT(a.laminar_Pa, 0.0);
    EXPECT_NEAR(a2.laminar_Pa / a.laminar_Pa, 2.0, 1e-12) << b;
    EXPECT_NEAR(a2.minor_Pa / a.minor_Pa, 4.0, 1e-12) << b;  // rho u^2
    // same mass flow, hotter gas: Vdot ~ T and mu rises -> dp_lam ~ mu(T) T
    const PressureDrop hot = ats.brickPressureDrop(b, 0.1, 800.0, 1.1e5);
    EXPECT_GT(hot.total(), a.total());
    EXPECT_NEAR(hot.laminar_Pa / a.laminar_Pa, mu(800.0) * 800.0 / (mu(600.0) * 600.0), 1e-9) << b;
  }
  // the laminar part dominates in flow-through monoliths
  const PressureDrop doc = ats.brickPressureDrop(kDOC, 0.3, 750.0, 1.2e5);
  EXPECT_GT(doc.laminar_Pa, 2.0 * doc.minor_Pa);
  // the Hagen-Poiseuille value by hand: 28.45 mu u L / d^2, u = Vdot / (A OFA)
  const Geo g = geometry(p.doc);
  const double rho = 1.2e5 * molarMass(GasComposition{}) / (8.314462618 * 750.0);
  const double u = 0.3 / rho / (g.V / p.doc.length_m * g.ofa);
  EXPECT_NEAR(doc.laminar_Pa, 28.455 * mu(750.0) * u * p.doc.length_m / (g.d * g.d), 1e-9 * doc.laminar_Pa);
}

TEST(PressureDrop, SootLoadRaisesDpfBackPressure) {
  AtsParams p = test::loadParams();
  p.dpf_soot_load_g_L = 0.0;
  Aftertreatment clean(p);
  p.dpf_soot_load_g_L = 4.0;
  Aftertreatment loaded(p);
  const double c = clean.brickPressureDrop(kDPF, 0.25, 700.0, 1.1e5).total();
  const double l = loaded.brickPressureDrop(kDPF, 0.25, 700.0, 1.1e5).total();
  EXPECT_GT(l, 1.2 * c);
}

}  // namespace
}  // namespace hbt::aftertreatment
