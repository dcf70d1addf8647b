#include "gasdyn/characteristics.hpp"

#include <algorithm>
#include <cmath>

namespace hbt::gasdyn {

namespace {

struct Wave {  // simple-wave relations of one end cell
  double gm, g, c, u, p, rho, A, ik;  // g = (gamma-1)/2, ik = 2 gamma/(gamma-1)
  Wave(const PerfectGas& gas, const EndState& s)
      : gm(gas.gamma), g(0.5 * (gas.gamma - 1.0)), c(std::sqrt(gas.gamma * s.p / s.rho)),
        u(s.u_in), p(s.p), rho(s.rho), A(s.A), ik(2.0 * gas.gamma / (gas.gamma - 1.0)) {}
  double base(double ub) const { return std::max(1.0 + g * (ub - u) / c, 1e-6); }
  double pressure(double ub) const { return p * std::pow(base(ub), ik); }
  // same-entropy face (outflow): density
  double density(double ub) const { return rho * std::pow(base(ub), 1.0 / g); }
  // sonic outflow speed w* (u_b = -w*) and the velocity at which the face pressure equals pt
  double wSonic() const { return std::max((c - g * u) / (1.0 + g), 0.0); }
  double velocityAt(double pt) const { return u + c / g * (std::pow(pt / p, 1.0 / ik) - 1.0); }
};

// Illinois (modified regula falsi) on f increasing with f(lo) < 0 < f(hi).
template <class F>
double illinois(F f, double lo, double hi, double flo, double fhi) {
  int side = 0;
  double x = lo;
  for (int it = 0; it < 60; ++it) {
    x = (lo * fhi - hi * flo) / (fhi - flo);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double fx = f(x);
    if (fx == 0.0) return x;
    if (fx < 0.0) {
      lo = x, flo = fx;
      if (side == -1) fhi *= 0.5;
      side = -1;
    } else {
      hi = x, fhi = fx;
      if (side == 1) flo *= 0.5;
      side = 1;
    }
    if (hi - lo <= 1e-13 * (std::abs(hi) + std::abs(lo)) + 1e-300) break;
  }
  return x;
}

FaceState inflowFace(const PerfectGas& gas, const Wave& w, double ub, double T0) {
  const double Tb = std::max(T0 - ub * ub / (2.0 * gas.cp()), 1e-6 * T0);
  const double pb = w.pressure(ub);
  return {pb / (gas.R * Tb), ub, pb};
}
FaceState outflowFace(const Wave& w, double wout) {
  return {w.density(-wout), -wout, w.pressure(-wout)};
}

}  // namespace

double closedFacePressure(const PerfectGas& g, const EndState& s) {
  return Wave(g, s).pressure(0.0);
}

FaceState closedFace(const PerfectGas& g, const EndState& s) {
  const Wave w(g, s);
  return {w.density(0.0), 0.0, w.pressure(0.0)};
}

FaceState reservoirFace(const PerfectGas& gas, const EndState& s, double p0, double T0) {
  const Wave w(gas, s);
  // outflow at static p0?
  const double ub = w.velocityAt(p0);
  if (ub <= 0.0) {
    const double ws = w.wSonic();
    return outflowFace(w, std::min(-ub, ws));
  }
  // inflow: pipe simple wave p_b(u_b) = reservoir isentrope p0 (1 - u_b^2/(2 cp T0))^(gamma/(gamma-1));
  // raised to the power (gamma-1)/(2 gamma) both sides are linear / square-root in u_b:
  //   B + G u_b = a sqrt(1 - D u_b^2),  B = 1 - g u_in/c, G = g/c, a = (p0/p)^((gamma-1)/(2 gamma))
  const double B = 1.0 - w.g * w.u / w.c, G = w.g / w.c, D = 1.0 / (2.0 * gas.cp() * T0);
  const double a = std::pow(p0 / w.p, 1.0 / w.ik);
  const double qa = G * G + a * a * D;
  const double disc = B * B * G * G - qa * (B * B - a * a);
  double u = disc > 0.0 ? (-B * G + std::sqrt(disc)) / qa : 0.0;
  u = std::max(u, 0.0);
  const double us = std::sqrt(2.0 * gas.gamma * gas.R * T0 / (gas.gamma + 1.0));
  if (u >= us) u = us;  // choked inflow: sonic face from the total state
  const double Tb = T0 - u * u / (2.0 * gas.cp());
  const double pb = p0 * std::pow(Tb / T0, gas.gamma / (gas.gamma - 1.0));
  return {pb / (gas.R * Tb), u, pb};
}

FaceState massFlowFace(const PerfectGas& gas, const EndState& s, double mdot, double T0) {
  const Wave w(gas, s);
  if (mdot > 0.0) {
    const double us = std::sqrt(2.0 * gas.gamma * gas.R * T0 / (gas.gamma + 1.0));
    auto f = [&](double ub) { return inflowFace(gas, w, ub, T0).mdot_in(w.A) - mdot; };
    const double fhi = f(us);
    if (fhi <= 0.0) return inflowFace(gas, w, us, T0);  // capped at the sonic face
    return inflowFace(gas, w, illinois(f, 0.0, us, -mdot, fhi), T0);
  }
  if (mdot < 0.0) {
    const double ws = w.wSonic();
    auto f = [&](double wo) { return -outflowFace(w, wo).mdot_in(w.A) + mdot; };
    const double fhi = f(ws);
    if (fhi <= 0.0) return outflowFace(w, ws);
    return outflowFace(w, illinois(f, 0.0, ws, mdot, fhi));
  }
  return closedFace(gas, s);
}

void stagnation(const PerfectGas& g, const FaceState& f, double& p0, double& T0) {
  const double T = f.p / (f.rho * g.R);
  T0 = T + 0.5 * f.u_in * f.u_in / g.cp();
  p0 = f.p * std::pow(T0 / T, g.gamma / (g.gamma - 1.0));
}

FaceState orificeFace(const PerfectGas& gas, const EndState& s, double A_in, double A_out,
                      double pv, double Tv) {
  const Wave w(gas, s);
  const double pb0 = w.pressure(0.0);
  if (pv > pb0) {  // into the pipe
    if (A_in <= 0.0) return closedFace(gas, s);
    const double us = std::sqrt(2.0 * gas.gamma * gas.R * Tv / (gas.gamma + 1.0));
    const double hi = std::min(us, w.velocityAt(pv));
    auto f = [&](double ub) {
      const FaceState fs = inflowFace(gas, w, ub, Tv);
      return fs.mdot_in(w.A) - nozzleMassFlow(gas, A_in, pv, Tv, fs.p);
    };
    const double f0 = f(0.0), fhi = f(hi);
    if (fhi <= 0.0) return inflowFace(gas, w, hi, Tv);  // the pipe end chokes
    if (f0 >= 0.0) return inflowFace(gas, w, 0.0, Tv);
    return inflowFace(gas, w, illinois(f, 0.0, hi, f0, fhi), Tv);
  }
  if (pv < pb0) {  // out of the pipe
    if (A_out <= 0.0) return closedFace(gas, s);
    const double ws = w.wSonic();
    auto f = [&](double wo) {
      const FaceState fs = outflowFace(w, wo);
      double p0, T0;
      stagnation(gas, fs, p0, T0);
      return -fs.mdot_in(w.A) - nozzleMassFlow(gas, A_out, p0, T0, pv);
    };
    const double f0 = f(0.0), fhi = f(ws);
    if (fhi <= 0.0) return outflowFace(w, ws);
    if (f0 >= 0.0) return outflowFace(w, 0.0);
    return outflowFace(w, illinois(f, 0.0, ws, f0, fhi));
  }
  return closedFace(gas, s);
}

}  // namespace hbt::gasdyn
