#include "gasdyn/turbo_boundaries.hpp"

#include <algorithm>
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
  const double k = (g.gamma - 1.0) / g.gamma, pout = out_.p();
  power_ = 0.0;
  if (closedFacePressure(g, s) >= pout) {  // pipe -> turbine, flow from the face total state
    const FaceState f = warmDemandOutflowFace(g, s, [&](double p0, double T0) {
      return std::max(map_->massFlow(p0, T0, pout, speed_), 0.0);
    }, warm_out_);
    warm_in_ = WarmStart{};
    const EndFlux F = faceFlux(g, f.rho, f.u_in, f.p, s.A);
    end_.setFlux(F);
    mdot_ = -F.mdot_in;
    double p0f, T0f;
    stagnation(g, f, p0f, T0f);
    const double eta = mdot_ > 0.0 ? map_->efficiency(p0f, T0f, pout, speed_) : 0.0;
    const double pr = pout < p0f ? pout / p0f : 1.0;
    const double T0out = T0f * (1.0 - eta * (1.0 - ConstPow(k)(pr)));
    const double e_out = mdot_ * g.cp() * T0out;
    out_.addFlow(mdot_, e_out);
    power_ = -F.energy_in - e_out;
  } else {  // back flow from the outlet volume into the pipe (map used with roles swapped)
    const double Tout = out_.T();
    const FaceState f = warmDemandInflowFace(g, s, [&](double pb) {
      return Supply{std::max(map_->massFlow(pout, Tout, pb, speed_), 0.0), Tout};
    }, warm_in_);
    warm_out_ = WarmStart{};
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
  const double k = (g.gamma - 1.0) / g.gamma, pin = in_.p(), Tin = in_.T();
  auto supply = [&](double pb) {
    const double m = map_->massFlow(pin, Tin, pb, speed_);
    return Supply{std::max(m, 0.0), Tin * map_->temperatureRatio(pin, Tin, pb, speed_, k)};
  };
  power_ = 0.0;
  const double pb0 = closedFacePressure(g, s);
  const double m0 = map_->massFlow(pin, Tin, pb0, speed_);
  if (m0 > 0.0) {  // delivery at the face static pressure
    const FaceState f = warmDemandInflowFace(g, s, supply, warm_);
    const EndFlux F = faceFlux(g, f.rho, f.u_in, f.p, s.A);
    end_.setFlux(F);
    mdot_ = F.mdot_in;
    const double e_in = mdot_ * g.cp() * Tin;
    in_.addFlow(-mdot_, -e_in);
    power_ = F.energy_in - e_in;
  } else {  // surge back flow: gas leaves the pipe into the inlet volume
    const FaceState f = massFlowFace(g, s, m0, 0.0);
    mdot_ = applyFace(f, end_, &in_);
    warm_ = WarmStart{};
  }
}

}  // namespace hbt::gasdyn
