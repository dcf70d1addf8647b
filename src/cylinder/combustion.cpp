#include "cylinder/combustion.hpp"

#include "cylinder/thermo.hpp"
#include "common/units.hpp"

#include <algorithm>
#include <cmath>

namespace hbt::cylinder {

double Wiebe::x(double th) const {
  const double t = (th - theta_i_deg) / duration_deg;
  if (t <= 0.0) return 0.0;
  if (t >= 1.0) return 1.0;
  return (1.0 - std::exp(-a * std::pow(t, m + 1.0))) / (1.0 - std::exp(-a));
}

double Wiebe::rate(double th) const {
  const double t = (th - theta_i_deg) / duration_deg;
  if (t <= 0.0 || t > 1.0) return 0.0;
  const double tm = std::pow(t, m);
  return a * (m + 1.0) * tm * std::exp(-a * tm * t) / ((1.0 - std::exp(-a)) * duration_deg);
}

double Wiebe::inverse(double xx) const {
  if (xx <= 0.0) return theta_i_deg;
  if (xx >= 1.0) return theta_i_deg + duration_deg;
  const double t = std::pow(-std::log(1.0 - xx * (1.0 - std::exp(-a))) / a, 1.0 / (m + 1.0));
  return theta_i_deg + duration_deg * t;
}

double DoubleWiebe::end_deg() const {
  return std::max(premixed.theta_i_deg + premixed.duration_deg,
                  diffusive.theta_i_deg + diffusive.duration_deg);
}

double hardenbergHaseDelayDeg(double p_Pa, double T_K, double cm, double cetane) {
  const double p_bar = std::max(p_Pa * 1e-5, 13.0);  // correlation singular at 12.4 bar
  const double EA = 618840.0 / (cetane + 25.0);
  const double arg = EA * (1.0 / (kRu * T_K) - 1.0 / 17190.0) *
                     std::pow(21.2 / (p_bar - 12.4), 0.63);
  return (0.36 + 0.22 * cm) * std::exp(arg);
}

double watsonPremixedFraction(double phi, double tau_ms) {
  if (tau_ms <= 0.0) return 0.0;
  const double b = 1.0 - 0.926 * std::pow(std::max(phi, 1e-6), 0.37) / std::pow(tau_ms, 0.26);
  return std::clamp(b, 0.0, 1.0);
}

double Nozzle::massRate(double p_rail, double p_cyl) const {
  const double dp = p_rail - p_cyl;
  if (dp <= 0.0) return 0.0;
  const double A = holes * 0.25 * units::kPi * hole_diameter_m * hole_diameter_m;
  return discharge_coeff * A * std::sqrt(2.0 * fuel_density_kg_m3 * dp);
}

}  // namespace hbt::cylinder
