#include "gasdyn/volume.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.hpp"

namespace hbt::gasdyn {

Volume::Volume(const PerfectGas& gas, std::string name, double volume_m3, double p, double T)
    : gas_(gas), name_(std::move(name)), V_(volume_m3), p_(p), T_(T) {
  if (!(volume_m3 > 0.0)) throw InputError("volume " + name_, "volume", "must be > 0 m^3");
  if (!(p > 0.0)) throw InputError("volume " + name_, "p", "must be > 0 Pa");
  if (!(T > 0.0)) throw InputError("volume " + name_, "T", "must be > 0 K");
  m_ = p * V_ / (gas_.R * T);
  U_ = m_ * gas_.cv() * T;
}

Volume Volume::reservoir(const PerfectGas& gas, std::string name, double p, double T) {
  Volume v;
  v.gas_ = gas;
  v.name_ = std::move(name);
  v.reservoir_ = true;
  v.setReservoirState(p, T);
  return v;
}

void Volume::setReservoirState(double p, double T) {
  if (!reservoir_) throw InputError("volume " + name_, "state", "only a reservoir has a set state");
  if (!(p > 0.0)) throw InputError("volume " + name_, "p", "must be > 0 Pa");
  if (!(T > 0.0)) throw InputError("volume " + name_, "T", "must be > 0 K");
  p_ = p;
  T_ = T;
}

void Volume::registerPort(VolumePort* port, double area) {
  if (reservoir_) throw InputError("volume " + name_, "port", "a reservoir has no ports");
  ports_.push_back(port);
  port_area_ += area;
}

double Volume::maxDt() const {
  const double a = implicit_ ? area_sum_ : area_sum_ + port_area_;
  if (reservoir_ || a <= 0.0) return std::numeric_limits<double>::infinity();
  return V_ / (gas_.soundSpeed(T_) * a);
}

void Volume::closePorts(double dt) {
  double dp = 0.0;
  if (implicit_ && !ports_.empty()) {
    double S = edot_, D = 0.0;
    for (VolumePort* q : ports_) {
      S -= q->flux.energy_in;
      if (q->pipe->implicitCell()) {  // header "Implicit one-cell pipes": d >= 0, e <= 0
        const PipeGeometry& geo = q->pipe->geometry();
        const End other = q->end == End::Left ? End::Right : End::Left;
        const double C = geo.V_cell[0] / ((q->pipe->gas().gamma - 1.0) * dt);
        const double d = std::max(q->denergy_dp, 0.0), e = std::min(q->denergy_dpc, 0.0);
        q->cell_alpha = (q->flux.energy_in + q->pipe->endFlux(other).energy_in) / (C - e);
        q->cell_beta = d / (C - e);
        S -= e * q->cell_alpha;
        D += d + e * q->cell_beta;
      } else {
        D += q->denergy_dp;
      }
    }
    const double k = (gas_.gamma - 1.0) * dt / V_;
    dp = k * S / (1.0 + k * std::max(D, 0.0));
  }
  for (VolumePort* q : ports_) {
    EndFlux& F = q->flux;
    F.mdot_in += q->dmdot_dp * dp;
    F.momentum += q->dmomentum_dp * dp;
    F.energy_in += q->denergy_dp * dp;
    if (implicit_ && q->pipe->implicitCell()) {
      const double dpc = q->cell_alpha + q->cell_beta * dp;
      F.mdot_in += q->dmdot_dpc * dpc;
      F.momentum += q->dmomentum_dpc * dpc;
      F.energy_in += q->denergy_dpc * dpc;
    }
    q->pipe->setEndFlux(q->end, F);
    addFlow(-F.mdot_in, -F.energy_in);
  }
}

void Volume::advance(double dt) {
  cum_m_ += dt * mdot_;
  cum_e_ += dt * edot_;
  if (!reservoir_) {
    m_ += dt * mdot_;
    U_ += dt * edot_;
    T_ = U_ / (m_ * gas_.cv());
    p_ = m_ * gas_.R * T_ / V_;
    if (!(m_ > 0.0) || !std::isfinite(m_))
      throw ModelDivergence("volume " + name_, "mass", "non-physical value " + std::to_string(m_));
    if (!(T_ > 0.0) || !std::isfinite(T_))
      throw ModelDivergence("volume " + name_, "temperature",
                            "non-physical value " + std::to_string(T_));
  }
  mdot_ = edot_ = 0.0;
}

}  // namespace hbt::gasdyn
