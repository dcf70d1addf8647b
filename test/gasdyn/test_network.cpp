// Network-level checks for both solvers: mass and energy conservation to round-off in a closed
// network (junction + plenum), relaxation towards the uniform equilibrium pressure, gas at rest
// staying at rest in a tapered pipe (well-balanced area source), the divergence guard and the
// input validation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "gasdyn/cases.hpp"
#include "gasdyn/characteristics.hpp"
#include "gasdyn/network.hpp"

using namespace hbt::gasdyn;

class BothSolvers : public ::testing::TestWithParam<SolverKind> {};
INSTANTIATE_TEST_SUITE_P(Solvers, BothSolvers, ::testing::Values(SolverKind::FSM, SolverKind::TVD),
                         [](const auto& i) { return std::string(solverName(i.param)); });

TEST_P(BothSolvers, ClosedNetworkConservesMassAndEnergy) {
  const DriftResult r = runClosedNetwork(GetParam(), 50, 1.0);
  std::printf("[closed %s] %ld steps, cpu %.3f s, mass drift %.3e, energy drift %.3e\n",
              solverName(GetParam()), r.steps, r.cpu_s, r.massDrift(), r.energyDrift());
  EXPECT_LT(std::abs(r.massDrift()), 1e-12);
  EXPECT_LT(std::abs(r.energyDrift()), 1e-12);
  EXPECT_GT(r.steps, 10000);
}

TEST_P(BothSolvers, ClosedNetworkImplicitVolumesConserveMassAndEnergy) {
  const DriftResult r = runClosedNetwork(GetParam(), 50, 1.0, true);
  std::printf("[closed implicit %s] %ld steps, mass drift %.3e, energy drift %.3e\n",
              solverName(GetParam()), r.steps, r.massDrift(), r.energyDrift());
  EXPECT_LT(std::abs(r.massDrift()), 1e-12);
  EXPECT_LT(std::abs(r.energyDrift()), 1e-12);
}

TEST(Network, OneCellFsmPipesConserveAndRelax) {
  // 1-cell FSM pipes (both ports are boundary faces), implicit volumes: conservative to
  // round-off and the closed network still relaxes to the uniform rest pressure.
  const DriftResult r = runClosedNetwork(SolverKind::FSM, 1, 1.0, true);
  EXPECT_LT(std::abs(r.massDrift()), 1e-12);
  EXPECT_LT(std::abs(r.energyDrift()), 1e-12);
  Network net(hbt::PerfectGas{1.4, 287.0});
  net.setImplicitVolumes(true);
  PipeConfig c;
  c.name = "a", c.length = 0.3, c.cells = 1, c.friction_darcy = 0.05;
  c.diameter_left = c.diameter_right = 0.04;
  Pipe& a = net.addPipe(c);
  c.name = "b";
  Pipe& b = net.addPipe(c);
  a.setUniform(2e5, 300.0);
  b.setUniform(1e5, 300.0);
  // tiny junction: its explicit limit V/(c sum A) would be ~ 1/10 of the pipes' CFL step
  Volume& j = net.addVolume("j", 0.1 * a.geometry().V_cell[0], 1.5e5, 300.0);
  net.close(a, End::Left);
  net.connect(a, End::Right, j);
  net.connect(b, End::Left, j);
  net.close(b, End::Right);
  std::string who;
  net.stableDt(&who);
  EXPECT_TRUE(who == "a" || who == "b") << who;  // the implicit volume does not set the step
  const double V = j.volume() + a.geometry().V_cell[0] + b.geometry().V_cell[0];
  const double peq = 0.4 * net.totalEnergy() / V;
  net.advance(2.0);
  EXPECT_NEAR(j.p(), peq, 0.01 * peq);
  EXPECT_NEAR(a.p(0), peq, 0.01 * peq);
  EXPECT_NEAR(b.p(0), peq, 0.01 * peq);
}

