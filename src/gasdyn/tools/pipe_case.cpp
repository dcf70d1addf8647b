// pipe_case: verification runs of the gasdyn pipe-flow library.
//   pipe_case --case sod --solver fsm|tvd --cells N [--out FILE.csv]
//   pipe_case --case closed --solver fsm|tvd [--cells N_per_m] [--time S] [--implicit]
//   pipe_case --case quarterwave --solver fsm|tvd [--cells N]
//   pipe_case --case bench [--solver fsm|tvd] [--cells N] [--steps K]
// Exit codes: 0 ok, 2 usage error, 3 model error.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <string>

#include "common/errors.hpp"
#include "gasdyn/cases.hpp"

using namespace hbt::gasdyn;

namespace {

const char* kUsage =
    "usage: pipe_case --case sod|closed|quarterwave|bench [--solver fsm|tvd] [--cells N]\n"
    "                 [--out FILE.csv] [--time S] [--steps K] [--implicit]\n"
    "  sod          Sod shock tube at t = 0.6 ms, CSV x_m,rho_kg_m3,u_m_s,p_pa (--out, else stdout)\n"
    "  closed       closed network (junction + plenum), prints relative mass and energy drift\n"
    "               (--implicit: volume open ends linearised-implicit)\n"
    "  quarterwave  open-closed pipe, prints first resonance vs c/4L\n"
    "  bench        cost per cell-step of the solver(s) [ns]\n";

int usage(const std::string& msg) {
  std::cerr << "pipe_case: " << msg << "\n" << kUsage;
  return 2;
}

long parseInt(const std::string& key, const std::string& v, long lo) {
  char* end = nullptr;
  const long x = std::strtol(v.c_str(), &end, 10);
  if (v.empty() || *end != '\0' || x < lo)
    throw hbt::InputError("command line", key, "expected an integer >= " + std::to_string(lo) +
                                                   ", got '" + v + "'");
  return x;
}

double parseDouble(const std::string& key, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !(x > 0.0))
    throw hbt::InputError("command line", key, "expected a number > 0, got '" + v + "'");
  return x;
}

}  // namespace

int main(int argc, char** argv) {
  std::map<std::string, std::string> a;
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if (k == "-h" || k == "--help") {
      std::cout << kUsage;
      return 0;
    }
    if (k == "--implicit") {  // flag without a value
      a[k] = "1";
      continue;
    }
    if (k != "--case" && k != "--solver" && k != "--cells" && k != "--out" && k != "--time" &&
        k != "--steps")
      return usage("unknown argument '" + k + "'");
    if (i + 1 >= argc) return usage("missing value after " + k);
    a[k] = argv[++i];
  }
  if (!a.count("--case")) return usage("--case is required");
  const std::string cs = a["--case"];
  try {
    const bool have_solver = a.count("--solver") > 0;
    const SolverKind solver = have_solver ? parseSolver(a["--solver"]) : SolverKind::FSM;
    if (cs == "sod") {
      if (!have_solver) return usage("--solver is required for --case sod");
      const int cells = a.count("--cells") ? parseInt("--cells", a["--cells"], 2) : 100;
      const Profile r = runSod(solver, cells);
      std::ofstream file;
      if (a.count("--out")) {
        file.open(a["--out"]);
        if (!file) throw hbt::InputError(a["--out"], "--out", "cannot open for writing");
      }
      std::ostream& os = a.count("--out") ? file : std::cout;
      os.precision(10);
      os << "x_m,rho_kg_m3,u_m_s,p_pa\n";
      for (std::size_t i = 0; i < r.x.size(); ++i)
        os << r.x[i] << ',' << r.rho[i] << ',' << r.u[i] << ',' << r.p[i] << '\n';
      if (!os) throw hbt::InputError(a.count("--out") ? a["--out"] : "stdout", "--out", "write failed");
    } else if (cs == "closed") {
      if (!have_solver) return usage("--solver is required for --case closed");
      const int cpm = a.count("--cells") ? parseInt("--cells", a["--cells"], 2) : 50;
      const double t = a.count("--time") ? parseDouble("--time", a["--time"]) : 1.0;
      const bool imp = a.count("--implicit") > 0;
      const DriftResult r = runClosedNetwork(solver, cpm, t, imp);
      std::printf("closed network, %s, %d cells/m, %s volumes, %.3f s: %ld steps, cpu %.3f s\n",
                  solverName(solver), cpm, imp ? "implicit" : "explicit", t, r.steps, r.cpu_s);
      std::printf("mass   %.12e -> %.12e kg  relative drift %.3e\n", r.mass0, r.mass1,
                  r.massDrift());
      std::printf("energy %.12e -> %.12e J   relative drift %.3e\n", r.energy0, r.energy1,
                  r.energyDrift());
    } else if (cs == "quarterwave") {
      if (!have_solver) return usage("--solver is required for --case quarterwave");
      const int cells = a.count("--cells") ? parseInt("--cells", a["--cells"], 2) : 50;
      const ResonanceResult r = runQuarterWave(solver, cells);
      std::printf("quarter-wave open-closed pipe L = 1 m, %s, %d cells: f1 = %.4f Hz, c/4L = %.4f Hz, "
                  "relative error %.3e (%d zero crossings)\n",
                  solverName(solver), cells, r.f_measured, r.f_theory, r.rel_error, r.crossings);
    } else if (cs == "bench") {
      const long steps = a.count("--steps") ? parseInt("--steps", a["--steps"], 1) : 20000;
      const int cells = a.count("--cells") ? parseInt("--cells", a["--cells"], 2) : 0;
      std::printf("cells  solver  ns/cell-step\n");
      for (SolverKind s : {SolverKind::FSM, SolverKind::TVD}) {
        if (have_solver && s != solver) continue;
        for (int n : {10, 30, 100, 1000}) {
          if (cells && n != cells) continue;
          const long k = std::max(10L, steps * 100 / std::max(n, 100));
          std::printf("%5d  %6s  %8.2f\n", n, solverName(s), benchCellStep(s, n, k));
        }
        if (cells && cells != 10 && cells != 30 && cells != 100 && cells != 1000)
          std::printf("%5d  %6s  %8.2f\n", cells, solverName(s), benchCellStep(s, cells, steps));
      }
    } else {
      return usage("unknown case '" + cs + "'");
    }
  } catch (const hbt::InputError& e) {
    std::cerr << "pipe_case: " << e.what() << "\n" << kUsage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "pipe_case: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
