#include "aftertreatment/brick.hpp"

#include <cmath>

#include "aftertreatment/gas.hpp"
#include "aftertreatment/lumped_wall.hpp"
#include "common/errors.hpp"

namespace hbt::aftertreatment {

namespace {
// Outer film resistance [m^2 K/W] where no external heat transfer acts: the can loses ~nothing.
constexpr double kNoFilmResistance_m2K_W = 1e12;
}  // namespace

Brick::Brick(std::string name, const BrickParams& p, const HeatTransferParams& h, bool wall_flow)
    : name_(std::move(name)), p_(p), h_(h), wall_flow_(wall_flow), n_(p.slices) {
  A_ = 0.25 * units::kPi * p.diameter_m * p.diameter_m;
  V_ = A_ * p.length_m;
  pitch_ = 0.0254 / std::sqrt(p.cpsi);
  w_ = p.wall_thickness_mil * 25.4e-6;
  d_ = pitch_ - w_;
  ofa_ = (d_ / pitch_) * (d_ / pitch_);
  gsa_ = 4.0 * d_ / (pitch_ * pitch_);
  const double C = V_ * (1.0 - ofa_) * p.wall_density_kg_m3 * p.wall_cp_J_kgK +
                   V_ * p.washcoat_g_L * p.washcoat_cp_J_kgK  // g/L == kg/m^3
                   + p.can_mass_kg * p.can_cp_J_kgK;
  C_slice_ = C / n_;
  A_can_slice_ = units::kPi * (p.diameter_m + 2.0 * h.insulation_thickness_m) * p.length_m / n_ *
                 h.can_length_factor;
  T_.assign(n_, 298.15);
}

void Brick::setUniformTemperature(double T_K) { T_.assign(n_, T_K); }

double Brick::meanT() const {
  double s = 0.0;
  for (double t : T_) s += t;
  return s / n_;
}

double Brick::externalH(double T_wall_K, double T_amb_K, double v) const {
  return outerFilmH(T_wall_K, T_amb_K, h_.underbody_air_factor * v,
                    p_.diameter_m + 2.0 * h_.insulation_thickness_m, h_.h_natural_W_m2K,
                    h_.can_emissivity);
}

double Brick::canUA(double T_wall_K, double T_amb_K, double v) const {
  const double he = externalH(T_wall_K, T_amb_K, v);
  const double R = h_.insulation_thickness_m / h_.insulation_k_W_mK + (he > 0.0 ? 1.0 / he : kNoFilmResistance_m2K_W);
  return A_can_slice_ / R;
}

double Brick::sliceHA(double T_K) const {
  return h_.nusselt * conductivity(T_K) / d_ * gsa_ * V_ / n_;
}

double Brick::stepThermal(double dt, double mdot, double cp, double Tg, const double* qr,
                          double T_amb, double v, BrickEnergy& e) {
  const double mcp = mdot * cp;
  for (int i = 0; i < n_; ++i) {
    const double T0 = T_[i];
    const double G = mcp > 0.0 ? -mcp * std::expm1(-sliceHA(Tg) / mcp) : 0.0;
    const double UA = canUA(T0, T_amb, v);
    const double Q = qr ? qr[i] : 0.0;
    const WallStep w = exactWallStep(T0, C_slice_, G, UA, Q, Tg, T_amb, dt);
    const double T1 = w.T1, Tbar = w.Tbar, C = C_slice_;
    if (!std::isfinite(T1) || T1 <= 0.0)
      throw ModelDivergence("aftertreatment brick " + name_ + " slice " + std::to_string(i),
                            "wall temperature", "non-physical value " + std::to_string(T1));
    T_[i] = T1;
    const double q_gas = G * (Tg - Tbar);
    e.gas_to_wall_J += q_gas * dt;
    e.can_loss_J += UA * (Tbar - T_amb) * dt;
    e.reaction_J += Q * dt;
    e.stored_J += C * (T1 - T0);
    if (mcp > 0.0) Tg -= q_gas / mcp;
    else Tg = Tbar;
  }
  return Tg;
}

PressureDrop Brick::pressureDrop(double Vdot, double T, double rho, const DpfFlowParams* dpf,
                                 double Kc) const {
  PressureDrop dp;
  if (Vdot <= 0.0) return dp;
  const double mu = viscosity(T);
  const double L = p_.length_m;
  if (!wall_flow_ || !dpf) {
    const double u = Vdot / (A_ * ofa_);
    dp.laminar_Pa = 0.5 * 56.91 * mu * u * L / (d_ * d_);
    dp.minor_Pa = (Kc + (1.0 - ofa_) * (1.0 - ofa_)) * 0.5 * rho * u * u;
    return dp;
  }
  const double N_in = A_ / (2.0 * pitch_ * pitch_);
  const double A_f = 4.0 * d_ * L * N_in;
  const double u_w = Vdot / A_f;
  const double u0 = Vdot / (N_in * d_ * d_);
  const double m_soot = dpf->soot_load_g_L * V_;  // g/L == kg/m^3
  const double w_soot = m_soot / (dpf->soot_cake_density_kg_m3 * A_f);
  dp.laminar_Pa = 28.45 * mu * u0 * L / (d_ * d_) + mu * u_w * w_ / dpf->wall_permeability_m2 +
                  mu * u_w * w_soot / dpf->soot_permeability_m2;
  const double open_in = 0.5 * ofa_;
  dp.minor_Pa = (Kc + (1.0 - open_in) * (1.0 - open_in)) * 0.5 * rho * u0 * u0;
  return dp;
}

}  // namespace hbt::aftertreatment