namespace {
// Closed network of the engine's kind: three one-cell runners (closed far ends) on a plenum, a
// 6-cell duct from the plenum to a second volume with one more runner; unequal pressures and
// temperatures, implicit volume ports.
struct RunnerNetwork {
  Network net{hbt::PerfectGas{1.4, 287.0}};
  std::vector<Pipe*> runners;
  Pipe* duct = nullptr;
  Volume* plenum = nullptr;
  Volume* box = nullptr;
  RunnerNetwork(bool implicit_cells, double subcycle_cfl) {
    net.setImplicitVolumes(true);
    net.setImplicitOneCellPipes(implicit_cells);
    net.setSubcycledPipes(subcycle_cfl);
    PipeConfig c;
    c.length = 0.25, c.cells = 1, c.friction_darcy = 0.03;
    c.diameter_left = c.diameter_right = 0.045;
    const double p[] = {2.0e5, 1.0e5, 1.5e5, 0.9e5}, T[] = {300.0, 350.0, 400.0, 320.0};
    for (int k = 0; k < 4; ++k) {
      c.name = "runner_" + std::to_string(k + 1);
      runners.push_back(&net.addPipe(c));
      runners.back()->setUniform(p[k], T[k]);
    }
    c.name = "duct", c.length = 2.0, c.cells = 6, c.diameter_left = c.diameter_right = 0.075;
    duct = &net.addPipe(c);
    duct->setUniform(1.2e5, 300.0);
    plenum = &net.addVolume("plenum", 5e-3, 1.1e5, 310.0);
    box = &net.addVolume("box", 1e-3, 1.0e5, 300.0);
    for (int k = 0; k < 3; ++k) {
      net.close(*runners[k], End::Left);
      net.connect(*runners[k], End::Right, *plenum);
    }
    net.connect(*duct, End::Left, *plenum);
    net.connect(*duct, End::Right, *box);
    net.connect(*runners[3], End::Left, *box);
    net.close(*runners[3], End::Right);
  }
  double volume() const {
    double V = plenum->volume() + box->volume();
    for (const auto& q : net.pipes())
      for (double v : q->geometry().V_cell) V += v;
    return V;
  }
};
}  // namespace

TEST(Network, ImplicitOneCellPipesAndSubcycledPipesConserveAndRelax) {
  // The runners' acoustics implicit with their volume, the duct sub-cycled: the step is the
  // duct's end-cell coupling limit (1.5 dx/(|u| + c)), ~2x the runners' explicit CFL step;
  // mass and energy stay conserved to round-off and the network relaxes to p_eq.
  RunnerNetwork n(true, 1.5);
  const double m0 = n.net.totalMass(), e0 = n.net.totalEnergy();
  const double peq = 0.4 * e0 / n.volume();
  std::string who;
  const double dt = n.net.stableDt(&who);
  const Pipe& r = *n.runners[0];
  const double runner_cfl_dt = r.config().cfl * r.dx() / (std::abs(r.u(0)) + std::sqrt(1.4 * r.p(0) / r.rho(0)));
  std::printf("[implicit cells] step %.3f ms set by %s; runner's explicit CFL step %.3f ms\n",
              1e3 * dt, who.c_str(), 1e3 * runner_cfl_dt);
  EXPECT_EQ(who, "duct");
  EXPECT_GT(dt, 1.5 * runner_cfl_dt);
  n.net.advance(2.0);
  const double dm = n.net.totalMass() / m0 - 1.0, de = n.net.totalEnergy() / e0 - 1.0;
  std::printf("[implicit cells] %ld network steps, duct %ld solver steps, mass drift %.2e, energy "
              "drift %.2e, p_eq %.1f Pa, plenum %.1f, runner_1 %.1f, runner_4 %.1f\n",
              n.net.steps(), n.duct->steps(), dm, de, peq, n.plenum->p(), r.p(0),
              n.runners[3]->p(0));
  EXPECT_LT(std::abs(dm), 1e-12);
  EXPECT_LT(std::abs(de), 1e-12);
  EXPECT_GT(n.duct->steps(), n.net.steps());  // sub-cycled: its own CFL steps
  EXPECT_EQ(r.steps(), n.net.steps());
  for (const Pipe* q : n.runners) EXPECT_NEAR(q->p(0), peq, 0.01 * peq) << q->name();
  EXPECT_NEAR(n.plenum->p(), peq, 0.01 * peq);
  EXPECT_NEAR(n.box->p(), peq, 0.01 * peq);
}

