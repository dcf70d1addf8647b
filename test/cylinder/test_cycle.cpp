// Closed-cycle tests of the Cylinder: isentropic motoring, energy conservation with combustion,
// burn-point bookkeeping against the double-Wiebe inverse.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/units.hpp"
#include "cylinder/cylinder.hpp"
#include "support.hpp"

using namespace hbt::cylinder;

namespace {
constexpr double kOmega = 1400.0 * M_PI / 30.0;
double dtFor(double deg) { return hbt::units::degToRad(deg) / kOmega; }
double sensibleU(const Cylinder& c) {
  double m[kNumGroups];
  for (int g = 0; g < kNumGroups; ++g) m[g] = c.unburnedGroupMass(Group(g));
  double U = mixturePoly(c.thermo(), m).u(c.unburnedTemperature_K());
  if (c.twoZone()) {
    for (int g = 0; g < kNumGroups; ++g) m[g] = c.burnedZoneGroupMass(Group(g));
    U += mixturePoly(c.thermo(), m).u(c.burnedTemperature_K());
  }
  return U;
}
}  // namespace

TEST(CylinderCycle, MotoredConstantCpIsIsentropicAndReturnsToStart) {
  CylinderParams P = test::loadParams();
  P.constant_cp = true;
  // Runs BDC → TDC → BDC adiabatic and closed; returns the worst |p V^γ / (p V^γ)_0 − 1|.
  auto run = [&](double step_deg, Cylinder& c) {
    c.setWallHeatTransfer(false);
    c.setCombustion(false);
    c.initialize(-180.0, 1.0e5, 300.0, 0.0);
    const double cp = c.thermo().group(kAir).cp(300.0), R = c.thermo().group(kAir).R;
    const double g = cp / (cp - R);
    const double pv0 = c.pressure_Pa() * std::pow(c.volume_m3(), g);
    double worst = 0.0, pmax = 0.0;
    const PortFlows none;
    const int n = static_cast<int>(std::lround(360.0 / step_deg));
    for (int i = 0; i < n; ++i) {
      c.advance(dtFor(step_deg), kOmega, none);
      worst = std::max(worst, std::fabs(c.pressure_Pa() * std::pow(c.volume_m3(), g) / pv0 - 1.0));
      pmax = std::max(pmax, c.pressure_Pa());
    }
    EXPECT_NEAR(pmax / 1.0e5, std::pow(16.8, g), 1e-5 * pmax / 1.0e5);  // p_TDC = p_BDC ε^γ
    return worst;
  };
  Cylinder c1(P, "motored"), c2(P, "motored");
  const double e1 = run(0.1, c1), e2 = run(0.05, c2);
  EXPECT_LT(e1, 5e-6);  // p V^γ = const to the O(Δθ²) error of the trapezoidal energy equation
  EXPECT_GT(e1 / e2, 3.5);  // second order: halving the step divides the error by ~4
  EXPECT_LT(e1 / e2, 4.5);
  EXPECT_NEAR(c1.crankAngle_deg(), 180.0, 1e-9);
  EXPECT_NEAR(c1.pressure_Pa() / 1.0e5, 1.0, 1e-9);  // back at the start state
  EXPECT_NEAR(c1.temperature_K() / 300.0, 1.0, 1e-9);
}

TEST(CylinderCycle, MotoredVariableCpConservesEnergyOverTheCycle) {
  CylinderParams P = test::loadParams();
  Cylinder c(P, "motored");
  c.setWallHeatTransfer(false);
  c.setCombustion(false);
  c.initialize(-180.0, 2.0e5, 330.0, 0.1);
  const double U0 = sensibleU(c);
  std::vector<double> pv;
  double W = 0.0, p_prev = c.pressure_Pa(), V_prev = c.volume_m3();
  const PortFlows none;
  for (int i = 0; i < 1800; ++i) {
    c.advance(dtFor(0.2), kOmega, none);
    W += 0.5 * (p_prev + c.pressure_Pa()) * (c.volume_m3() - V_prev);
    p_prev = c.pressure_Pa();
    V_prev = c.volume_m3();
  }
  EXPECT_NEAR((sensibleU(c) - U0 + W) / U0, 0.0, 1e-12);  // first law, adiabatic closed
  EXPECT_NEAR(c.pressure_Pa() / 2.0e5, 1.0, 1e-6);         // back at the start state
}

