// Boundary and steady-flow checks for both solvers against analytic references:
//   quarter-wave open-closed pipe: first resonance vs c/(4L) within 1%;
//   steady friction flow: Mach and pressure along the pipe vs the Fanno relations;
//   valve (orifice between a reservoir and a pipe): choked mass flow vs the nozzle formula,
//   both flow directions; lift-profile area provider geometry;
//   turbine entry / compressor outlet with analytic maps: mass flow, energy bookkeeping.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

#include "gasdyn/cases.hpp"
#include "gasdyn/network.hpp"
#include "gasdyn/turbo_boundaries.hpp"

using namespace hbt::gasdyn;

namespace {

const hbt::PerfectGas kAir{1.4, 287.0};

PipeConfig pipeCfg(const char* name, double L, int cells, double d, SolverKind s, double fD = 0) {
  PipeConfig c;
  c.name = name, c.length = L, c.cells = cells, c.diameter_left = c.diameter_right = d;
  c.solver = s, c.friction_darcy = fD;
  return c;
}

// Fanno function f_D L*/D of the Mach number
double fanno(double M) {
  const double g = kAir.gamma, M2 = M * M;
  return (1.0 - M2) / (g * M2) + (g + 1.0) / (2.0 * g) * std::log((g + 1.0) * M2 / (2.0 + (g - 1.0) * M2));
}
double fannoPressure(double M) {  // p/p*
  const double g = kAir.gamma;
  return 1.0 / M * std::sqrt((g + 1.0) / (2.0 + (g - 1.0) * M * M));
}

// nozzle-like analytic turbine map: mdot = A p0/sqrt(R T0) psi(p/p0), constant efficiency
class NozzleMap final : public FlowMap {
 public:
  NozzleMap(double area, double eta) : a_(area), eta_(eta) {}
  double massFlow(double p0, double T0, double p, double) const override {
    return nozzleMassFlow(kAir, a_, p0, T0, p);
  }
  double efficiency(double, double, double, double) const override { return eta_; }

 private:
  double a_, eta_;
};

// analytic compressor characteristic: mdot falls linearly from m0 at PR = 1 to 0 at PR = prmax
class LinearCompressorMap final : public FlowMap {
 public:
  double massFlow(double p0, double, double p, double speed) const override {
    return 0.1 * speed * (1.0 - (p / p0 - 1.0) / (2.0 - 1.0));
  }
  double efficiency(double, double, double, double) const override { return 0.75; }
};

}  // namespace

class BothSolvers : public ::testing::TestWithParam<SolverKind> {};
INSTANTIATE_TEST_SUITE_P(Solvers, BothSolvers, ::testing::Values(SolverKind::FSM, SolverKind::TVD),
                         [](const auto& i) { return std::string(solverName(i.param)); });

TEST_P(BothSolvers, QuarterWaveResonanceWithinOnePercent) {
  const ResonanceResult r = runQuarterWave(GetParam(), 50);
  std::printf("[quarterwave %s] f1 %.3f Hz, c/4L %.3f Hz, error %.3e (%d crossings)\n",
              solverName(GetParam()), r.f_measured, r.f_theory, r.rel_error, r.crossings);
  EXPECT_GE(r.crossings, 20);
  EXPECT_LT(std::abs(r.rel_error), 0.01);
}