TEST(Network, ImplicitOneCellPipeDecaysAtAnyStep) {
  // A one-cell runner (closed far end) on a plenum, nothing else. Explicit, its acoustic CFL
  // step splits every 5 ms into >= 7 steps; with its cell implicit only the transport limit
  // remains and every 5 ms is one network step. The pressure deviation (the cell's filling mode
  // with its explicit momentum) then decays by >= 2x every 5 steps down to round-off, and the
  // network keeps its mass and energy.
  auto build = [](Network& net, bool implicit_cell) {
    net.setImplicitVolumes(true);
    net.setImplicitOneCellPipes(implicit_cell);
    PipeConfig c;
    c.name = "runner", c.length = 0.25, c.cells = 1, c.friction_darcy = 0.03;
    c.diameter_left = c.diameter_right = 0.045;
    Pipe& r = net.addPipe(c);
    r.setUniform(1.6e5, 330.0);
    Volume& pl = net.addVolume("plenum", 2e-3, 1.0e5, 300.0);
    net.close(r, End::Left);
    net.connect(r, End::Right, pl);
    return &r;
  };
  Network expl(hbt::PerfectGas{1.4, 287.0});
  build(expl, false);
  expl.advance(5e-3);
  EXPECT_GE(expl.steps(), 7);
  Network net(hbt::PerfectGas{1.4, 287.0});
  const Pipe& r = *build(net, true);
  const double m0 = net.totalMass(), e0 = net.totalEnergy();
  const double peq = 0.4 * e0 / (net.volumes()[0]->volume() + r.geometry().V_cell[0]);
  const double dev0 = std::abs(r.p(0) - peq);
  double window_prev = dev0, window = 0.0;
  for (int k = 1; k <= 100; ++k) {
    const long before = net.steps();
    net.advance(5e-3);
    EXPECT_EQ(net.steps() - before, 1) << "step " << k;
    window = std::max(window, std::abs(r.p(0) - peq));
    if (k % 5 == 0) {
      if (window_prev > 1e-9 * peq) {
        EXPECT_LT(window, 0.5 * window_prev) << "steps to " << k;
      }
      window_prev = window;
      window = 0.0;
    }
  }
  std::printf("[implicit cell alone] explicit: %ld steps per 5 ms; implicit: deviation %.1f -> "
              "%.2e Pa after 0.5 s in 5 ms steps\n", expl.steps(), dev0, window_prev);
  EXPECT_LT(window_prev, 1e-9 * peq);
  EXPECT_LT(std::abs(net.totalMass() / m0 - 1.0), 1e-12);
  EXPECT_LT(std::abs(net.totalEnergy() / e0 - 1.0), 1e-12);
}

namespace {
// Central differences (step h) of the flux into the pipe through the face face(x) at x.
template <class Face>
FaceSensitivity centralDifference(const hbt::PerfectGas& g, double A, Face face, double x, double h) {
  const FaceState fp = face(x + h), fm = face(x - h);
  const EndFlux Fp = faceFlux(g, fp.rho, fp.u_in, fp.p, A), Fm = faceFlux(g, fm.rho, fm.u_in, fm.p, A);
  return {(Fp.mdot_in - Fm.mdot_in) / (2 * h), (Fp.momentum - Fm.momentum) / (2 * h),
          (Fp.energy_in - Fm.energy_in) / (2 * h)};
}
void expectNearSensitivity(const FaceSensitivity& d, const FaceSensitivity& fd, const std::string& what) {
  std::printf("[%s] dmdot %.4e (fd %.4e), dmom %.4e (fd %.4e), denergy %.4e (fd %.4e)\n",
              what.c_str(), d.dmdot, fd.dmdot, d.dmomentum, fd.dmomentum, d.denergy, fd.denergy);
  EXPECT_NEAR(d.dmdot, fd.dmdot, 1e-5 * (std::abs(fd.dmdot) + 1e-12)) << what;
  EXPECT_NEAR(d.dmomentum, fd.dmomentum, 1e-5 * (std::abs(fd.dmomentum) + 1e-9)) << what;
  EXPECT_NEAR(d.denergy, fd.denergy, 1e-5 * (std::abs(fd.denergy) + 1e-6)) << what;
}
// The four regimes of reservoirFace at a 1.6 bar end cell (p0 [Pa], u_in [m/s]).
struct FaceCase { double p0, u; const char* name; };
constexpr FaceCase kFaceCases[] = {{1.4e5, 30.0, "subsonic outflow"}, {0.3e5, 0.0, "choked outflow"},
                                   {1.9e5, -20.0, "subsonic inflow"}, {4.0e6, 0.0, "choked inflow"}};
}  // namespace

TEST(Network, ReservoirFaceSensitivityMatchesFiniteDifference) {
  // d(flux into the pipe)/d p0 of reservoirFace against central differences, in the four
  // regimes: subsonic / choked outflow, subsonic / choked inflow.
  const hbt::PerfectGas g{1.35, 290.0};
  for (const FaceCase& cs : kFaceCases) {
    EndState s{1.5, cs.u, 1.6e5, 2e-3};
    const double T0 = 420.0;
    const FaceState f = reservoirFace(g, s, cs.p0, T0);
    const FaceSensitivity fd = centralDifference(
        g, s.A, [&](double p0) { return reservoirFace(g, s, p0, T0); }, cs.p0, 1e-6 * cs.p0);
    expectNearSensitivity(reservoirFaceSensitivity(g, s, cs.p0, T0, f), fd,
                          std::string("sensitivity ") + cs.name);
  }
}

