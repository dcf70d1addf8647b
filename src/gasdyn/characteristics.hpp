// End-face states of a pipe end from the method of characteristics (quasi-steady boundaries).
//
// Along the characteristic leaving the pipe through the end (speed c - u_in outwards), the
// Riemann variable of the end cell is carried to the face:
//   2 c_b/(gamma-1) - u_b = 2 c/(gamma-1) - u_in               (u positive into the pipe)
// and the face gas that came from the pipe keeps the end-cell entropy (p/rho^gamma). So a face
// reached by a simple wave from the end cell has, for face velocity u_b [m/s],
//   p_b = p (1 + (gamma-1)/2 (u_b - u_in)/c)^(2 gamma/(gamma-1))   [Pa].
// Inflow faces (u_b > 0) carry gas from the boundary side, whose stagnation temperature T0 is
// given: T_b = T0 - u_b^2/(2 cp). Faces never exceed sonic speed (choking); mass flows asked
// beyond the sonic limit are capped there, so callers must use the returned state's flow.
#pragma once
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "gasdyn/gas.hpp"
#include "gasdyn/pipe_end.hpp"

namespace hbt::gasdyn {

struct FaceState {
  double rho;   // [kg/m^3]
  double u_in;  // [m/s], positive into the pipe
  double p;     // [Pa]
  double mdot_in(double A) const { return rho * u_in * A; }
};

/// Pressure of the face brought to rest (u_b = 0): the reflected wall pressure [Pa].
double closedFacePressure(const PerfectGas& g, const EndState& s);
/// Closed end (u_b = 0).
FaceState closedFace(const PerfectGas& g, const EndState& s);
/// Open end to gas at rest (p0 [Pa], T0 [K]): isentropic inflow from the total state, outflow at
/// static p0; both directions may choke.
FaceState reservoirFace(const PerfectGas& g, const EndState& s, double p0, double T0);
/// Derivatives of the flux into the pipe through a reservoirFace (open end to gas at rest at p0,
/// T0) with respect to p0 at fixed T0 and fixed end-cell state: mass [kg/(s Pa)], momentum
/// [N/Pa = m^2], energy [W/Pa]. Used by the implicit volume ports (volume.hpp). Exact
/// derivatives of the face relations of each regime, f = the face reservoirFace returned:
///  * subsonic outflow (u_b < 0, face at p_b = p0 on the pipe's simple wave):
///      du_b/dp0 = 1/(rho_b c_b), drho_b/dp0 = 1/c_b^2, dp_b/dp0 = 1
///      -> dmdot/dp0 = A (c_b + u_b)/c_b^2 = A (1 - M_b)/c_b;
///  * subsonic inflow (0 < u_b < u*, isentropic from (p0, T0) meeting the simple wave
///    B + G u_b = a s, a = (p0/p)^(1/ik), s = sqrt(T_b/T0)):
///      du_b/dp0 = (a s/(ik p0)) / (G + a s u_b/(2 cp T_b)),
///      drho_b/dp0 = rho_b/p0 - rho_b u_b/c_b^2 du_b/dp0,  dp_b/dp0 = p_b/p0 - rho_b u_b du_b/dp0;
///  * choked inflow: the face scales with p0 (dmdot/dp0 = mdot/p0); choked outflow: 0.
/// Then dmdot = A (u drho + rho du), dmomentum = A (dp + u^2 drho + 2 rho u du),
/// denergy = h0 dmdot + mdot dh0 with h0 = gamma/(gamma-1) p/rho + u^2/2 (faceFlux).
struct FaceSensitivity {
  double dmdot, dmomentum, denergy;
};
FaceSensitivity reservoirFaceSensitivity(const PerfectGas& g, const EndState& s, double p0,
                                         double T0, const FaceState& f);
/// Derivatives of the same flux with respect to the end cell's pressure p [per Pa] at fixed p0,
/// T0, u_in and cell entropy (an isentropic change: drho = dp/c^2, dc/dp = c/(ik p)); used by
/// the implicit one-cell pipes (volume.hpp). With the cell's Riemann relations (Wave):
///  * subsonic outflow: p_b = p0 and rho_b = rho (p0/p)^(1/gamma) stay, du_b/dp = -1/(rho c);
///  * choked outflow (u_b = -w*, b = w*/c, w* = (c - g u)/(1 + g)):
///      du_b/dp = -c/((1 + g) ik p),  db/dp = (1/(1 + g) - b)/(ik p),
///      drho_b/dp = rho_b (1/(gamma p) + db/(g b)),  dp_b/dp = p_b (1/p + ik db/b);
///  * subsonic inflow (B + G u_b = a s, whose p-derivative at fixed u_b is 1/(ik p) since
///    a s = 1 + g (u_b - u)/c):  du_b/dp = -(1/(ik p)) / (G + a s u_b/(2 cp T_b)),
///      drho_b/dp = -rho_b u_b/c_b^2 du_b/dp,  dp_b/dp = -rho_b u_b du_b/dp;
///  * choked inflow: 0 (the face is the reservoir's).
FaceSensitivity reservoirFaceCellSensitivity(const PerfectGas& g, const EndState& s, double p0,
                                             double T0, const FaceState& f);

/// Face carrying mdot_in [kg/s] (>0 into the pipe, supply stagnation temperature T0_in [K];
/// <0 out of the pipe), capped at the sonic face.
FaceState massFlowFace(const PerfectGas& g, const EndState& s, double mdot_in, double T0_in);
/// Orifice of effective area A_in (flow into the pipe) / A_out (out of the pipe) [m^2] between gas
/// at rest (pv [Pa], Tv [K]) and the pipe end; the isentropic nozzle equation (choked or not)
/// and the pipe characteristic are solved together for the face state.
FaceState orificeFace(const PerfectGas& g, const EndState& s, double A_in, double A_out,
                      double pv, double Tv);
/// Stagnation pressure [Pa] and temperature [K] of a face state.
void stagnation(const PerfectGas& g, const FaceState& f, double& p0, double& T0);

/// Inflow demanded by a device at the face pressure: mass flow [kg/s] (decreasing in p_b) and
/// the stagnation temperature [K] of the delivered gas.
struct Supply {
  double mdot, T0;
};

namespace detail {
/// Simple-wave relations of one end cell (g = (gamma-1)/2, ik = 2 gamma/(gamma-1)). The powers
/// use ConstPow (gas.hpp): by multiplication for gamma = 1.4 (1/g = 5, ik = 7), else exp2/log2.
struct Wave {
  double g, c, u, p, rho, A, ik;
  ConstPow pow_ik, pow_ig, pow_hik;  // x^ik, x^(1/g), x^(ik/2) = x^(gamma/(gamma-1))
  Wave(const PerfectGas& gas, const EndState& s)
      : g(0.5 * (gas.gamma - 1.0)), c(std::sqrt(gas.gamma * s.p / s.rho)), u(s.u_in), p(s.p),
        rho(s.rho), A(s.A), ik(2.0 * gas.gamma / (gas.gamma - 1.0)), pow_ik(ik),
        pow_ig(1.0 / g), pow_hik(0.5 * ik) {}
  double base(double ub) const { return std::max(1.0 + g * (ub - u) / c, 1e-6); }
  double pressure(double ub) const { return p * pow_ik(base(ub)); }
  double density(double ub) const { return rho * pow_ig(base(ub)); }  // same entropy
  double wSonic() const { return std::max((c - g * u) / (1.0 + g), 0.0); }       // sonic outflow
  /// Outflow at speed wo >= 0: mass flow out of the pipe [kg/s] and the face total state (p0 [Pa],
  /// T0 [K]) with two powers: the face keeps the end-cell entropy, so T_b = T b^2
  /// (b = base(-wo)) and p0 = p_b (T0/T_b)^(gamma/(gamma-1)) = p (T0/T)^(gamma/(gamma-1)).
  /// Same values as outflow(wo) + stagnation() (3 powers).
  double outflowTotal(double wo, double cp, double R, double& p0, double& T0) const {
    const double b = base(-wo), T = p / (rho * R);
    T0 = T * b * b + 0.5 * wo * wo / cp;
    p0 = p * pow_hik(T0 / T);
    return rho * pow_ig(b) * wo * A;
  }
  double velocityAt(double pt) const {
    return u + c / g * (std::exp2(std::log2(pt / p) / ik) - 1.0);
  }
  /// Face state of the outflow at speed w >= 0 (one power: b^ik = b^(1/g) b^2).
  FaceState outflow(double w) const {
    const double b = base(-w), bg = pow_ig(b);
    return {rho * bg, -w, p * bg * b * b};
  }
  /// Face at rest (u_b = 0), same relation.
  FaceState atRest() const {
    const double b = base(0.0), bg = pow_ig(b);
    return {rho * bg, 0.0, p * bg * b * b};
  }
  FaceState inflow(const PerfectGas& gas, double ub, double T0) const {
    const double Tb = std::max(T0 - ub * ub / (2.0 * gas.cp()), 1e-6 * T0);
    const double pb = pressure(ub);
    return {pb / (gas.R * Tb), ub, pb};
  }
};

/// Supply of an inflow demand at face velocity ub: demand(p_b) or, if the demand also takes the
/// wave base b (p_b = p b^ik), demand(p_b, b) -- lets a nozzle demand get
/// (p_b/p_v)^((gamma-1)/gamma) = (p/p_v)^((gamma-1)/gamma) b^2 without a power.
template <class Demand>
Supply inflowDemand(const Demand& demand, const Wave& w, double ub) {
  const double b = w.base(ub), pb = w.p * w.pow_ik(b);
  if constexpr (std::is_invocable_v<const Demand&, double, double>)
    return demand(pb, b);
  else
    return demand(pb);
}

/// Root of f increasing on [lo, hi] with f(lo) < 0 < f(hi) (Illinois / modified regula falsi).
template <class F>
double illinois(F f, double lo, double hi, double flo, double fhi, double rtol = 1e-13) {
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
    if (hi - lo <= rtol * (std::abs(hi) + std::abs(lo)) + 1e-300) break;
  }
  return x;
}
}  // namespace detail