TEST_P(BothSolvers, SteadyFrictionFlowFollowsFanno) {
  // reservoir 1.6 bar -> 2 m pipe, D = 25 mm, f_D = 0.025 (f_D L/D = 2) -> reservoir 1 bar
  Network net(kAir);
  const int n = 80;
  Pipe& p = net.addPipe(pipeCfg("fanno", 2.0, n, 0.025, GetParam(), 0.025));
  p.setUniform(1e5, 300.0);
  Volume& in = net.addReservoir("in", 1.6e5, 300.0);
  Volume& out = net.addReservoir("out", 1e5, 300.0);
  auto& bin = net.connect(p, End::Left, in);
  auto& bout = net.connect(p, End::Right, out);
  net.advance(0.6);
  const double m_in = bin.massFlowIn(), m_out = -bout.massFlowIn();
  EXPECT_NEAR(m_out, m_in, 2e-3 * m_in) << "not steady";
  const int i1 = n / 10, i2 = n - 1 - n / 10;
  const double M1 = p.mach(i1), M2 = p.mach(i2);
  const double L12 = p.xCentre(i2) - p.xCentre(i1);
  const double fl_pred = fanno(M1) - fanno(M2), fl = 0.025 * L12 / 0.025;
  const double pr_pred = fannoPressure(M2) / fannoPressure(M1), pr = p.p(i2) / p.p(i1);
  std::printf("[fanno %s] mdot %.5f kg/s, M %.4f -> %.4f; f_D L/D: Fanno %.4f vs %.4f (%.2e); "
              "p2/p1: Fanno %.5f vs %.5f (%.2e)\n",
              solverName(GetParam()), m_in, M1, M2, fl_pred, fl, fl_pred / fl - 1.0, pr_pred, pr,
              pr / pr_pred - 1.0);
  EXPECT_GT(M2, 1.3 * M1);                        // friction accelerates subsonic flow
  EXPECT_NEAR(fl_pred, fl, 0.03 * fl);            // Fanno length within 3%
  EXPECT_NEAR(pr, pr_pred, 0.005 * pr_pred);      // pressure ratio within 0.5%
  // total temperature constant along an adiabatic pipe
  const double T01 = p.T(i1) + 0.5 * p.u(i1) * p.u(i1) / kAir.cp();
  const double T02 = p.T(i2) + 0.5 * p.u(i2) * p.u(i2) / kAir.cp();
  EXPECT_NEAR(T02, T01, 1e-3 * T01);
}

TEST_P(BothSolvers, ValveChokedMassFlowBothDirections) {
  const double Ageo = 1e-4, cdf = 0.8, cdr = 0.6, T0 = 300.0;
  for (int dir = 0; dir < 2; ++dir) {
    Network net(kAir);
    Pipe& p = net.addPipe(pipeCfg("port", 0.5, 50, 0.03, GetParam()));
    const double pv = dir == 0 ? 3e5 : 1e5, pr = dir == 0 ? 1e5 : 3e5;
    p.setUniform(pr, T0);
    Volume& v = net.addReservoir("cyl", pv, T0);
    Volume& r = net.addReservoir("amb", pr, T0);
    auto area = std::make_shared<ConstantArea>(Ageo, cdf, cdr);
    auto& valve = net.add<Valve>("valve", v, leftEnd(p), area);
    auto& open = net.connect(p, End::Right, r);
    net.advance(0.15);
    const double cd = dir == 0 ? cdf : cdr;
    const double expect = cd * Ageo * 3e5 / std::sqrt(kAir.R * T0) * kAir.chokedFlowFunction();
    const double m = dir == 0 ? valve.massFlowIn() : -valve.massFlowIn();
    std::printf("[valve %s %s] mdot %.6f kg/s, choked formula %.6f (%.2e), pipe end %.6f\n",
                solverName(GetParam()), dir == 0 ? "into pipe" : "out of pipe", m, expect,
                m / expect - 1.0, std::abs(open.massFlowIn()));
    EXPECT_NEAR(m, expect, (dir == 0 ? 2e-3 : 1e-2) * expect);
    EXPECT_NEAR(std::abs(open.massFlowIn()), expect, 1e-2 * expect);
  }
}

TEST(Valve, ClosedValveIsAWall) {
  Network net(kAir);
  Pipe& p = net.addPipe(pipeCfg("port", 0.3, 20, 0.03, SolverKind::FSM));
  p.setUniform(1e5, 300.0);
  Volume& v = net.addVolume("cyl", 1e-3, 5e5, 900.0);
  net.add<Valve>("valve", v, leftEnd(p), std::make_shared<ConstantArea>(0.0, 0.7, 0.7));
  net.close(p, End::Right);
  const double m0 = net.totalMass();
  net.advance(0.01);
  EXPECT_DOUBLE_EQ(v.p(), 5e5);
  EXPECT_NEAR(net.totalMass(), m0, 1e-15);
  EXPECT_LT(std::abs(p.u(0)), 1e-9);
}

