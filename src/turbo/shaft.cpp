#include "turbo/shaft.hpp"

#include <algorithm>
#include <cmath>

#include "common/units.hpp"

namespace hbt::turbo {

TurboShaft::TurboShaft(const ShaftParams& p, double omega0) : p_(p) {
  kf_ = p.friction_ref_power_W / (p.friction_ref_speed_rad_s * p.friction_ref_speed_rad_s);
  setOmega(omega0);
}

void TurboShaft::setOmega(double w) { omega_ = std::isfinite(w) ? std::max(w, 0.0) : 0.0; }

double TurboShaft::speedRpm() const { return units::radpsToRpm(omega_); }

double TurboShaft::netPower(double pt, double pc) const {
  return p_.eta_mech * pt - pc - kf_ * omega_ * omega_;
}

double TurboShaft::derivative(double pt, double pc) const {
  return netPower(pt, pc) / (p_.inertia_kg_m2 * std::max(omega_, p_.omega_min_rad_s));
}

void TurboShaft::step(double dt, double pt, double pc) {
  if (!(dt > 0.0)) return;
  const double J = p_.inertia_kg_m2;
  const double F = p_.eta_mech * pt - pc;
  const double E = 0.5 * J * omega_ * omega_;
  const double a = 2.0 * kf_ / J;
  double En;
  if (a * dt > 1e-12) {
    const double e = std::exp(-a * dt);
    En = E * e + F / a * (1.0 - e);
  } else {
    En = E + F * dt;
  }
  setOmega(std::sqrt(2.0 * std::max(En, 0.0) / J));
}

}  // namespace hbt::turbo
