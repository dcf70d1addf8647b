// Components of the assembly: tabulated turbo maps against the direct look-ups, valve areas,
// the charge-air-cooler link (mass conservation, heat removal), the cycle window, and the GTR
// No. 4 reference speeds / regression helpers, determinism and the coupled-step limiter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "engine_1d/cycle_window.hpp"
#include "engine_1d/whtc.hpp"
#include "support.hpp"

using namespace hbt::engine_1d;
using namespace hbt::engine_1d::test;

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

// Around PI = 1 the stationary wheel's flow has a kink: the orifice flow K sqrt(1 - PI) of the
// throttling wheel below, no forward flow against a pressure rise above (compressor_map.hpp).
// The grid must not turn the stopped turbocharger into a pump (a PI = 1 node): at N = 0 the
// tabulated flow is 0 wherever the map's is (PI > 1), and below PI = 1 it stays under the map's
// orifice law (a chord of the concave sqrt): within 2 % of it down to PI = 0.9, 12 % in the two
// grid cells next to PI = 1 (1.6 % of PI wide, where sqrt(1 - PI) is steepest). (Between N = 0
// and the first speed node, 1.3 krpm, the slow wheel's kink is interpolated linearly in N: a
// spinning-down wheel passes through it in a fraction of a second.)
TEST(Engine1DComponents, TabulatedCompressorPassesNoFlowAgainstAPressureRiseAtRest) {
  const auto& c = turbo().compressor;
  CompressorFlowMap m(c);
  const double p1 = 1e5, T1 = c.tRef();  // corrected = actual
  for (double pr : {1.0, 1.001, 1.005, 1.0115, 1.02, 1.05}) {
    const double direct = c.map().atPressureRatio(0.0, pr).flow_kg_s * p1 / c.pRef();
    ASSERT_NEAR(direct, 0.0, 1e-12) << "PR " << pr;  // the map's own law (premise)
    EXPECT_NEAR(m.massFlow(p1, T1, pr * p1, 0.0), 0.0, 1e-12) << "PR " << pr;
  }
  for (double pr : {0.5, 0.8, 0.9, 0.95, 0.98}) {
    const double direct = c.map().atPressureRatio(0.0, pr).flow_kg_s * p1 / c.pRef();
    const double tab = m.massFlow(p1, T1, pr * p1, 0.0);
    EXPECT_LE(tab, direct * (1.0 + 1e-9)) << "PR " << pr;
    EXPECT_NEAR(tab, direct, (pr <= 0.9 ? 0.02 : 0.12) * direct) << "PR " << pr;
  }
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
  hbt::cylinder::Cylinder c(p.cylinder, "c");
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
  // x0 = 1 + sin(theta), period 720 deg at constant speed; x1: an "injection" of 3 per cycle
  // spread over 100...120 deg, passed as the step's mean rate (as the assembly does). Steps
  // shorter than a bin (5 deg) and up to longer than one (the FSM's coupled step reaches 6 deg):
  // every window, at any phase of the step/bin/cycle pattern, must read the cycle means.
  for (const double dth : {0.7, 3.8, 5.0, 6.3}) {
    CycleWindow<2, 144> win;
    win.reset();
    const double dt = 1e-4 * dth;
    const double cycle_time = 720.0 / dth * dt;
    auto injected = [](double th) {  // cumulative injection at crank angle th [deg]
      const double c = std::floor(th / 720.0), ph = th - 720.0 * c;
      return 3.0 * (c + std::clamp((ph - 100.0) / 20.0, 0.0, 1.0));
    };
    double th = 0.0, worst0 = 0.0, worst1 = 0.0;
    for (int i = 0; i < static_cast<int>(20000 * 0.7 / dth); ++i) {
      const double a = th * M_PI / 360.0, b = (th + dth) * M_PI / 360.0;
      const double x[2] = {1.0 + (std::cos(a) - std::cos(b)) / (b - a),  // step mean of x0
                           (injected(th + dth) - injected(th)) / dt};
      win.add(dt, dth, x);
      th += dth;
      if (th > 1440.0) {
        double m[2];
        win.mean(m);
        worst0 = std::max(worst0, std::abs(m[0] - 1.0));
        worst1 = std::max(worst1, std::abs(m[1] * cycle_time / 3.0 - 1.0));
      }
    }
    std::printf("[cycle window] %.1f deg steps: worst |mean - 1| %.2e, injection %.2e\n", dth,
                worst0, worst1);
    EXPECT_LT(worst0, 1e-3) << dth << " deg steps";
    // a step's injection is known only as its mean rate over the step: the window edge cutting
    // a step smears up to ~half a step of the 20 deg injection (exact when the steps tile 720)
    EXPECT_LT(worst1, 0.5 * dth / 20.0 + 1e-12) << dth << " deg steps";
  }
  CycleWindow<1, 144> win;  // impulses
  win.reset();
  const double one[1] = {0.0};
  for (int i = 0; i < 1440; ++i) {
    win.add(1e-4, 1.0, one);
    if (i % 720 == 300) win.addImpulse(0, 2.0);
  }
  double m[1];
  win.mean(m);
  EXPECT_NEAR(m[0], 2.0 / 0.072, 1e-9);
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

TEST(Engine1DComponents, CoupledStepDeterministicAndNotSetByVolumes) {
  // Same run twice -> bit-identical outputs; with implicit volumes and the FSM's own mesh the
  // coupled step is set by a pipe's CFL (or the crank-angle cap), never by a volume, and the
  // cylinder coupling guard does not bind at this mid-load point.
  const Engine1DParams& p = defaultParams();
  ASSERT_TRUE(p.engine.implicit_volumes);
  double torque[2], fuel[2];
  for (int r = 0; r < 2; ++r) {
    Engine1D e(p, repoRoot());
    e.reset(1400.0 * kRpm, 600.0);
    const Engine1DOutputs& o = run(e, 1400.0, 600.0, 0.4);
    torque[r] = o.brake_torque_Nm;
    fuel[r] = o.fuel_mass_kg;
    std::string who;
    const double dt = e.assembly().stableDt(1400.0 * kRpm, &who);
    bool is_pipe = who == "crank-angle cap";
    for (auto* n : {&e.assembly().intakeNetwork(), &e.assembly().exhaustNetwork()})
      for (const auto& pp : n->pipes()) is_pipe |= pp->name() == who;
    EXPECT_TRUE(is_pipe) << "step limited by " << who;
    EXPECT_GT(dt, 0.3e-3) << who;
  }
  EXPECT_EQ(torque[0], torque[1]);
  EXPECT_EQ(fuel[0], fuel[1]);
}
