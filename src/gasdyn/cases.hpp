// Canned verification cases shared by the pipe_case tool and the gtests.
#pragma once
#include <string>
#include <vector>

#include "gasdyn/pipe_config.hpp"

namespace hbt::gasdyn {

/// Sod shock tube: 1 m pipe, constant area, closed ends, diaphragm at 0.5 m; left rho = 1 kg/m^3,
/// p = 100 kPa; right rho = 0.125 kg/m^3, p = 10 kPa; u = 0; gamma 1.4, R 287; no friction/heat.
struct Profile {
  std::vector<double> x, rho, u, p;  // cell centres [m], [kg/m^3], [m/s], [Pa]
};
Profile runSod(SolverKind solver, int cells, double t_end = 0.6e-3);

/// Closed network: pipe a (closed left end) -> junction volume <- pipes b, c -> plenum; a starts at
/// 3 bar, the rest at 1 bar (all 300 K); friction f_D = 0.02; runs t_end seconds. implicit:
/// the two volumes' open ends linearised-implicit (Network::setImplicitVolumes).
struct DriftResult {
  double mass0, mass1, energy0, energy1;  // [kg], [J]
  long steps;
  double cpu_s;
  double massDrift() const { return (mass1 - mass0) / mass0; }
  double energyDrift() const { return (energy1 - energy0) / energy0; }
};
DriftResult runClosedNetwork(SolverKind solver, int cells_per_m, double t_end = 1.0,
                             bool implicit = false);

/// Open-closed pipe (L = 1 m, D = 50 mm, open end to 1 bar / 300 K, gas initially at 1.01 bar):
/// first resonance from the zero crossings of the closed-end pressure oscillation.
struct ResonanceResult {
  double f_measured, f_theory, rel_error;  // [Hz], [Hz] = c/(4L), [-]
  int crossings;
};
ResonanceResult runQuarterWave(SolverKind solver, int cells, double periods = 12.0);

/// Cost of one solver: a closed pipe with a pressure step advanced `steps` network steps; thread
/// CPU time per cell-step [ns] (includes the per-step boundary and network overhead).
double benchCellStep(SolverKind solver, int cells, long steps);

SolverKind parseSolver(const std::string& s);  // "fsm" | "tvd"; throws InputError
const char* solverName(SolverKind s);

}  // namespace hbt::gasdyn