TEST(LiftProfileArea, CurtainAreaTimesCd) {
  // lift 0 -> 10 mm -> 0 over 180..540 deg; Cd(L/d) = 0.7 - 0.5 L/d
  hbt::Table1D lift({0, 180, 360, 540, 720}, {0, 0, 0.01, 0, 0});
  hbt::Table1D cd({0.0, 0.5}, {0.7, 0.45});
  LiftProfileArea a(lift, cd, cd, 0.04, 2);
  a.setCrank(0.0, 0.0, 1500.0);              // 9000 deg/s
  const double t_top = 360.0 / 9000.0;       // 360 deg
  const double area = 2 * M_PI * 0.04 * 0.01 * (0.7 - 0.5 * 0.25);
  EXPECT_NEAR(a.effectiveArea(FlowDirection::Forward, t_top), area, 1e-12);
  EXPECT_NEAR(a.crankAngle(t_top + 2 * 720.0 / 9000.0), 360.0, 1e-9);
  EXPECT_EQ(a.effectiveArea(FlowDirection::Reverse, 100.0 / 9000.0), 0.0);
}

TEST_P(BothSolvers, TurbineEntryWithNozzleMap) {
  const double p0 = 2e5, T0 = 600.0, At = 3e-4, eta = 0.7;
  Network net(kAir);
  Pipe& p = net.addPipe(pipeCfg("exh", 0.5, 40, 0.04, GetParam()));
  p.setUniform(p0, T0);
  Volume& in = net.addReservoir("manifold", p0, T0);
  Volume& out = net.addReservoir("turbine_out", 1e5, 500.0);
  auto& open = net.connect(p, End::Left, in);
  auto& turb = net.add<TurbineEntry>("turbine", rightEnd(p), out, std::make_shared<NozzleMap>(At, eta));
  const double E0 = net.totalEnergy();
  net.advance(0.1);
  const double expect = nozzleMassFlow(kAir, At, p0, T0, 1e5);  // choked
  const double P = expect * kAir.cp() * T0 * eta * (1.0 - std::pow(0.5, 0.4 / 1.4));
  std::printf("[turbine %s] mdot %.6f kg/s vs nozzle %.6f (%.2e); power %.1f W vs %.1f W\n",
              solverName(GetParam()), turb.massFlow(), expect, turb.massFlow() / expect - 1.0,
              turb.power(), P);
  EXPECT_NEAR(turb.massFlow(), expect, 3e-3 * expect);
  EXPECT_NEAR(open.massFlowIn(), expect, 3e-3 * expect);
  EXPECT_NEAR(turb.power(), P, 1e-2 * P);
  // energy: pipe + what entered the reservoirs + shaft work is conserved
  const double E1 = net.totalEnergy() + net.reservoirEnergyIn() + turb.work();
  EXPECT_NEAR(E1, E0, 1e-11 * E0);
}

TEST_P(BothSolvers, CompressorOutletWithAnalyticMap) {
  const double pin = 1e5, Tin = 300.0, pout = 1.5e5;
  Network net(kAir);
  Pipe& p = net.addPipe(pipeCfg("boost", 0.5, 40, 0.04, GetParam()));
  p.setUniform(pout, 330.0);
  Volume& filter = net.addReservoir("filter", pin, Tin);
  Volume& manifold = net.addReservoir("manifold", pout, 330.0);
  auto& comp = net.add<CompressorOutlet>("compressor", filter, leftEnd(p),
                                         std::make_shared<LinearCompressorMap>());
  comp.setSpeed(1.0);
  auto& open = net.connect(p, End::Right, manifold);
  const double E0 = net.totalEnergy();
  net.advance(0.1);
  const double m = comp.massFlow();
  const double pr = p.p(0) / pin;  // pressure just downstream of the compressor
  const double T0expect = Tin * (1.0 + (std::pow(pr, 0.4 / 1.4) - 1.0) / 0.75);
  const int k = p.cells() - 1;
  const double T0pipe = p.T(k) + 0.5 * p.u(k) * p.u(k) / kAir.cp();
  std::printf("[compressor %s] mdot %.5f kg/s, outlet %.5f; PR %.4f; T0 pipe %.2f K vs %.2f K\n",
              solverName(GetParam()), m, -open.massFlowIn(), pr, T0pipe, T0expect);
  EXPECT_NEAR(m, 0.1 * (1.0 - (pout / pin - 1.0)), 0.03 * m);  // map at the delivery pressure
  EXPECT_NEAR(-open.massFlowIn(), m, 3e-3 * m);
  EXPECT_NEAR(T0pipe, T0expect, 2e-3 * T0expect);
  const double E1 = net.totalEnergy() + net.reservoirEnergyIn() - comp.work();
  EXPECT_NEAR(E1, E0, 1e-11 * E0);
}

