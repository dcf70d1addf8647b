// Warm-started pipe-end face solvers for boundaries evaluated every time step.
//
// Same equations as gasdyn::demandOutflowFace / demandInflowFace (gasdyn/characteristics.hpp):
// the face state on the end cell's characteristic whose mass flow equals the device demand
// (nozzle, intercooler core, ...). gasdyn brackets the root on [0, sonic] and iterates to 1e-13;
// here a secant iteration starts from the previous step's face velocity (the state changes little
// per step) and stops at |dx| <= 1e-9 x the sonic bound, usually after 2-3 evaluations instead of
// 10-15. If the secant leaves (0, sonic) or has not converged after 6 evaluations, the gasdyn
// bracketing solver is used, so choked and closing faces are handled exactly as in gasdyn.
#pragma once
#include <cmath>

#include "gasdyn/characteristics.hpp"

namespace hbt::engine1d {

namespace detail {
template <class F>
bool warmSecant(F f, double hi, double& x) {
  if (!(x > 0.0 && x < hi)) return false;
  double x0 = x, f0 = f(x0);
  double x1 = f0 > 0.0 ? 0.98 * x0 : std::fmin(1.02 * x0, 0.5 * (x0 + hi));
  double f1 = f(x1);
  for (int it = 0; it < 5; ++it) {
    if (f1 == f0) return false;
    const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    if (!(x2 > 0.0 && x2 < hi)) return false;
    if (std::fabs(x2 - x1) <= 1e-9 * hi) {
      x = x2;
      return true;
    }
    x0 = x1, f0 = f1, x1 = x2, f1 = f(x1);
  }
  return false;
}
}  // namespace detail

/// Outflow face with demand(p0_face, T0_face) [kg/s]; `guess` = outflow velocity of the last call.
template <class Demand>
gasdyn::FaceState warmOutflowFace(const gasdyn::PerfectGas& gas, const gasdyn::EndState& s,
                                  Demand demand, double& guess) {
  const gasdyn::detail::Wave w(gas, s);
  auto f = [&](double wo) {
    const gasdyn::FaceState fs = w.outflow(wo);
    double p0, T0;
    gasdyn::stagnation(gas, fs, p0, T0);
    return -fs.mdot_in(w.A) - demand(p0, T0);
  };
  double x = guess;
  if (detail::warmSecant(f, w.wSonic(), x)) {
    guess = x;
    return w.outflow(x);
  }
  const gasdyn::FaceState fs = gasdyn::demandOutflowFace(gas, s, demand);
  guess = -fs.u_in;
  return fs;
}

/// Inflow face with demand(p_b) -> Supply{mdot, T0}; `guess` = face velocity of the last call.
template <class Demand>
gasdyn::FaceState warmInflowFace(const gasdyn::PerfectGas& gas, const gasdyn::EndState& s,
                                 Demand demand, double& guess) {
  const gasdyn::detail::Wave w(gas, s);
  auto f = [&](double ub) {
    const gasdyn::Supply d = demand(w.pressure(ub));
    return w.inflow(gas, ub, d.T0).mdot_in(w.A) - d.mdot;
  };
  const double T0 = demand(w.pressure(guess > 0.0 ? guess : 0.0)).T0;
  const double us = std::sqrt(2.0 * gas.gamma * gas.R * T0 / (gas.gamma + 1.0));
  double x = guess;
  if (detail::warmSecant(f, us, x)) {
    guess = x;
    return w.inflow(gas, x, demand(w.pressure(x)).T0);
  }
  const gasdyn::FaceState fs = gasdyn::demandInflowFace(gas, s, demand);
  guess = fs.u_in;
  return fs;
}

}  // namespace hbt::engine1d
