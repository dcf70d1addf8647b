#include "cylinder/flame_temperature.hpp"

#include <cmath>

namespace hbt::cylinder {

double frozenEnthalpy_J_kg(const double Y[kNumSpecies], double T) {
  double h = 0.0;
  for (int s = 0; s < kNumSpecies; ++s)
    if (Y[s] != 0.0) h += Y[s] / species(Species(s)).M * hRT(Species(s), T);
  return h * kRu * T;
}

double mixtureEnthalpy_J_kg(double n, const double x[kNumSpecies], double T) {
  double h = 0.0;
  for (int s = 0; s < kNumSpecies; ++s)
    if (x[s] != 0.0) h += x[s] * hRT(Species(s), T);
  return n * h * kRu * T;
}

namespace {
// Enthalpy of the equilibrium zone with NO counted as its elements (½N2 + ½O2): NO is formed
// kinetically (zeldovich.hpp) and stays far below its equilibrium, so its formation enthalpy
// (x_NO,eq ≈ 0.5 % at 2400 K, lean: ~10 K) is not taken from the zone's energy.
double zoneEnthalpy_J_kg(double n, const double x[kNumSpecies], double T) {
  double h = mixtureEnthalpy_J_kg(n, x, T);
  h -= n * x[kNO] * (hRT(kNO, T) - 0.5 * hRT(kN2, T) - 0.5 * hRT(kO2, T)) * kRu * T;
  return h;
}

// Frozen heat capacity of a mixture of n [mol/kg] and mole fractions x [J/(kg K)].
double mixtureCp_J_kgK(double n, const double x[kNumSpecies], double T) {
  double c = 0.0;
  for (int s = 0; s < kNumSpecies; ++s)
    if (x[s] != 0.0) c += x[s] * cpR(Species(s), T);
  return n * c * kRu;
}
}  // namespace

bool DissociatedFlame::equilibriumAt(const std::array<double, 5>& b, double T, double p,
                                     Result& r) {
  ++solves_;
  if (!eq_.solve(b, T, p, r.x)) {  // cold restart once (the warm start may be far off)
    eq_.reset();
    if (!eq_.solve(b, T, p, r.x)) return false;
  }
  r.T_K = T;
  r.n_mol_kg = eq_.molesPerKg();
  return true;
}

// Stages: target enthalpy of the frozen zone; residual at T_f; one frozen-cp step; secant steps.
// A temperature is accepted (with its equilibrium) once the next correction would move it by less
// than the tolerance (kToleranceK unless given), so the cold limit costs a single equilibrium solve.
bool DissociatedFlame::solve(const std::array<double, 5>& b, const double Y[kNumSpecies],
                             double T_f, double p, Result& out, double tol) {
  solves_ = 0;
  if (!(T_f > 0.0 && p > 0.0) || !std::isfinite(T_f + p)) return false;
  const double h_target = frozenEnthalpy_J_kg(Y, T_f);
  if (!equilibriumAt(b, T_f, p, out)) return false;
  double T0 = T_f;
  double r0 = zoneEnthalpy_J_kg(out.n_mol_kg, out.x, T0) - h_target;
  double T1 = T0 - r0 / mixtureCp_J_kgK(out.n_mol_kg, out.x, T0);
  if (std::fabs(T1 - T0) < tol) return true;  // no dissociation to speak of: T_eq = T_f
  for (int it = 0; it < kMaxIterations; ++it) {
    if (!(T1 > 0.0) || !std::isfinite(T1)) return false;
    if (!equilibriumAt(b, T1, p, out)) return false;
    const double r1 = zoneEnthalpy_J_kg(out.n_mol_kg, out.x, T1) - h_target;
    if (r1 == r0) return true;  // residual at round-off level
    const double T2 = T1 - r1 * (T1 - T0) / (r1 - r0);
    if (std::fabs(T2 - T1) < tol) return true;
    T0 = T1;
    r0 = r1;
    T1 = T2;
  }
  return false;
}

}  // namespace hbt::cylinder