TEST_P(BothSolvers, PipeOrificeChokedFlowAndConservation) {
  // reservoir 3 bar -> pipe a -> orifice (A = 1e-4, Cd 0.8) -> pipe b -> reservoir 1 bar
  const double T0 = 300.0, Ageo = 1e-4, cd = 0.8;
  Network net(kAir);
  Pipe& a = net.addPipe(pipeCfg("a", 0.4, 40, 0.03, GetParam()));
  Pipe& b = net.addPipe(pipeCfg("b", 0.4, 40, 0.03, GetParam()));
  a.setUniform(3e5, T0);
  b.setUniform(1e5, T0);
  Volume& hi = net.addReservoir("hi", 3e5, T0);
  Volume& lo = net.addReservoir("lo", 1e5, T0);
  net.connect(a, End::Left, hi);
  auto& orif = net.add<PipeOrifice>("orifice", rightEnd(a), leftEnd(b),
                                    std::make_shared<ConstantArea>(Ageo, cd, cd));
  net.connect(b, End::Right, lo);
  const double M0 = net.totalMass(), E0 = net.totalEnergy();
  net.advance(0.15);
  // the upstream pipe runs at low Mach, so the orifice sees ~ the reservoir total state
  const double expect = nozzleMassFlow(kAir, cd * Ageo, 3e5, T0, 1e5);
  std::printf("[orifice %s] mdot %.6f kg/s vs choked formula %.6f (%.2e)\n", solverName(GetParam()),
              orif.massFlowAtoB(), expect, orif.massFlowAtoB() / expect - 1.0);
  EXPECT_NEAR(orif.massFlowAtoB(), expect, 5e-3 * expect);
  EXPECT_NEAR(net.totalMass() + net.reservoirMassIn(), M0, 1e-13 * M0);
  EXPECT_NEAR(net.totalEnergy() + net.reservoirEnergyIn(), E0, 1e-13 * E0);
}

// ConstPow (isentropic powers): multiplication for gamma = 1.4 exponents, exp2/log2 otherwise;
// both at round-off level against std::pow. Nozzle flow with the caller's t = pr^k is the same
// as the direct one.
TEST(ConstPow, MatchesStdPowAtRoundOff) {
  for (double gamma : {1.4, 1.33, 1.3}) {
    const double g = 0.5 * (gamma - 1.0);
    for (double e : {1.0 / g, 2.0 * gamma / (gamma - 1.0), gamma / (gamma - 1.0),
                     (gamma - 1.0) / gamma, 1.0 / (2.0 * gamma / (gamma - 1.0))}) {
      const ConstPow pw(e);
      for (double x = 0.05; x < 3.0; x += 0.0173)
        EXPECT_NEAR(pw(x), std::pow(x, e), 2e-15 * std::pow(x, e) * (1.0 + std::fabs(e * std::log2(x))))
            << "gamma " << gamma << " e " << e << " x " << x;
    }
  }
  const hbt::PerfectGas ex{1.33, 287.0};
  for (double pr = 0.3; pr < 1.0; pr += 0.01) {
    const double t = std::pow(pr, (ex.gamma - 1.0) / ex.gamma);
    EXPECT_NEAR(nozzleMassFlowT(ex, 1e-3, 2e5, 800.0, 2e5 * pr, t),
                nozzleMassFlow(ex, 1e-3, 2e5, 800.0, 2e5 * pr), 1e-14);
  }
}