namespace detail {
/// Residual of an outflow face at outflow speed wo [m/s]: pipe-side mass flow minus the device's
/// demand(p0, T0) [kg/s] at the total state of the gas leaving through the face.
template <class Demand>
auto outflowResidual(const PerfectGas& gas, const Wave& w, Demand& demand) {
  return [&w, &demand, cp = gas.cp(), R = gas.R](double wo) {
    double p0, T0;
    const double m = w.outflowTotal(wo, cp, R, p0, T0);
    return m - demand(p0, T0);
  };
}
}  // namespace detail

/// Outflow face whose mass flow equals demand(p0_face, T0_face) >= 0 [kg/s] (a nozzle, a turbine
/// map...): the device sees the total state of the gas actually leaving through the face.
template <class Demand>
FaceState demandOutflowFace(const PerfectGas& gas, const EndState& s, Demand demand) {
  const detail::Wave w(gas, s);
  const auto f = detail::outflowResidual(gas, w, demand);
  const double ws = w.wSonic();
  const double f0 = f(0.0);
  if (f0 >= 0.0) return w.outflow(0.0);
  const double fhi = f(ws);
  if (fhi <= 0.0) return w.outflow(ws);  // the pipe end chokes
  return w.outflow(detail::illinois(f, 0.0, ws, f0, fhi));
}

