#include "gasdyn/volume.hpp"

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

double Volume::maxDt() const {
  if (reservoir_ || area_sum_ <= 0.0) return std::numeric_limits<double>::infinity();
  return V_ / (gas_.soundSpeed(T_) * area_sum_);
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