TEST(Network, ReservoirFaceCellSensitivityMatchesFiniteDifference) {
  // d(flux into the pipe)/d p of the end cell (isentropic change of the cell, u and entropy
  // fixed) against central differences, in the four regimes, for air and exhaust gas.
  for (const hbt::PerfectGas g : {hbt::PerfectGas{1.4, 287.0}, hbt::PerfectGas{1.33, 290.0}}) {
    for (const FaceCase& cs : kFaceCases) {
      const EndState s{1.5, cs.u, 1.6e5, 2e-3};
      const double T0 = 420.0;
      auto face = [&](double p) {  // the cell at p, same u and entropy: rho ~ p^(1/gamma)
        EndState e = s;
        e.p = p;
        e.rho = s.rho * std::pow(p / s.p, 1.0 / g.gamma);
        return reservoirFace(g, e, cs.p0, T0);
      };
      const FaceState f = reservoirFace(g, s, cs.p0, T0);
      const FaceSensitivity d = reservoirFaceCellSensitivity(g, s, cs.p0, T0, f);
      char what[64];
      std::snprintf(what, sizeof what, "cell sensitivity gamma %.2f %s", g.gamma, cs.name);
      expectNearSensitivity(d, centralDifference(g, s.A, face, s.p, 1e-6 * s.p), what);
      // physical signs: a higher cell pressure pushes more gas out, lets less in; a choked
      // inflow face is the reservoir's sonic state, whatever the cell
      const double u_sonic = std::sqrt(2.0 * g.gamma * g.R * T0 / (g.gamma + 1.0));
      if (std::string(cs.name) == "choked inflow") {
        EXPECT_NEAR(f.u_in, u_sonic, 1e-9 * u_sonic);
        EXPECT_EQ(d.dmdot, 0.0);
      } else {
        EXPECT_LT(d.dmdot, 0.0) << cs.name;
      }
    }
  }
}

TEST_P(BothSolvers, ClosedNetworkRelaxesToEquilibrium) {
  // After the pressure step, friction damps the waves; the final state must approach the uniform
  // rest state with p_eq = (gamma-1) E_total / V_total (energy all internal).
  Network net(hbt::PerfectGas{1.4, 287.0});
  auto cfg = [&](const char* n, double L, double d) {
    PipeConfig c;
    c.name = n, c.length = L, c.cells = static_cast<int>(L * 40), c.friction_darcy = 0.05;
    c.diameter_left = c.diameter_right = d, c.solver = GetParam();
    return c;
  };
  Pipe& a = net.addPipe(cfg("a", 1.0, 0.05));
  Pipe& b = net.addPipe(cfg("b", 0.5, 0.03));
  Pipe& c = net.addPipe(cfg("c", 0.7, 0.03));
  a.setUniform(2e5, 300.0);
  b.setUniform(1e5, 300.0);
  c.setUniform(1e5, 300.0);
  Volume& j = net.addVolume("j", 5e-5, 1e5, 300.0);
  Volume& pl = net.addVolume("plenum", 1e-3, 1e5, 300.0);
  net.close(a, End::Left);
  net.connect(a, End::Right, j);
  net.connect(b, End::Left, j);
  net.connect(c, End::Left, j);
  net.connect(b, End::Right, pl);
  net.connect(c, End::Right, pl);
  double V = j.volume() + pl.volume();
  for (const auto& p : net.pipes())
    for (double v : p->geometry().V_cell) V += v;
  const double peq = 0.4 * net.totalEnergy() / V;
  net.advance(3.0);
  std::printf("[equilibrium %s] p_eq %.1f Pa, plenum %.1f, junction %.1f, a(0) %.1f\n",
              solverName(GetParam()), peq, pl.p(), j.p(), a.p(0));
  EXPECT_NEAR(pl.p(), peq, 0.01 * peq);
  EXPECT_NEAR(j.p(), peq, 0.01 * peq);
  EXPECT_NEAR(a.p(0), peq, 0.01 * peq);
}