/// Inflow face whose mass flow equals demand(p_b).mdot >= 0 at its own static pressure p_b, the
/// gas arriving with total temperature demand(p_b).T0 (an orifice from a volume, a compressor).
template <class Demand>
FaceState demandInflowFace(const PerfectGas& gas, const EndState& s, Demand demand) {
  const detail::Wave w(gas, s);
  auto face = [&](double ub) { return w.inflow(gas, ub, detail::inflowDemand(demand, w, ub).T0); };
  auto f = [&](double ub) {
    const Supply d = detail::inflowDemand(demand, w, ub);
    return w.inflow(gas, ub, d.T0).mdot_in(w.A) - d.mdot;
  };
  const double f0 = f(0.0);
  if (f0 >= 0.0) return face(0.0);
  double us = std::sqrt(2.0 * gas.gamma * gas.R * detail::inflowDemand(demand, w, 0.0).T0 / (gas.gamma + 1.0));
  us = std::sqrt(2.0 * gas.gamma * gas.R * detail::inflowDemand(demand, w, us).T0 / (gas.gamma + 1.0));
  const double fhi = f(us);
  if (fhi <= 0.0) return face(us);  // sonic face
  return face(detail::illinois(f, 0.0, us, f0, fhi));
}

// --- Warm-started variants for boundaries evaluated every time step ---------------------------
// Same equations and root semantics as demandOutflowFace / demandInflowFace (f increasing on
// [0, hi]: f(0) >= 0 -> no flow, f(hi) <= 0 -> sonic face, else the root). The face state changes
// little from one step to the next, so a secant iteration starts from the roots of the last two
// steps and the last residual slope (WarmStart, kept by the caller): x0 = 2 x_last - x_before
// (the linear extrapolation, when it lies in (0, hi); else x_last), x1 = x0 - f(x0)/slope (a
// Newton step with the last slope; without one, x0 -/+ 2 %), then secant steps until
// |dx| <= kWarmTolerance hi (a Newton step with the last slope that is already that small ends
// it). Evaluations per call over the first 300 s of the WHTC, all faces: 3.64 (4.43 from the last
// root at a 1e-7 tolerance); the cylinder valves take the most (their flows change by 10-50 % per
// step at blow-down and closing).
// Every evaluated point narrows a bracket; if the secant leaves it (or needs more than
// kWarmSecantSteps steps) the missing end values are evaluated and the Illinois solver finishes
// on that bracket (same tolerance). The residual slope of the last secant step is kept.
/// Warm start of a face solve: the last root x [m/s] (<= 0: none), the root before it
/// x_before [m/s] (<= 0: none) and the residual's slope df/dx [kg/s per m/s] (<= 0: unknown).
struct WarmStart {
  double x = 0.0, x_before = 0.0, slope = 0.0;
  void setRoot(double root) {  // the new root; the last one becomes the one before
    x_before = x;
    x = root;
  }
  /// First point of the next solve on (0, hi): the linear extrapolation of the last two roots
  /// if both exist and it lies inside, else the last root.
  double guess(double hi) const {
    if (x > 0.0 && x_before > 0.0) {
      const double g = 2.0 * x - x_before;
      if (g > 0.0 && g < hi) return g;
    }
    return x;
  }
};

