#include "gasdyn/characteristics.hpp"

#include <algorithm>
#include <cmath>

namespace hbt::gasdyn {

namespace {
using detail::Wave;
using detail::illinois;
FaceState inflowFace(const PerfectGas& gas, const Wave& w, double ub, double T0) {
  return w.inflow(gas, ub, T0);
}
FaceState outflowFace(const Wave& w, double wout) { return w.outflow(wout); }

// Flux derivatives [kg/(s x)], [m^2 Pa/x], [W/x] from the face state's (du, drho, dp) per unit x
// of some parameter x (faceFlux: mdot = rho u A, momentum = A (p + rho u^2), energy = mdot h0).
FaceSensitivity faceFluxDerivative(const PerfectGas& gas, const FaceState& f, double A,
                                   double du, double drho, double dp) {
  const double rho = f.rho, u = f.u_in, pb = f.p;
  const double mdot = rho * u * A;
  const double dm = A * (u * drho + rho * du);
  const double k = gas.gamma / (gas.gamma - 1.0);
  const double h0 = k * pb / rho + 0.5 * u * u;
  const double dh0 = k * (dp / rho - pb * drho / (rho * rho)) + u * du;
  return {dm, A * (dp + u * u * drho + 2.0 * rho * u * du), h0 * dm + mdot * dh0};
}
}  // namespace

double closedFacePressure(const PerfectGas& g, const EndState& s) {
  return Wave(g, s).pressure(0.0);
}

FaceState closedFace(const PerfectGas& g, const EndState& s) {
  return Wave(g, s).atRest();
}

FaceState reservoirFace(const PerfectGas& gas, const EndState& s, double p0, double T0) {
  const Wave w(gas, s);
  // outflow at static p0?  (a = (p0/p)^(1/ik) = base(ub): the face is at p0 unless choked)
  const double a = std::exp2(std::log2(p0 / w.p) / w.ik);
  const double ub = w.u + w.c / w.g * (a - 1.0);
  if (ub <= 0.0) {
    const double ws = w.wSonic();
    if (-ub <= ws) {
      const double ag = w.pow_ig(a);
      return {w.rho * ag, ub, w.p * ag * a * a};
    }
    return outflowFace(w, ws);
  }
  // inflow: pipe simple wave p_b(u_b) = reservoir isentrope p0 (1 - u_b^2/(2 cp T0))^(gamma/(gamma-1));
  // raised to the power (gamma-1)/(2 gamma) both sides are linear / square-root in u_b:
  //   B + G u_b = a sqrt(1 - D u_b^2),  B = 1 - g u_in/c, G = g/c, a = (p0/p)^((gamma-1)/(2 gamma))
  const double B = 1.0 - w.g * w.u / w.c, G = w.g / w.c, D = 1.0 / (2.0 * gas.cp() * T0);
  const double qa = G * G + a * a * D;
  const double disc = B * B * G * G - qa * (B * B - a * a);
  double u = disc > 0.0 ? (-B * G + std::sqrt(disc)) / qa : 0.0;
  u = std::max(u, 0.0);
  const double us = std::sqrt(2.0 * gas.gamma * gas.R * T0 / (gas.gamma + 1.0));
  if (u >= us) u = us;  // choked inflow: sonic face from the total state
  const double Tb = T0 - u * u / (2.0 * gas.cp());
  const double pb = p0 * w.pow_hik(Tb / T0);
  return {pb / (gas.R * Tb), u, pb};
}

FaceSensitivity reservoirFaceSensitivity(const PerfectGas& gas, const EndState& s, double p0,
                                         double T0, const FaceState& f) {
  const double rho = f.rho, u = f.u_in, pb = f.p, A = s.A;
  const double c2 = gas.gamma * pb / rho, cb = std::sqrt(c2);
  double du, drho, dp;
  if (u <= 0.0) {
    if (-u >= cb * (1.0 - 1e-12)) return {0.0, 0.0, 0.0};  // choked outflow
    du = 1.0 / (rho * cb);
    drho = 1.0 / c2;
    dp = 1.0;
  } else {
    const double us = std::sqrt(2.0 * gas.gamma * gas.R * T0 / (gas.gamma + 1.0));
    if (u >= us * (1.0 - 1e-12)) {  // choked inflow: face state proportional to p0
      du = 0.0;
      drho = rho / p0;
      dp = pb / p0;
    } else {
      const double cs = std::sqrt(gas.gamma * s.p / s.rho), g = 0.5 * (gas.gamma - 1.0);
      const double ik = 2.0 * gas.gamma / (gas.gamma - 1.0);
      const double as = 1.0 - g * (s.u_in - u) / cs;  // B + G u_b = a s
      const double Tb = pb / (rho * gas.R);
      du = (as / (ik * p0)) / (g / cs + as * u / (2.0 * gas.cp() * Tb));
      drho = rho / p0 - rho * u / c2 * du;
      dp = pb / p0 - rho * u * du;
    }
  }
  return faceFluxDerivative(gas, f, A, du, drho, dp);
}

FaceSensitivity reservoirFaceCellSensitivity(const PerfectGas& gas, const EndState& s,
                                             double p0, double T0, const FaceState& f) {
  const Wave w(gas, s);
  const double rho = f.rho, u = f.u_in, pb = f.p;
  const double c2 = gas.gamma * pb / rho, cb = std::sqrt(c2);
  double du, drho, dp;
  if (u <= 0.0) {
    if (-u >= cb * (1.0 - 1e-12)) {  // choked outflow: u_b = -w*, b = w*/c
      const double b = w.wSonic() / w.c;
      if (!(b > 0.0)) return {0.0, 0.0, 0.0};
      const double db = (1.0 / (1.0 + w.g) - b) / (w.ik * w.p);
      du = -w.c / ((1.0 + w.g) * w.ik * w.p);
      drho = rho * (1.0 / (gas.gamma * w.p) + db / (w.g * b));
      dp = pb * (1.0 / w.p + w.ik * db / b);
    } else {  // subsonic outflow: the face at p0 with the cell's entropy
      du = -1.0 / (w.rho * w.c);
      drho = 0.0;
      dp = 0.0;
    }
  } else {
    const double us = std::sqrt(2.0 * gas.gamma * gas.R * T0 / (gas.gamma + 1.0));
    if (u >= us * (1.0 - 1e-12)) return {0.0, 0.0, 0.0};  // choked inflow: the reservoir's face
    const double as = 1.0 - w.g * (w.u - u) / w.c;         // B + G u_b = a s
    const double Tb = pb / (rho * gas.R);
    du = -(1.0 / (w.ik * w.p)) / (w.g / w.c + as * u / (2.0 * gas.cp() * Tb));
    drho = -rho * u / c2 * du;
    dp = -rho * u * du;
  }
  return faceFluxDerivative(gas, f, s.A, du, drho, dp);
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
  p0 = f.p * ConstPow(g.gamma / (g.gamma - 1.0))(T0 / T);
}

FaceState orificeFace(const PerfectGas& gas, const EndState& s, double A_in, double A_out,
                      double pv, double Tv) {
  const double pb0 = closedFacePressure(gas, s);
  if (pv > pb0 && A_in > 0.0)  // into the pipe
    return demandInflowFace(gas, s, [&](double pb) {
      return Supply{nozzleMassFlow(gas, A_in, pv, Tv, pb), Tv};
    });
  if (pv < pb0 && A_out > 0.0)  // out of the pipe
    return demandOutflowFace(gas, s, [&](double p0, double T0) {
      return nozzleMassFlow(gas, A_out, p0, T0, pv);
    });
  return closedFace(gas, s);
}

}  // namespace hbt::gasdyn
