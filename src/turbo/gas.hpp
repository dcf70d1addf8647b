// Perfect-gas helpers shared by the turbocharger models (SI units throughout).
//
//   isentropic exponent          k = (γ − 1)/γ                          [-]
//   specific heat                c_p = γ R/(γ − 1)                      [J/(kg·K)]
//   isentropic head coefficient  h_s = Π^k − 1  (Δh_s = c_p T_1 h_s)    [-]
//   nozzle flow function (isentropic nozzle, upstream total p0,T0, downstream static p):
//     ṁ = A p0/√(R T0) · ψ(π),  π = p/p0,
//     ψ(π) = √(2γ/(γ−1) · (π^(2/γ) − π^((γ+1)/γ)))  for π ≥ π* = (2/(γ+1))^(γ/(γ−1)),
//     ψ(π) = ψ(π*) (choked)                          for π < π*.
#pragma once
#include <algorithm>
#include <cmath>

namespace hbt::turbo {

struct Gas {
  double gamma = 1.4;    // ratio of specific heats [-]
  double R = 287.0;      // specific gas constant [J/(kg·K)]
  double k() const { return (gamma - 1.0) / gamma; }
  double cp() const { return gamma * R / (gamma - 1.0); }
  /// Critical pressure ratio p*/p0 [-].
  double criticalPressureRatio() const {
    return std::pow(2.0 / (gamma + 1.0), gamma / (gamma - 1.0));
  }
  /// Nozzle flow function ψ(π) for π = p_out/p0_in; 0 for π ≥ 1 (no reverse flow).
  double psi(double pi) const {
    if (!(pi < 1.0)) return 0.0;
    const double pc = criticalPressureRatio();
    const double p = std::max(pi, pc);
    const double v = 2.0 * gamma / (gamma - 1.0) *
                     (std::pow(p, 2.0 / gamma) - std::pow(p, (gamma + 1.0) / gamma));
    return std::sqrt(std::max(v, 0.0));
  }
};

}  // namespace hbt::turbo
