// Perfect-gas properties and the isentropic nozzle (orifice) relations shared by all boundaries.
//
//   p = rho R T  [Pa],  cp = gamma R/(gamma-1), cv = R/(gamma-1)  [J/(kg K)],  c = sqrt(gamma R T) [m/s]
//   Stagnation state of a moving gas: T0 = T + u^2/(2 cp),  p0 = p (T0/T)^(gamma/(gamma-1)).
//   Nozzle mass flow [kg/s] from upstream stagnation (p0 [Pa], T0 [K]) through the effective
//   (= discharge coefficient x geometric) area A [m^2] to the downstream static pressure p [Pa]:
//     pr  = max(p/p0, pr*),  pr* = (2/(gamma+1))^(gamma/(gamma-1))   (choked below pr*)
//     mdot = A p0 / sqrt(R T0) * sqrt( 2 gamma/(gamma-1) (pr^(2/gamma) - pr^((gamma+1)/gamma)) )
//   Choked: mdot* = A p0/sqrt(R T0) sqrt(gamma) (2/(gamma+1))^((gamma+1)/(2(gamma-1))).
#pragma once
#include <cmath>

namespace hbt::gasdyn {

struct PerfectGas {
  double gamma = 1.4;  // ratio of specific heats [-]
  double R = 287.0;    // specific gas constant [J/(kg K)]

  double cp() const { return gamma * R / (gamma - 1.0); }
  double cv() const { return R / (gamma - 1.0); }
  double soundSpeed(double T) const { return std::sqrt(gamma * R * T); }
  double criticalPressureRatio() const {
    return std::pow(2.0 / (gamma + 1.0), gamma / (gamma - 1.0));
  }
  /// Choked flow function sqrt(gamma) (2/(gamma+1))^((gamma+1)/(2(gamma-1))) [-].
  double chokedFlowFunction() const {
    return std::sqrt(gamma) * std::pow(2.0 / (gamma + 1.0), (gamma + 1.0) / (2.0 * (gamma - 1.0)));
  }
};

/// Dimensionless nozzle flow function psi(p/p0) (choked value below the critical ratio) [-].
/// One pow() in the subsonic case: with t = pr^((gamma-1)/gamma),
///   pr^(2/gamma) - pr^((gamma+1)/gamma) = pr^2/t^2 (1 - t),  and pr <= pr*  <=>  t <= 2/(gamma+1).
inline double nozzleFlowFunction(const PerfectGas& g, double pr) {
  if (pr >= 1.0) return 0.0;
  if (!(pr > 0.0)) return g.chokedFlowFunction();
  const double t = std::pow(pr, (g.gamma - 1.0) / g.gamma);
  if (t <= 2.0 / (g.gamma + 1.0)) return g.chokedFlowFunction();
  const double v = pr * pr / (t * t) * (1.0 - t);
  return std::sqrt(2.0 * g.gamma / (g.gamma - 1.0) * (v > 0.0 ? v : 0.0));
}

/// Isentropic nozzle mass flow [kg/s], >= 0; zero if p >= p0 or area <= 0.
inline double nozzleMassFlow(const PerfectGas& g, double area, double p0, double T0, double p) {
  if (area <= 0.0 || p >= p0) return 0.0;
  return area * p0 / std::sqrt(g.R * T0) * nozzleFlowFunction(g, p / p0);
}

}  // namespace hbt::gasdyn
