// Engine-oil viscosity ratio (Vogel law), shared by the 1D engine's Chen-Flynn friction and the
// map engine's warm-up correction so both engines feel a cold engine the same way.
//
//   μ(T) ∝ exp(b / (T − c))                                 Vogel (1921), T [K], b, c [K]
//   φ(T_oil) = (μ(T_oil) / μ(T_ref))^n                      friction factor [-], n [-]
//
// Hydrodynamic friction scales with a power of the viscosity (n ≈ 0.25–0.5; Sandoval & Heywood,
// SAE 2003-01-0725, use n = 0.5 on the hydrodynamic terms only; applied to the whole friction
// n ≈ 0.25 gives a cold-start FMEP of about 2x the warm value at 20 °C, as measured by Shayler
// et al., SAE 2005-01-1654). T is floored at c + 60 K (below, the law leaves its range).
#pragma once
#include <algorithm>
#include <cmath>

namespace hbt {

inline double oilViscosityFactor(double T_oil_K, double T_ref_K, double vogel_b_K,
                                 double vogel_c_K, double exponent) {
  const double T = std::max(T_oil_K, vogel_c_K + 60.0);
  const double ratio = std::exp(vogel_b_K / (T - vogel_c_K) - vogel_b_K / (T_ref_K - vogel_c_K));
  return std::pow(ratio, exponent);
}

}  // namespace hbt
