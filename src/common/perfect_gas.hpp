// The perfect gas of the gas-dynamic pipes (gasdyn) and the turbocharger (turbo), SI units.
//
//   p = rho R T  [Pa],  cp = gamma R/(gamma-1),  cv = R/(gamma-1)  [J/(kg K)]
//   speed of sound  c = sqrt(gamma R T)  [m/s]
//   isentropic exponent  k = (gamma-1)/gamma  [-]  (head h_s = pi^k - 1, dh_s = cp T1 h_s)
//   critical pressure ratio  pi* = (2/(gamma+1))^(gamma/(gamma-1))  [-]
//   isentropic nozzle from upstream stagnation (p0 [Pa], T0 [K]) through the effective area
//   A [m^2] to the downstream static pressure p [Pa]:  mdot = A p0/sqrt(R T0) psi(pi),  pi = p/p0,
//     psi(pi) = sqrt(2 gamma/(gamma-1) (pi^(2/gamma) - pi^((gamma+1)/gamma)))  for pi* <= pi < 1,
//     psi(pi) = psi(pi*)  (choked)  for pi < pi*,  0 for pi >= 1 (no reverse flow);
//   choked flow function  psi(pi*) = sqrt(gamma) (2/(gamma+1))^((gamma+1)/(2(gamma-1)))  [-].
// The members use std::pow; the fast nozzle functions of the pipe boundaries (one ConstPow per
// call) are free functions in gasdyn/gas.hpp.
#pragma once
#include <algorithm>
#include <cmath>

namespace hbt {

struct PerfectGas {
  double gamma = 1.4;  // ratio of specific heats [-]
  double R = 287.0;    // specific gas constant [J/(kg K)]

  double k() const { return (gamma - 1.0) / gamma; }
  double cp() const { return gamma * R / (gamma - 1.0); }
  double cv() const { return R / (gamma - 1.0); }
  double soundSpeed(double T) const { return std::sqrt(gamma * R * T); }
  /// Critical pressure ratio p*/p0 [-].
  double criticalPressureRatio() const {
    return std::pow(2.0 / (gamma + 1.0), gamma / (gamma - 1.0));
  }
  /// Choked flow function sqrt(gamma) (2/(gamma+1))^((gamma+1)/(2(gamma-1))) [-] (closed form).
  double chokedFlowFunction() const {
    return std::sqrt(gamma) * std::pow(2.0 / (gamma + 1.0), (gamma + 1.0) / (2.0 * (gamma - 1.0)));
  }
  /// Nozzle flow function psi(pi) for pi = p_out/p0_in [-]: the choked branch evaluates the
  /// subsonic expression at pi*; 0 for pi >= 1 (no reverse flow).
  double psi(double pi) const {
    if (!(pi < 1.0)) return 0.0;
    const double pc = criticalPressureRatio();
    const double p = std::max(pi, pc);
    const double v = 2.0 * gamma / (gamma - 1.0) *
                     (std::pow(p, 2.0 / gamma) - std::pow(p, (gamma + 1.0) / gamma));
    return std::sqrt(std::max(v, 0.0));
  }
};

}  // namespace hbt