TEST(CylinderCycle, FiredClosedCycleFirstLawClosesOnLHV) {
  CylinderParams P = test::loadParams();
  Cylinder c(P, "fired");
  c.setWallHeatTransfer(false);
  InjectionSchedule s;
  s.rail_pressure_Pa = 1300e5;
  s.pulse[0] = {-17.0, 2e-6};   // pilot
  s.pulse[1] = {-5.0, 58e-6};   // main
  s.pulse[2] = {20.0, 4e-6};    // post
  c.setInjectionOverride(s);
  c.initialize(-150.5, 1.9e5, 340.0, 0.04);  // just before IVC
  const PortFlows none;
  c.advance(dtFor(0.5), kOmega, none);       // crosses IVC: schedule latched
  const double U0 = sensibleU(c);
  double W = 0.0, p_prev = c.pressure_Pa(), V_prev = c.volume_m3();
  while (c.crankAngle_deg() < 129.0) {
    c.advance(dtFor(0.1), kOmega, none);
    W += 0.5 * (p_prev + c.pressure_Pa()) * (c.volume_m3() - V_prev);
    p_prev = c.pressure_Pa();
    V_prev = c.volume_m3();
  }
  const double m_inj = 64e-6;
  EXPECT_NEAR(c.pulseInjected_kg(0) + c.pulseInjected_kg(1) + c.pulseInjected_kg(2), m_inj, 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(c.pulseIgnited(i)) << "pulse " << i;
  const double m_fb = c.fuelBurnedThisCycle_kg();
  EXPECT_NEAR(m_fb / m_inj, 1.0, 1e-3);  // every pulse burned out by EVO
  // Energy: ΔU_sensible + W − m_inj (h_fuel(T_fuel) − h_fg) = released chemical energy
  //         = m_fb (LHV + h_fg)  →  check against burned fuel × LHV within 0.1 %.
  const double h_inj = c.thermo().group(kFuelVap).h(P.fuel_temperature_K) - P.fuel.hfg_J_kg;
  const double released = sensibleU(c) - U0 + W - m_inj * h_inj - m_fb * P.fuel.hfg_J_kg;
  EXPECT_NEAR(released / (m_fb * P.fuel.lhv_J_kg), 1.0, 1e-3);
  EXPECT_NEAR(c.heatReleaseThisCycle_J(), m_fb * P.fuel.lhv_J_kg, 1e-9 * m_fb * P.fuel.lhv_J_kg);
  EXPECT_GT(c.workThisCycle_J(), 0.0);
}

TEST(CylinderCycle, BurnPointsFollowTheDoubleWiebeInverse) {
  CylinderParams P = test::loadParams();
  P.pilot_fraction.assign(25, 0.0);  // single pulse so that CA10/50/90 belong to one Wiebe pair
  P.finalize();
  Cylinder c(P, "ca50");
  c.setFuelPerCycle(60e-6);
  c.setWallHeatTransfer(false);
  c.initialize(-160.0, 1.9e5, 340.0, 0.04);
  const PortFlows none;
  while (c.crankAngle_deg() < 129.0) c.advance(dtFor(0.05), kOmega, none);
  ASSERT_TRUE(c.pulseIgnited(1));
  const DoubleWiebe& w = c.pulseWiebe(1);
  // Invert the double Wiebe numerically (bisection) and compare with the cylinder's own marks.
  auto inv = [&](double x) {
    double a = w.premixed.theta_i_deg, b = w.end_deg();
    for (int i = 0; i < 200; ++i) {
      const double m = 0.5 * (a + b);
      (w.x(m) < x ? a : b) = m;
    }
    return 0.5 * (a + b);
  };
  // Run to the end of the cycle so that the marks are published.
  while (c.cyclesCompleted() == 0) c.advance(dtFor(0.5), kOmega, none);
  const CycleResults& r = c.lastCycle();
  EXPECT_NEAR(r.ca10_deg, inv(0.1), 0.06);
  EXPECT_NEAR(r.ca50_deg, inv(0.5), 0.06);
  EXPECT_NEAR(r.ca90_deg, inv(0.9), 0.06);
  EXPECT_GT(r.ca50_deg, 0.0);
  EXPECT_LT(r.ca50_deg, 25.0);
}