namespace detail {
constexpr int kWarmSecantSteps = 8;
/// Root tolerance relative to the sonic bound: 1e-6 hi (0.3 mm/s at a 300 m/s bound, 1e-5 of a
/// 30 m/s port flow), far below the faces' discretisation error; mass is conserved exactly
/// whatever the root's error (both sides take the flux of the face state). Against 1e-7 the
/// WHTC's fuel, NOx and regression are unchanged to the printed digits (engine_1d SPEED.md).
constexpr double kWarmTolerance = 1e-6;
template <class F>
double warmRoot(F f, double hi, WarmStart& ws) {
  const double tol = kWarmTolerance * hi, guess = ws.guess(hi);
  double a = 0.0, b = hi, fa = 0.0, fb = 0.0;
  bool has_a = false, has_b = false;
  auto take = [&](double x, double fx) {
    if (fx < 0.0) a = x, fa = fx, has_a = true;
    else b = x, fb = fx, has_b = true;
  };
  if (guess > 0.0 && guess < hi) {
    double x0 = guess, f0 = f(x0);
    if (f0 == 0.0) return x0;
    take(x0, f0);
    double x1 = ws.slope > 0.0 ? x0 - f0 / ws.slope : -1.0;
    if (x1 > a && x1 < b && std::fabs(x1 - x0) <= tol) return x1;
    if (!(x1 > a && x1 < b)) x1 = f0 > 0.0 ? 0.98 * x0 : std::fmin(1.02 * x0, 0.5 * (x0 + hi));
    double f1 = f(x1);
    if (f1 == 0.0) return x1;
    take(x1, f1);
    for (int it = 0; it < kWarmSecantSteps; ++it) {
      if (f1 == f0) break;
      const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
      if (!(x2 > a && x2 < b)) break;
      ws.slope = (f1 - f0) / (x1 - x0);
      if (std::fabs(x2 - x1) <= tol) return x2;
      x0 = x1, f0 = f1, x1 = x2, f1 = f(x1);
      if (f1 == 0.0) return x1;
      take(x1, f1);
    }
  }
  if (!has_a) {  // lower end still 0
    fa = f(0.0);
    if (fa >= 0.0) return 0.0;
  }
  if (!has_b) {  // upper end still the sonic bound
    fb = f(hi);
    if (fb <= 0.0) return hi;
  }
  ws.slope = (fb - fa) / (b - a);  // chord of the final bracket
  return illinois(f, a, b, fa, fb, 0.5 * kWarmTolerance);
}
}  // namespace detail

