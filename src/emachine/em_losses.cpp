#include "emachine/em_losses.hpp"

#include <algorithm>
#include <cmath>

namespace hbt::emachine {

namespace {
constexpr double kT20_K = 293.15;
}  // namespace

double LossModel::phaseResistance(double T_w, double f) const {
  const double x = f / e_.ac_doubling_frequency_Hz;
  return e_.phase_resistance_20C_ohm * (1.0 + e_.resistance_tempco_per_K * (T_w - kT20_K)) *
         (1.0 + x * x);
}

double LossModel::magnetFluxFactor(double T_m) const {
  constexpr double kMinFluxFactor = 0.05;
  return std::max(kMinFluxFactor,
                  1.0 + e_.magnet_remanence_tempco_per_K * (T_m - e_.torque_constant_ref_K));
}

double LossModel::voltageLimitSpeed(double V, double T_m) const {
  const double ke = torqueConstant(T_m) / 3.0;
  return std::max(0.0, V) * e_.phase_voltage_per_dc_volt / ke;
}

LossBreakdown LossModel::evaluate(double T, double w, double V, double T_w, double T_m) const {
  LossBreakdown b;
  w = std::max(0.0, w);
  const double beta = magnetFluxFactor(T_m), kt = beta * e_.torque_constant_Nm_A;
  b.magnet_flux_factor = beta;
  const double Vph = std::max(0.0, V) * e_.phase_voltage_per_dc_volt;
  const double wv = voltageLimitSpeed(V, T_m);
  // Field weakening: flux ratio and d-current (no-load form).
  double ratio = 1.0;
  if (w > 0.0) ratio = (wv < w) ? wv / w : 1.0;
  b.flux_ratio = ratio;
  b.i_q_A = std::abs(T) / kt;
  b.i_d_A = -beta * e_.characteristic_current_A * (1.0 - ratio);
  double I = std::hypot(b.i_q_A, b.i_d_A);
  const double P_air = std::abs(T * w);
  if (P_air > 0.0) I = Vph > 0.0 ? std::max(I, P_air / (3.0 * Vph)) : I;
  b.i_A = I;
  b.frequency_Hz = e_.pole_pairs * w / (2.0 * units::kPi);
  b.copper_W = 3.0 * I * I * phaseResistance(T_w, b.frequency_Hz);
  const double f = b.frequency_Hz, B = beta * fe_.peak_flux_density_T * ratio;
  b.iron_W = fe_.build_factor * fe_.stator_iron_mass_kg *
             (fe_.hysteresis_coeff * f * B * B + fe_.eddy_coeff * f * f * B * B);
  b.rotor_W = fe_.rotor_loss_fraction * b.iron_W;
  b.bearing_W = m_.bearing_torque_Nm * w;
  const double r = w / m_.windage_ref_speed_rad_s;
  b.windage_W = m_.windage_ref_W * r * r * r;
  const bool active = w > 0.0 || T != 0.0;
  b.inverter_conduction_W = 3.0 * I * I * inv_.conduction_resistance_ohm;
  const double I_mean = 2.0 * std::sqrt(2.0) / units::kPi * I;
  b.inverter_switching_W = 3.0 * inv_.switching_frequency_Hz * inv_.switching_energy_ref_J *
                           (std::max(0.0, V) / inv_.switching_ref_voltage_V) *
                           (I_mean / inv_.switching_ref_current_A);
  b.inverter_fixed_W = active ? inv_.fixed_loss_W : 0.0;
  return b;
}

}  // namespace hbt::emachine
