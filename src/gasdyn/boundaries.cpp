#include "gasdyn/boundaries.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace hbt::gasdyn {

double applyFace(const FaceState& f, const PipeEnd& end, Volume* vol) {
  const PerfectGas& g = end.pipe->gas();
  const EndFlux F = faceFlux(g, f.rho, f.u_in, f.p, end.area());
  end.setFlux(F);
  if (vol) vol->addFlow(-F.mdot_in, -F.energy_in);
  return F.mdot_in;
}

ClosedEnd::ClosedEnd(std::string name, PipeEnd end) : Boundary(std::move(name)) {
  end_ = claim(end);
}

void ClosedEnd::computeFluxes(double) {
  const EndState s = end_.state();
  const double pb = closedFacePressure(end_.pipe->gas(), s);
  end_.setFlux({0.0, pb * s.A, 0.0});
}

OpenEnd::OpenEnd(std::string name, PipeEnd end, Volume& volume)
    : Boundary(std::move(name)), vol_(volume) {
  end_ = claim(end);
  if (vol_.isReservoir()) {
    vol_.registerConnection(end_.area());
  } else {
    port_.pipe = end_.pipe;
    port_.end = end_.end;
    vol_.registerPort(&port_, end_.area());
  }
}

void OpenEnd::computeFluxes(double) {
  const PerfectGas& g = end_.pipe->gas();
  const EndState s = end_.state();
  const double p0 = vol_.p(), T0 = vol_.T();
  const FaceState f = reservoirFace(g, s, p0, T0);
  if (vol_.isReservoir()) {
    mdot_ = applyFace(f, end_, &vol_);
    return;
  }
  port_.flux = faceFlux(g, f.rho, f.u_in, f.p, s.A);  // given to the pipe end by closePorts()
  if (vol_.implicit()) {
    const FaceSensitivity d = reservoirFaceSensitivity(g, s, p0, T0, f);
    port_.dmdot_dp = d.dmdot;
    port_.dmomentum_dp = d.dmomentum;
    port_.denergy_dp = d.denergy;
    if (end_.pipe->implicitCell()) cellSensitivity(s, p0, T0, f);
  }
}

// d flux / d p_c of the end cell (isentropic change; characteristics.hpp).
void OpenEnd::cellSensitivity(const EndState& s, double p0, double T0, const FaceState& f) {
  const FaceSensitivity d = reservoirFaceCellSensitivity(end_.pipe->gas(), s, p0, T0, f);
  port_.dmdot_dpc = d.dmdot;
  port_.dmomentum_dpc = d.dmomentum;
  port_.denergy_dpc = d.denergy;
}

Valve::Valve(std::string name, Volume& volume, PipeEnd end,
             std::shared_ptr<const AreaProvider> area)
    : Boundary(std::move(name)), vol_(volume), area_(std::move(area)) {
  if (!area_) throw InputError("valve " + this->name(), "area", "no area provider");
  end_ = claim(end);
  vol_.registerConnection(end_.area());
}

void Valve::computeFluxes(double t) {
  const double ain = area_->effectiveArea(FlowDirection::Forward, t);
  const double aout = area_->effectiveArea(FlowDirection::Reverse, t);
  const FaceState f = orificeFace(end_.pipe->gas(), end_.state(), ain, aout, vol_.p(), vol_.T());
  mdot_ = applyFace(f, end_, &vol_);
}

PipeOrifice::PipeOrifice(std::string name, PipeEnd a, PipeEnd b,
                         std::shared_ptr<const AreaProvider> area)
    : Boundary(std::move(name)), area_(std::move(area)) {
  if (!area_) throw InputError("orifice " + this->name(), "area", "no area provider");
  a_ = claim(a);
  b_ = claim(b);
}

void PipeOrifice::computeFluxes(double t) {
  const PerfectGas& g = a_.pipe->gas();
  const EndState sa = a_.state(), sb = b_.state();
  const double pa = closedFacePressure(g, sa), pb = closedFacePressure(g, sb);
  const bool forward = pa >= pb;
  const PipeEnd& up = forward ? a_ : b_;
  const PipeEnd& dn = forward ? b_ : a_;
  const EndState su = forward ? sa : sb, sd = forward ? sb : sa;
  const double pd = sd.p;
  const double aeff =
      area_->effectiveArea(forward ? FlowDirection::Forward : FlowDirection::Reverse, t);
  FaceState fu = demandOutflowFace(g, su, [&](double p0, double T0) {
    return nozzleMassFlow(g, aeff, p0, T0, pd);
  });
  double mdot = -fu.mdot_in(su.A);
  if (mdot <= 0.0) {
    a_.setFlux({0.0, closedFacePressure(g, sa) * sa.A, 0.0});
    b_.setFlux({0.0, closedFacePressure(g, sb) * sb.A, 0.0});
    mdot_ = 0.0;
    return;
  }
  double pu0, Tu0;
  stagnation(g, fu, pu0, Tu0);
  FaceState fd = massFlowFace(g, sd, mdot, Tu0);
  const double md = fd.mdot_in(sd.A);
  if (md < mdot) {  // downstream end choked: both ends carry the smaller flow
    mdot = md;
    fu = massFlowFace(g, su, -mdot, 0.0);
    stagnation(g, fu, pu0, Tu0);
    fd = massFlowFace(g, sd, mdot, Tu0);
  }
  const EndFlux Fu = faceFlux(g, fu.rho, fu.u_in, fu.p, su.A);
  const EndFlux Fd = faceFlux(g, fd.rho, fd.u_in, fd.p, sd.A);
  // exact exchange: what leaves one end enters the other
  up.setFlux({Fu.mdot_in, Fu.momentum, Fu.energy_in});
  dn.setFlux({-Fu.mdot_in, Fd.momentum, -Fu.energy_in});
  mdot_ = forward ? -Fu.mdot_in : Fu.mdot_in;
}

}  // namespace hbt::gasdyn