/// demandOutflowFace with a warm start; ws.x [m/s] = outflow speed of the last call (in/out).
template <class Demand>
FaceState warmDemandOutflowFace(const PerfectGas& gas, const EndState& s, Demand demand,
                                WarmStart& ws) {
  const detail::Wave w(gas, s);
  const auto f = detail::outflowResidual(gas, w, demand);
  const double wsonic = w.wSonic();
  double x;
  if (ws.x >= wsonic && wsonic > 0.0 && f(wsonic) <= 0.0)  // still choked
    x = wsonic;
  else
    x = detail::warmRoot(f, wsonic, ws);
  ws.setRoot(x);
  return w.outflow(x);
}

/// demandInflowFace with a warm start; ws.x [m/s] = face velocity of the last call (in/out).
/// The sonic bound is taken at the supply temperature of the guess; a face that would be sonic
/// or closed is handed to demandInflowFace (its own sonic bound).
template <class Demand>
FaceState warmDemandInflowFace(const PerfectGas& gas, const EndState& s, Demand demand,
                               WarmStart& ws) {
  const detail::Wave w(gas, s);
  auto f = [&](double ub) {
    const Supply d = detail::inflowDemand(demand, w, ub);
    return w.inflow(gas, ub, d.T0).mdot_in(w.A) - d.mdot;
  };
  if (ws.x > 0.0) {
    const double T0 = detail::inflowDemand(demand, w, ws.x).T0;
    const double us = std::sqrt(2.0 * gas.gamma * gas.R * T0 / (gas.gamma + 1.0));
    if (ws.x < us) {
      const double x = detail::warmRoot(f, us, ws);
      if (x > 0.0 && x < us) {
        ws.setRoot(x);
        return w.inflow(gas, x, detail::inflowDemand(demand, w, x).T0);
      }
    }
  }
  const FaceState fs = demandInflowFace(gas, s, demand);
  ws.x_before = 0.0;  // a cold solve: no trend to extrapolate
  ws.x = fs.u_in;
  return fs;
}

/// massFlowFace for an inflow (mdot_in > 0, supply total temperature T0_in) with a warm start;
/// ws.x [m/s] = face velocity of the last call (in/out). Capped at the sonic face as there.
inline FaceState warmInflowMassFlowFace(const PerfectGas& gas, const EndState& s, double mdot_in,
                                        double T0_in, WarmStart& ws) {
  if (!(mdot_in > 0.0)) {
    ws = WarmStart{};
    return massFlowFace(gas, s, mdot_in, T0_in);
  }
  const detail::Wave w(gas, s);
  const double us = std::sqrt(2.0 * gas.gamma * gas.R * T0_in / (gas.gamma + 1.0));
  auto f = [&](double ub) { return w.inflow(gas, ub, T0_in).mdot_in(w.A) - mdot_in; };
  const double x = detail::warmRoot(f, us, ws);  // f(0) = -mdot_in < 0
  ws.setRoot(x);
  return w.inflow(gas, x, T0_in);
}

}  // namespace hbt::gasdyn
