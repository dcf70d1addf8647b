// Components of the assembly: tabulated turbo maps against the direct look-ups, valve areas,
// the charge-air-cooler link (mass conservation, heat removal), the cycle window, and the GTR
// No. 4 reference speeds / regression helpers.
#include <gtest/gtest.h>

#include <cmath>

#include "engine_1d/cycle_window.hpp"
#include "engine_1d/whtc.hpp"
#include "support.hpp"

using namespace hbt::engine1d;
using namespace hbt::engine1d::test;

namespace {
const hbt::turbo::Turbocharger& turbo() {
  static const hbt::turbo::Turbocharger t = hbt::turbo::buildTurbocharger(defaultParams().turbo, repoRoot());
  return t;
}
}  // namespace

TEST(Engine1DComponents, TabulatedCompressorMatchesDirectLookup) {
  const auto& c = turbo().compressor;
  CompressorFlowMap m(c);
  double worst = 0.0;
  for (double krpm : {40.0, 60.0, 80.0, 95.0})
    for (double pr : {1.2, 1.5, 1.9, 2.3, 2.6}) {
      const double w = krpm * 1e3 * kRpm, p1 = 98000.0, T1 = 300.0, p2 = pr * p1;
      const auto s = c.evaluate(p1, T1, p2, w);
      if (s.mass_flow_kg_s < 0.05) continue;  // near shut-off the relative error is meaningless
      worst = std::max(worst, std::fabs(m.massFlow(p1, T1, p2, w) / s.mass_flow_kg_s - 1.0));
      const double T2 = T1 * (1.0 + (std::pow(pr, 0.4 / 1.4) - 1.0) / m.efficiency(p1, T1, p2, w));
      EXPECT_NEAR(T2, s.outlet_total_temperature_K, 1.5) << krpm << " krpm PR " << pr;
    }
  EXPECT_LT(worst, 0.02);
}

TEST(Engine1DComponents, TabulatedTurbineAndWastegateMatchDirectLookup) {
  const auto& t = turbo().turbine;
  TurbineFlowMap e0(t.entry(0), &t.wastegate());
  for (double krpm : {30.0, 60.0, 90.0})
    for (double er : {1.3, 1.8, 2.5}) {
      const double w = krpm * 1e3 * kRpm, p4 = 105000.0, p3 = er * p4, T3 = 850.0;
      const auto s = t.entry(0).evaluate(p3, T3, p4, w);
      e0.setWastegateOpening(0.0);
      EXPECT_NEAR(e0.massFlow(p3, T3, p4, w), s.mass_flow_kg_s, 0.01 * s.mass_flow_kg_s + 1e-4);
      EXPECT_NEAR(e0.efficiency(p3, T3, p4, w), s.eta, 0.01);
      e0.setWastegateOpening(0.6);
      const double mwg = t.wastegate().massFlow(p3, T3, p4, 0.6);
      double me, mw;
      e0.flows(p3, T3, p4, w, me, mw);
      EXPECT_NEAR(mw, mwg, 0.002 * mwg + 1e-6);
      // bypass lowers the effective efficiency so that the power is the wheel's only
      EXPECT_NEAR(e0.efficiency(p3, T3, p4, w) * (me + mw), s.eta * me, 0.01 * s.eta * me + 1e-6);
    }
}

TEST(Engine1DComponents, ValveAreaFollowsLiftAndTiming) {
  const Engine1DParams& p = defaultParams();
  hbt::cyl::Cylinder c(p.cylinder, "c");
  CrankValveArea iv(c, p.engine.intake_valve, p.cylinder.ivo_deg, p.cylinder.ivc_deg, false);
  CrankValveArea ev(c, p.engine.exhaust_valve, p.cylinder.evo_deg, p.cylinder.evc_deg, true);
  EXPECT_EQ(iv.areaAt(0.0, false), 0.0);    // firing TDC: both closed
  EXPECT_EQ(ev.areaAt(0.0, true), 0.0);
  EXPECT_GT(iv.areaAt(-250.0, false), 0.0);  // intake stroke: intake open (normal = Reverse)
  EXPECT_EQ(iv.areaAt(-100.0, false), 0.0);  // after IVC
  EXPECT_GT(ev.areaAt(250.0, true), 0.0);    // exhaust stroke
  EXPECT_GT(iv.areaAt(-250.0, false), iv.areaAt(-250.0, true));  // back-flow Cd lower
  // maximum lift at mid-event: IVO 350 + 110 = 460 deg -> -260 deg
  const auto& v = p.engine.intake_valve;
  EXPECT_NEAR(iv.lift(-260.0), v.max_lift_m, 1e-9);
}

TEST(Engine1DComponents, CycleWindowGivesExactCycleMeanAndImpulses) {
  CycleWindow<2, 144> win;
  win.reset();
  // x0 = 1 + sin(theta), period 720 deg at constant speed; one impulse of 3 per cycle
  const double dth = 0.7, dt = 1e-4;
  double th = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double x[2] = {1.0 + std::sin(th * M_PI / 360.0), 0.0};
    win.add(dt, dth, x);
    const double before = std::fmod(th, 720.0);
    th += dth;
    if (std::fmod(th, 720.0) < before) win.addImpulse(1, 3.0);
  }
  double m[2];
  win.mean(m);
  const double cycle_time = 720.0 / dth * dt;
  EXPECT_NEAR(m[0], 1.0, 2e-3);
  EXPECT_NEAR(m[1], 3.0 / cycle_time, 0.01 * 3.0 / cycle_time);
}

TEST(Engine1DComponents, GtrReferenceSpeedsAndRegression) {
  // flat torque 1000 Nm from 600 to 1500 rpm, falling linearly to 0 at 3000 rpm
  auto fl = [](double n) { return n <= 1500.0 ? 1000.0 : 1000.0 * (3000.0 - n) / 1500.0; };
  const GtrReferenceSpeeds s = gtrReferenceSpeeds(fl, 600.0, 3000.0);
  // P max at 1500 rpm (d/dn of n(3000-n) = 0 at 1500): P = 1000 * 1500 pi/30
  EXPECT_NEAR(s.n_pmax, 1500.0, 1.0);
  EXPECT_NEAR(s.n_lo, 0.55 * 1500.0, 1.0);  // on the flat part P is proportional to n
  // highest speed with P = 0.7 Pmax: n(3000-n)/1500 = 0.7*1500 -> n = 1500 + sqrt(1500^2 - 0.7*1500*3000/... )
  const double nh = 1500.0 + std::sqrt(1500.0 * 1500.0 - 0.7 * 1500.0 * 1500.0);
  EXPECT_NEAR(s.n_hi, nh, 1.0);
  EXPECT_GT(s.n_pref, 600.0);
  EXPECT_LT(s.n_pref, s.n_95h);
  const Regression r = regress({0, 1, 2, 3, 4}, {1, 3, 5, 7, 9});
  EXPECT_NEAR(r.slope, 2.0, 1e-12);
  EXPECT_NEAR(r.intercept, 1.0, 1e-12);
  EXPECT_NEAR(r.r2, 1.0, 1e-12);
  EXPECT_NEAR(r.see, 0.0, 1e-9);
  EXPECT_TRUE(torqueLimits(1100.0).pass({1.0, 5.0, 0.95, 30.0, 100}));
  EXPECT_FALSE(torqueLimits(1100.0).pass({0.8, 5.0, 0.95, 30.0, 100}));
}
