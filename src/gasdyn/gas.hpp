// The isentropic nozzle (orifice) relations shared by all boundaries, on hbt::PerfectGas
// (common/perfect_gas.hpp: p = rho R T, cp, cv, c, pi*, the choked flow function), and ConstPow.
//
//   Stagnation state of a moving gas: T0 = T + u^2/(2 cp),  p0 = p (T0/T)^(gamma/(gamma-1)).
//   Nozzle mass flow [kg/s] from upstream stagnation (p0 [Pa], T0 [K]) through the effective
//   (= discharge coefficient x geometric) area A [m^2] to the downstream static pressure p [Pa]:
//     pr  = max(p/p0, pr*),  pr* = (2/(gamma+1))^(gamma/(gamma-1))   (choked below pr*)
//     mdot = A p0 / sqrt(R T0) * sqrt( 2 gamma/(gamma-1) (pr^(2/gamma) - pr^((gamma+1)/gamma)) )
//   Choked: mdot* = A p0/sqrt(R T0) sqrt(gamma) (2/(gamma+1))^((gamma+1)/(2(gamma-1))).
// One power (ConstPow) per subsonic call, where PerfectGas::psi takes three std::pow.
#pragma once
#include <cmath>

#include "common/perfect_gas.hpp"

namespace hbt::gasdyn {

/// x^e [-] for x > 0 and an exponent e that is constant for a gas (isentropic relations):
///  * e a multiple of 1/2 up to 8 (gamma = 1.4: 2/(gamma-1) = 5, 2 gamma/(gamma-1) = 7,
///    gamma/(gamma-1) = 3.5): x^n by multiplication (x sqrt(x) for the half), exact to round-off;
///  * otherwise exp2(e log2 x): relative error ~1e-16 |e log2 x| (round-off level), about 1.5x
///    cheaper than std::pow (no exact-rounding path). These relations are ~1/3 of the 1D
///    engine's instructions, hence the care.
class ConstPow {
 public:
  explicit ConstPow(double e) : e_(e) {
    const double twice = 2.0 * e;
    const long r = static_cast<long>(twice + 0.5);
    if (twice > -0.25 && std::fabs(twice - static_cast<double>(r)) < 1e-9 && r <= 16)
      half_steps_ = static_cast<int>(r);
  }
  double exponent() const { return e_; }
  double operator()(double x) const {
    if (half_steps_ < 0) return std::exp2(e_ * std::log2(x));
    double y = 1.0;
    for (int i = 0; i < half_steps_ / 2; ++i) y *= x;
    return (half_steps_ & 1) ? y * std::sqrt(x) : y;
  }

 private:
  double e_;
  int half_steps_ = -1;  // 2e if e is a multiple of 1/2 in [0, 8], else -1
};

/// Nozzle flow function from pr = p/p0 < 1 and t = pr^((gamma-1)/gamma) given by the caller
/// (e.g. known without a pow() along an isentrope): with
///   pr^(2/gamma) - pr^((gamma+1)/gamma) = pr^2/t^2 (1 - t),  and pr <= pr*  <=>  t <= 2/(gamma+1).
inline double nozzleFlowFunctionT(const PerfectGas& g, double pr, double t) {
  if (pr >= 1.0) return 0.0;
  if (!(pr > 0.0) || t <= 2.0 / (g.gamma + 1.0)) return g.chokedFlowFunction();
  const double v = pr * pr / (t * t) * (1.0 - t);
  return std::sqrt(2.0 * g.gamma / (g.gamma - 1.0) * (v > 0.0 ? v : 0.0));
}

/// Dimensionless nozzle flow function psi(p/p0) (choked value below the critical ratio) [-].
/// One power (ConstPow) in the subsonic case: t = pr^((gamma-1)/gamma).
inline double nozzleFlowFunction(const PerfectGas& g, double pr) {
  if (pr >= 1.0) return 0.0;
  if (!(pr > 0.0)) return g.chokedFlowFunction();
  return nozzleFlowFunctionT(g, pr, ConstPow((g.gamma - 1.0) / g.gamma)(pr));
}

/// Isentropic nozzle mass flow [kg/s], >= 0; zero if p >= p0 or area <= 0.
inline double nozzleMassFlow(const PerfectGas& g, double area, double p0, double T0, double p) {
  if (area <= 0.0 || p >= p0) return 0.0;
  return area * p0 / std::sqrt(g.R * T0) * nozzleFlowFunction(g, p / p0);
}

/// nozzleMassFlow with t = (p/p0)^((gamma-1)/gamma) supplied by the caller [kg/s].
inline double nozzleMassFlowT(const PerfectGas& g, double area, double p0, double T0, double p,
                              double t) {
  if (area <= 0.0 || p >= p0) return 0.0;
  return area * p0 / std::sqrt(g.R * T0) * nozzleFlowFunctionT(g, p / p0, t);
}

}  // namespace hbt::gasdyn
