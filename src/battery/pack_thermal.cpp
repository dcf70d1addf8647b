#include "battery/pack_thermal.hpp"

#include <cmath>

namespace hbt::battery {

namespace {
constexpr double kSigma = 5.670374419e-8;  // Stefan-Boltzmann constant [W/(m^2 K^4)] (CODATA 2018)

/// (e^{x} - 1)/x h written for x = l h: psi(l) = (e^{l h} - 1)/l.
double psi(double l, double h) { return std::expm1(l * h) / l; }
}  // namespace

double PackThermal::forcedOutsideH(double v) const {
  const double av = std::abs(v);
  if (av <= 0.0) return 0.0;
  const double Re = av * p_.flow_length_m / p_.air_viscosity_m2_s;
  const double pr3 = std::cbrt(p_.air_prandtl);
  const double Nu = Re <= 5e5 ? 0.664 * std::sqrt(Re) * pr3 : (0.037 * std::pow(Re, 0.8) - 871.0) * pr3;
  return Nu * p_.air_conductivity_W_mK / p_.flow_length_m;
}

PackConductances PackThermal::conductances(bool fan_on, double v, double T_amb_K) const {
  PackConductances g;
  const double Tm3 = std::pow(p_.radiation_mean_temperature_K, 3);
  g.cells_to_air_W_K = (fan_on ? p_.h_cells_fan_W_m2K : p_.h_cells_natural_W_m2K) * p_.cells_area_m2;
  g.air_to_wall_W_K =
      (fan_on ? p_.h_wall_inside_fan_W_m2K : p_.h_wall_inside_natural_W_m2K) * p_.housing_area_m2;
  g.ventilation_W_K = vent_.conductance_W_K(fan_on, T_amb_K);
  const double h_ri = 4.0 * kSigma * Tm3 / (1.0 / p_.emissivity_cells + 1.0 / p_.emissivity_housing - 1.0);
  g.radiation_in_W_K = h_ri * p_.housing_area_m2;
  // Star (air node) -> delta between cells, wall and ambient.
  const double S = g.cells_to_air_W_K + g.air_to_wall_W_K + g.ventilation_W_K;
  g.share_cells = g.cells_to_air_W_K / S;
  g.share_wall = g.air_to_wall_W_K / S;
  g.share_vent = g.ventilation_W_K / S;
  g.inner_W_K = g.cells_to_air_W_K * g.share_wall + g.radiation_in_W_K;
  g.cells_vent_W_K = g.cells_to_air_W_K * g.share_vent;
  g.wall_vent_W_K = g.air_to_wall_W_K * g.share_vent;
  const double hf = forcedOutsideH(v), hn = p_.h_outside_natural_W_m2K;
  const double h_o = std::cbrt(hn * hn * hn + hf * hf * hf);
  const double h_ro = 4.0 * p_.emissivity_housing * kSigma * Tm3;
  g.outer_W_K = p_.housing_area_m2 * (h_o + h_ro);
  const double gi = g.inner_W_K, go = g.outer_W_K + g.wall_vent_W_K;
  g.overall_W_K = ((gi + g.cells_vent_W_K) * (gi + go) - gi * gi) / (gi + go);
  return g;
}

void PackThermal::reset(double cells_T_K, double housing_T_K) {
  Tc_ = Tc0_ = cells_T_K;
  Tw_ = Tw0_ = T_air_ = housing_T_K;
  Q_amb_step_ = Q_vent_step_ = Q_cw_step_ = 0.0;
}

void PackThermal::step(double h, double Qc, double Qf, double Ta, bool fan_on, double v) {
  const PackConductances g = conductances(fan_on, v, Ta);
  const double gi = g.inner_W_K, gcv = g.cells_vent_W_K, go = g.outer_W_K + g.wall_vent_W_K;
  const double Cc = p_.cells_heat_capacity_J_K, Cw = p_.housing_heat_capacity_J_K;
  // Steady state of this step's inputs (Cramer's rule) and the deviation from it.
  const double qc = Qc + g.share_cells * Qf, qw = g.share_wall * Qf;
  const double det = (gi + gcv) * (gi + go) - gi * gi;
  const double u = (qc * (gi + go) + gi * qw) / det, w = (gi * qc + (gi + gcv) * qw) / det;
  const double Tc_inf = Ta + u, Tw_inf = Ta + w;
  const double y0c = Tc_ - Tc_inf, y0w = Tw_ - Tw_inf;
  // A = [[a11, a12], [a21, a22]], eigenvalues l1 > l2 (both < 0).
  const double a11 = -(gi + gcv) / Cc, a12 = gi / Cc, a21 = gi / Cw, a22 = -(gi + go) / Cw;
  const double m = 0.5 * (a11 + a22);
  const double d = std::sqrt(0.25 * (a11 - a22) * (a11 - a22) + a12 * a21);
  const double l1 = m + d, l2 = m - d;
  const double dh = d * h;
  const double phi12 = h * std::exp(m * h) * std::sinh(dh) / dh;
  const double e1 = std::exp(l1 * h);
  const double psi1 = psi(l1, h), psi12 = (psi1 - psi(l2, h)) / (l1 - l2);
  // (A - l1 I) y0
  const double bc = (a11 - l1) * y0c + a12 * y0w, bw = a21 * y0c + (a22 - l1) * y0w;
  const double yc = e1 * y0c + phi12 * bc, yw = e1 * y0w + phi12 * bw;     // E y0
  const double jc = psi1 * y0c + psi12 * bc, jw = psi1 * y0w + psi12 * bw;  // J y0
  Tc_ = Tc_inf + yc;
  Tw_ = Tw_inf + yw;
  const double int_u = u * h + jc, int_w = w * h + jw;  // ∫(T_c - T_amb) dt, ∫(T_w - T_amb) dt
  Q_amb_step_ = g.outer_W_K * int_w;
  Q_vent_step_ = gcv * int_u + g.wall_vent_W_K * int_w + g.share_vent * Qf * h;
  Q_cw_step_ = gi * (int_u - int_w);
  const double S = g.cells_to_air_W_K + g.air_to_wall_W_K + g.ventilation_W_K;
  T_air_ = (g.cells_to_air_W_K * Tc_ + g.air_to_wall_W_K * Tw_ + g.ventilation_W_K * Ta + Qf) / S;
}

}  // namespace hbt::battery
