#include "gasdyn/cases.hpp"

#include <chrono>
#include <cmath>
#include <ctime>

#include "common/errors.hpp"
#include "gasdyn/network.hpp"

namespace hbt::gasdyn {

SolverKind parseSolver(const std::string& s) {
  if (s == "fsm" || s == "FSM") return SolverKind::FSM;
  if (s == "tvd" || s == "TVD") return SolverKind::TVD;
  throw InputError("command line", "--solver", "expected fsm or tvd, got '" + s + "'");
}

const char* solverName(SolverKind s) { return s == SolverKind::FSM ? "fsm" : "tvd"; }

Profile runSod(SolverKind solver, int cells, double t_end) {
  Network net(PerfectGas{1.4, 287.0});
  PipeConfig c;
  c.name = "sod";
  c.length = 1.0;
  c.cells = cells;
  c.diameter_left = c.diameter_right = 0.05;
  c.solver = solver;
  Pipe& p = net.addPipe(c);
  for (int i = 0; i < cells; ++i) {
    const bool left = p.xCentre(i) < 0.5;
    p.setState(i, left ? 1.0 : 0.125, 0.0, left ? 1e5 : 1e4);
  }
  net.close(p, End::Left);
  net.close(p, End::Right);
  net.advance(t_end);
  Profile r;
  for (int i = 0; i < cells; ++i) {
    r.x.push_back(p.xCentre(i));
    r.rho.push_back(p.rho(i));
    r.u.push_back(p.u(i));
    r.p.push_back(p.p(i));
  }
  return r;
}

DriftResult runClosedNetwork(SolverKind solver, int cells_per_m, double t_end, bool implicit) {
  Network net(PerfectGas{1.4, 287.0});
  net.setImplicitVolumes(implicit);
  auto cfg = [&](const char* name, double L, double d1, double d2) {
    PipeConfig c;
    c.name = name;
    c.length = L;
    c.cells = std::max(solver == SolverKind::FSM ? 1 : 2,
                       static_cast<int>(std::lround(L * cells_per_m)));
    c.diameter_left = d1;
    c.diameter_right = d2;
    c.friction_darcy = 0.02;
    c.solver = solver;
    return c;
  };
  Pipe& a = net.addPipe(cfg("a", 1.0, 0.05, 0.05));
  Pipe& b = net.addPipe(cfg("b", 0.8, 0.04, 0.04));
  Pipe& c = net.addPipe(cfg("c", 1.2, 0.04, 0.05));
  a.setUniform(3e5, 300.0);
  b.setUniform(1e5, 300.0);
  c.setUniform(1e5, 300.0);
  const double vj = a.geometry().A_face.back() * a.dx() + b.geometry().A_face.front() * b.dx() +
                    c.geometry().A_face.front() * c.dx();
  Volume& junction = net.addVolume("junction", vj, 1e5, 300.0);
  Volume& plenum = net.addVolume("plenum", 2e-3, 1e5, 300.0);
  net.close(a, End::Left);
  net.connect(a, End::Right, junction);
  net.connect(b, End::Left, junction);
  net.connect(c, End::Left, junction);
  net.connect(b, End::Right, plenum);
  net.connect(c, End::Right, plenum);
  DriftResult r{};
  r.mass0 = net.totalMass();
  r.energy0 = net.totalEnergy();
  const auto t0 = std::chrono::steady_clock::now();
  net.advance(t_end);
  r.cpu_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.mass1 = net.totalMass();
  r.energy1 = net.totalEnergy();
  r.steps = net.steps();
  return r;
}

ResonanceResult runQuarterWave(SolverKind solver, int cells, double periods) {
  const PerfectGas gas{1.4, 287.0};
  const double L = 1.0, T = 300.0, pa = 1e5;
  Network net(gas);
  PipeConfig c;
  c.name = "quarterwave";
  c.length = L;
  c.cells = cells;
  c.diameter_left = c.diameter_right = 0.05;
  c.solver = solver;
  Pipe& p = net.addPipe(c);
  p.setUniform(1.01 * pa, T);
  Volume& amb = net.addReservoir("ambient", pa, T);
  net.connect(p, End::Left, amb);
  net.close(p, End::Right);
  ResonanceResult r{};
  r.f_theory = gas.soundSpeed(T) / (4.0 * L);
  const double t_end = periods / r.f_theory;
  std::vector<double> crossings;
  crossings.reserve(static_cast<std::size_t>(4 * periods + 8));
  double prev = p.p(cells - 1) - pa, tprev = 0.0;
  while (net.time() < t_end) {
    net.advance(std::min(p.maxDt(), t_end - net.time()));
    const double now = p.p(cells - 1) - pa, t = net.time();
    if ((prev < 0.0) != (now < 0.0) && now != prev)
      crossings.push_back(tprev + (t - tprev) * prev / (prev - now));
    prev = now;
    tprev = t;
  }
  r.crossings = static_cast<int>(crossings.size());
  if (crossings.size() >= 3) {
    // consecutive crossings are half a period apart; skip the first (start-up transient)
    const double span = crossings.back() - crossings[1];
    const double halves = static_cast<double>(crossings.size() - 2);
    r.f_measured = halves / (2.0 * span);
    r.rel_error = (r.f_measured - r.f_theory) / r.f_theory;
  }
  return r;
}

double benchCellStep(SolverKind solver, int cells, long steps) {
  Network net(PerfectGas{1.4, 287.0});
  PipeConfig c;
  c.name = "bench";
  c.length = 1.0;
  c.cells = cells;
  c.friction_darcy = 0.02;
  c.solver = solver;
  Pipe& p = net.addPipe(c);
  for (int i = 0; i < cells; ++i) p.setState(i, i < cells / 2 ? 2.3 : 1.2, 0.0, i < cells / 2 ? 2e5 : 1e5);
  net.close(p, End::Left);
  net.close(p, End::Right);
  const double dt = 0.5 * c.length / cells / 500.0;  // fixed, below the CFL limit
  net.advance(dt);                                   // warm-up
  // thread CPU time: robust against other processes sharing the cores
  auto cpu = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
  };
  const double t0 = cpu();
  for (long s = 0; s < steps; ++s) net.advance(dt);
  const double sec = cpu() - t0;
  return sec * 1e9 / (static_cast<double>(steps) * cells);
}

}  // namespace hbt::gasdyn