TEST_P(BothSolvers, TaperedPipeAtRestStaysAtRest) {
  Network net;
  PipeConfig c;
  c.name = "taper", c.length = 0.6, c.cells = 30, c.solver = GetParam();
  c.diameter_left = 0.02, c.diameter_right = 0.08, c.friction_darcy = 0.03;
  Pipe& p = net.addPipe(c);
  p.setUniform(1.3e5, 350.0);
  net.close(p, End::Left);
  net.close(p, End::Right);
  net.advance(0.02);
  for (int i = 0; i < p.cells(); ++i) {
    EXPECT_LT(std::abs(p.u(i)), 1e-9) << "cell " << i;
    EXPECT_NEAR(p.p(i), 1.3e5, 1e-6) << "cell " << i;
  }
}

TEST_P(BothSolvers, DivergenceNamesPipeCellAndQuantity) {
  Network net;
  PipeConfig c;
  c.name = "exh_manifold_1", c.length = 1.0, c.cells = 20, c.solver = GetParam();
  Pipe& p = net.addPipe(c);
  for (int i = 0; i < 20; ++i) p.setState(i, i < 10 ? 5.0 : 0.1, 0.0, i < 10 ? 5e5 : 1e4);
  net.close(p, End::Left);
  net.close(p, End::Right);
  try {
    p.step(50.0 * p.maxDt());  // far beyond the CFL limit
    FAIL() << "no ModelDivergence";
  } catch (const hbt::ModelDivergence& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find("pipe exh_manifold_1 cell "), std::string::npos) << w;
    EXPECT_TRUE(w.find("density") != std::string::npos || w.find("pressure") != std::string::npos)
        << w;
  }
}

TEST(Network, TimeStepFloorThrowsNamingTheLimitingPipe) {
  Network net;
  PipeConfig c;
  c.name = "short_runner", c.length = 0.01, c.cells = 10;
  Pipe& p = net.addPipe(c);
  p.setUniform(1e5, 300.0);
  net.close(p, End::Left);
  net.close(p, End::Right);
  net.setDtFloor(1e-5);  // the CFL step here is ~2.6e-6 s
  try {
    net.advance(1e-3);
    FAIL() << "no ModelDivergence";
  } catch (const hbt::ModelDivergence& e) {
    EXPECT_NE(std::string(e.what()).find("short_runner"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("time step"), std::string::npos) << e.what();
  }
}

TEST(Network, InputValidation) {
  Network net;
  PipeConfig c;
  c.name = "p1";
  Pipe& p = net.addPipe(c);
  EXPECT_THROW(net.addPipe(c), hbt::InputError);  // duplicate name
  net.close(p, End::Left);
  EXPECT_THROW(net.close(p, End::Left), hbt::InputError);  // end taken twice
  EXPECT_THROW(net.advance(1e-3), hbt::InputError);        // right end unconnected
  PipeConfig bad;
  bad.name = "bad", bad.cells = 0;  // FSM: >= 1 cell
  EXPECT_THROW(net.addPipe(bad), hbt::InputError);
  bad.cells = 1, bad.solver = SolverKind::TVD;  // TVD: >= 2 cells
  EXPECT_THROW(net.addPipe(bad), hbt::InputError);
  bad.solver = SolverKind::FSM;
  bad.cells = 10, bad.length = -1.0;
  EXPECT_THROW(net.addPipe(bad), hbt::InputError);
  EXPECT_THROW(net.addVolume("v", 0.0, 1e5, 300.0), hbt::InputError);
}

TEST_P(BothSolvers, WallHeatTransferRelaxesExponentially) {
  // closed pipe at rest, uniform gas at 500 K, wall 300 K, h = 200 W/(m^2 K):
  // rho cv dT/dt = h (4/D) (T_w - T)  ->  T = T_w + (T0 - T_w) exp(-4 h t/(D rho cv))
  Network net;
  PipeConfig c;
  c.name = "cooler", c.length = 0.5, c.cells = 20, c.solver = GetParam();
  c.diameter_left = c.diameter_right = 0.02;
  c.heat = WallHeat::GivenCoefficient, c.h_wall = 200.0, c.T_wall = 300.0;
  Pipe& p = net.addPipe(c);
  p.setUniform(2e5, 500.0);
  net.close(p, End::Left);
  net.close(p, End::Right);
  const double rho = p.rho(0), tau = 0.02 * rho * net.gas().cv() / (4.0 * 200.0);
  net.advance(tau);
  const double expect = 300.0 + 200.0 * std::exp(-1.0);
  std::printf("[heat %s] T(tau) %.3f K vs %.3f K\n", solverName(GetParam()), p.T(10), expect);
  EXPECT_NEAR(p.T(10), expect, 0.005 * expect);
  EXPECT_LT(std::abs(p.u(10)), 1e-6);
}
