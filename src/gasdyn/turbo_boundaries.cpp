#include "gasdyn/turbo_boundaries.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "gasdyn/boundaries.hpp"
#include "gasdyn/characteristics.hpp"

namespace hbt::gasdyn {

TurbineEntry::TurbineEntry(std::string name, PipeEnd inlet, Volume& outlet,
                           std::shared_ptr<const FlowMap> map)
    : Boundary(std::move(name)), out_(outlet), map_(std::move(map)) {
  if (!map_) throw InputError("turbine " + this->name(), "map", "no flow map");
  end_ = claim(inlet);
  out_.registerConnection(end_.area());
}

void TurbineEntry::computeFluxes(double) {
  const PerfectGas& g = end_.pipe->gas();
  const EndState s = end_.state();
  const double k = (g.gamma - 1.0) / g.gamma;
  const double p0 = closedFacePressure(g, s);
  const double T0 = s.p / (s.rho * g.R) * std::pow(p0 / s.p, k);
  const double m = map_->massFlow(p0, T0, out_.p(), speed_);
  power_ = 0.0;
  if (m >= 0.0) {
    const FaceState f = massFlowFace(g, s, -m, 0.0);
    const EndFlux F = faceFlux(g, f.rho, f.u_in, f.p, s.A);
    end_.setFlux(F);
    mdot_ = -F.mdot_in;
    double p0f, T0f;
    stagnation(g, f, p0f, T0f);
    const double eta = mdot_ > 0.0 ? map_->efficiency(p0, T0, out_.p(), speed_) : 0.0;
    const double pr = out_.p() < p0f ? out_.p() / p0f : 1.0;
    const double T0out = T0f * (1.0 - eta * (1.0 - std::pow(pr, k)));
    const double e_out = mdot_ * g.cp() * T0out;
    out_.addFlow(mdot_, e_out);
    power_ = -F.energy_in - e_out;
  } else {  // back flow from the outlet volume into the pipe
    const FaceState f = massFlowFace(g, s, -m, out_.T());
    mdot_ = -applyFace(f, end_, &out_);
  }
}

CompressorOutlet::CompressorOutlet(std::string name, Volume& inlet, PipeEnd outlet,
                                   std::shared_ptr<const FlowMap> map)
    : Boundary(std::move(name)), in_(inlet), map_(std::move(map)) {
  if (!map_) throw InputError("compressor " + this->name(), "map", "no flow map");
  end_ = claim(outlet);
  in_.registerConnection(end_.area());
}

void CompressorOutlet::computeFluxes(double) {
  const PerfectGas& g = end_.pipe->gas();
  const EndState s = end_.state();
  const double k = (g.gamma - 1.0) / g.gamma;
  const double pb = closedFacePressure(g, s);
  const double m = map_->massFlow(in_.p(), in_.T(), pb, speed_);
  power_ = 0.0;
  if (m >= 0.0) {
    const double eta = map_->efficiency(in_.p(), in_.T(), pb, speed_);
    const double T0out = in_.T() * (1.0 + (std::pow(pb / in_.p(), k) - 1.0) / eta);
    const FaceState f = massFlowFace(g, s, m, T0out);
    const EndFlux F = faceFlux(g, f.rho, f.u_in, f.p, s.A);
    end_.setFlux(F);
    mdot_ = F.mdot_in;
    const double e_in = mdot_ * g.cp() * in_.T();
    in_.addFlow(-mdot_, -e_in);
    power_ = F.energy_in - e_in;
  } else {  // surge back flow: gas leaves the pipe into the inlet volume
    const FaceState f = massFlowFace(g, s, m, 0.0);
    mdot_ = applyFace(f, end_, &in_);
  }
}

}  // namespace hbt::gasdyn
