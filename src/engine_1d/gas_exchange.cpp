#include "engine_1d/gas_exchange.hpp"

#include <cmath>

#include "common/table1d.hpp"
#include "common/units.hpp"
#include "engine_1d/fast_faces.hpp"
#include "gasdyn/boundaries.hpp"
#include "gasdyn/characteristics.hpp"

namespace hbt::engine_1d {
namespace {
constexpr double kStep = 0.25;  // deg
}  // namespace

CrankValveArea::CrankValveArea(const cylinder::Cylinder& c, const ValveSpec& v, double open_deg,
                               double close_deg, bool normal_is_forward)
    : cyl_(c), v_(v), open_(open_deg) {
  duration_ = std::fmod(close_deg - open_deg + 1440.0, 720.0);
  const Table1D cd_n(v.ld, v.cd_normal, "valve", "cd_normal");
  const Table1D cd_b(v.ld, v.cd_back, "valve", "cd_back");
  const int n = static_cast<int>(std::ceil(duration_ / kStep)) + 2;  // nodes beyond Delta: 0
  tab_.resize(2 * static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double L = lift(open_ + i * kStep);
    const double curtain = v.count * units::kPi * v.diameter_m * L;
    const double an = curtain * cd_n(L / v.diameter_m), ab = curtain * cd_b(L / v.diameter_m);
    tab_[2 * i] = normal_is_forward ? an : ab;
    tab_[2 * i + 1] = normal_is_forward ? ab : an;
  }
}

double CrankValveArea::lift(double th) const {
  const double phi = std::fmod(th - open_ + 1440.0, 720.0);
  if (phi >= duration_) return 0.0;
  const double s = std::sin(units::kPi * phi / duration_);
  return v_.max_lift_m * std::pow(s > 0.0 ? s : 0.0, v_.shape_exponent);
}

void CrankValveArea::areas(double th, double& fwd, double& rev) const {
  double phi = th - open_;  // th in [-360, 370) (incl. a lead), open_ in [-360, 720)
  if (phi < 0.0) phi += 720.0;
  if (phi < 0.0) phi += 720.0;
  if (phi >= 720.0) phi -= 720.0;
  if (!(phi < duration_)) {
    fwd = rev = 0.0;
    return;
  }
  const double x = phi / kStep;
  const int i = static_cast<int>(x);
  const double f = x - i;
  const double* a = &tab_[2 * static_cast<std::size_t>(i)];
  fwd = (1.0 - f) * a[0] + f * a[2];
  rev = (1.0 - f) * a[1] + f * a[3];
}

double CrankValveArea::areaAt(double th, bool forward) const {
  double f, r;
  areas(cylinder::wrapCycleDeg(th), f, r);
  return forward ? f : r;
}

void CrankValveArea::areasNow(double& forward, double& reverse) const {
  areas(cyl_.crankAngle_deg() + lead_, forward, reverse);
}

double CrankValveArea::effectiveArea(gasdyn::FlowDirection dir, double) const {
  return areaAt(cyl_.crankAngle_deg(), dir == gasdyn::FlowDirection::Forward);
}

CylinderValve::CylinderValve(std::string name, gasdyn::Volume& v, gasdyn::PipeEnd end,
                             std::shared_ptr<const CrankValveArea> area)
    : Boundary(std::move(name)), vol_(v), area_(std::move(area)) {
  end_ = claim(end);
  vol_.registerConnection(end_.area());
}

void CylinderValve::computeFluxes(double t) {
  using namespace gasdyn;
  const PerfectGas& g = end_.pipe->gas();
  const EndState s = end_.state();
  double a_in, a_out;
  area_->areasNow(a_in, a_out);
  const double pv = vol_.p(), Tv = vol_.T();
  FaceState f;
  if (a_in <= 0.0 && a_out <= 0.0) {
    f = closedFace(g, s);
    warm_in_ = warm_out_ = gasdyn::WarmStart{};
  } else {
    const double pb0 = closedFacePressure(g, s);
    // Nozzle t = (p_down/p0_up)^((gamma-1)/gamma) without a power per iteration (isentropes):
    //  inflow  (face p_b = p b^ik):              (p_b/p_v)^k  = (p/p_v)^k b^2;
    //  outflow (face p0 = p (T0/T)^(1/k)):       (p_v/p0)^k   = (p_v/p)^k T/T0.
    const ConstPow pow_k((g.gamma - 1.0) / g.gamma);
    if (pv > pb0 && a_in > 0.0) {
      const double tp = pow_k(s.p / pv);
      f = warmInflowFace(g, s, [&](double pb, double b) {
        return Supply{nozzleMassFlowT(g, a_in, pv, Tv, pb, tp * b * b), Tv};
      }, warm_in_);
      warm_out_ = WarmStart{};
    } else if (pv < pb0 && a_out > 0.0) {
      const double tv = pow_k(pv / s.p), T = s.p / (s.rho * g.R);
      f = warmOutflowFace(g, s, [&](double p0, double T0) {
        return nozzleMassFlowT(g, a_out, p0, T0, pv, tv * T / T0);
      }, warm_out_);
      warm_in_ = WarmStart{};
    } else {
      f = closedFace(g, s);
    }
  }
  mdot_ = applyFace(f, end_, &vol_);
}

ChargeAirCoolerLink::ChargeAirCoolerLink(std::string name, gasdyn::PipeEnd hot,
                                         gasdyn::PipeEnd cold, const turbo::Intercooler& cooler)
    : Boundary(std::move(name)), ic_(cooler) {
  a_ = claim(hot);
  b_ = claim(cold);
}

void ChargeAirCoolerLink::computeFluxes(double) {
  using namespace gasdyn;
  const PerfectGas& g = a_.pipe->gas();
  const EndState sa = a_.state(), sb = b_.state();
  const double pa = closedFacePressure(g, sa), pb = closedFacePressure(g, sb);
  const bool forward = pa >= pb;
  const PipeEnd& up = forward ? a_ : b_;
  const PipeEnd& dn = forward ? b_ : a_;
  const EndState su = forward ? sa : sb, sd = forward ? sb : sa;
  const double pd = sd.p;
  if (forward != warm_forward_) {  // direction change: cold start
    warm_up_ = warm_down_ = WarmStart{};
    warm_forward_ = forward;
  }
  FaceState fu = warmOutflowFace(g, su, [&](double p0, double T0) {
    return ic_.massFlowForDrop(p0 - pd, T0, p0);
  }, warm_up_);
  double mdot = -fu.mdot_in(su.A);
  heat_W_ = 0.0;
  if (!(mdot > 0.0)) {
    a_.setFlux({0.0, pa * sa.A, 0.0});
    b_.setFlux({0.0, pb * sb.A, 0.0});
    mdot_ = 0.0;
    return;
  }
  double p0u, T0u;
  stagnation(g, fu, p0u, T0u);
  double T0d = ic_.outletTemperature(T0u, T_cool_, mdot);
  FaceState fd = warmInflowMassFlowFace(g, sd, mdot, T0d, warm_down_);
  const double md = fd.mdot_in(sd.A);
  if (md < mdot) {  // downstream face choked
    mdot = md;
    fu = massFlowFace(g, su, -mdot, 0.0);
    stagnation(g, fu, p0u, T0u);
    T0d = ic_.outletTemperature(T0u, T_cool_, mdot);
    fd = massFlowFace(g, sd, mdot, T0d);
  }
  const EndFlux Fu = faceFlux(g, fu.rho, fu.u_in, fu.p, su.A);
  const EndFlux Fd = faceFlux(g, fd.rho, fd.u_in, fd.p, sd.A);
  const double e_out = mdot * g.cp() * T0d;
  up.setFlux(Fu);
  dn.setFlux({mdot, Fd.momentum, e_out});
  heat_W_ = -Fu.energy_in - e_out;
  T0_out_ = T0d;
  mdot_ = forward ? mdot : -mdot;
}

}  // namespace hbt::engine_1d
