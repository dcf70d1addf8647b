#include "emachine/emachine_model.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace hbt::emachine {

namespace {
double clamp01(double x) { return std::min(1.0, std::max(0.0, x)); }
/// 1 below a, 0 above b, linear between.
double ramp(double T, double a, double b) { return clamp01((b - T) / (b - a)); }
std::string resolve(const std::string& base, const std::string& path) {
  if (base.empty() || path.empty() || path[0] == '/') return path;
  return base + "/" + path;
}
void requireFinite(double v, const char* name) {
  if (!std::isfinite(v)) throw ModelDivergence("emachine", std::string("input ") + name, "not finite");
}
}  // namespace

EMachineModel::EMachineModel(const EMachineParams& p, const std::string& file, const std::string& base_dir)
    : p_(p), file_(file) {
  p_.validate(file);
  const auto& e = p_.envelope;
  env_ = TorqueEnvelope(resolve(base_dir, p_.data.vemp_file), e.nominal_voltage_V,
                        e.max_effective_voltage_V, e.undervoltage_zero_V, e.undervoltage_full_V,
                        e.continuous_power_W, e.continuous_torque_Nm);
  loss_ = LossModel(p_.electrical, p_.iron, p_.mechanical, p_.inverter);
  const auto& t = p_.thermal;
  ThermalNetwork::Vec C, g, ge;
  C << t.C_winding_J_K, t.C_stator_J_K, t.C_rotor_J_K, t.C_housing_J_K;
  g << 0.0, 0.0, 0.0, t.G_housing_coolant_W_K;
  ge << 0.0, 0.0, t.G_rotor_crank_W_K, t.G_housing_engine_W_K;
  ThermalNetwork::Mat G = ThermalNetwork::Mat::Zero();
  auto link = [&G](int i, int j, double v) { G(i, j) = G(j, i) = v; };
  enum { W = 0, S = 1, R = 2, H = 3 };
  link(W, S, t.G_winding_stator_W_K);
  link(W, H, t.G_winding_housing_W_K);
  link(S, H, t.G_stator_housing_W_K);
  link(R, S, t.G_rotor_stator_W_K);
  link(R, H, t.G_rotor_housing_W_K);
  net_ = ThermalNetwork(C, G, g, ge, file);
  reset(units::celsiusToK(25.0));
}

double EMachineModel::crankTorque(double T_em) const {
  const double r = p_.data.ratio, eta = p_.data.ratio_efficiency;
  return T_em >= 0.0 ? r * eta * T_em : r * T_em / eta;
}

double EMachineModel::emTorque(double T_crank) const {
  const double r = p_.data.ratio, eta = p_.data.ratio_efficiency;
  return T_crank >= 0.0 ? T_crank / (r * eta) : T_crank * eta / r;
}

CrankLimits EMachineModel::limits(double w_crank, double V, double T_w, double T_m) const {
  const auto& d = p_.derating;
  const double w = p_.data.ratio * std::max(0.0, w_crank);
  const double pmax = env_.peakDrive(w, V), pmin = env_.peakRecup(w, V);
  const double cmax = env_.continuousDrive(w, V), cmin = env_.continuousRecup(w, V);
  const double lam = std::min(ramp(T_w, d.winding_start_K, d.winding_continuous_K),
                              ramp(T_m, d.magnet_start_K, d.magnet_continuous_K));
  const double kap = std::min(ramp(T_w, d.winding_continuous_K, d.winding_zero_K),
                              ramp(T_m, d.magnet_continuous_K, d.magnet_zero_K));
  // λ = 1 gives the peak and λ = 0 the continuous limit exactly (no rounding).
  const double lmax = kap * (lam * pmax + (1.0 - lam) * cmax);
  const double lmin = kap * (lam * pmin + (1.0 - lam) * cmin);
  CrankLimits c;
  c.max_peak = crankTorque(pmax);
  c.min_peak = crankTorque(pmin);
  c.max_cont = crankTorque(cmax);
  c.min_cont = crankTorque(cmin);
  c.max_live = crankTorque(lmax);
  c.min_live = crankTorque(lmin);
  double f = 1.0;
  if (pmax > 0.0) f = std::min(f, lmax / pmax);
  if (pmin < 0.0) f = std::min(f, lmin / pmin);
  c.derating_factor = f;
  return c;
}

double EMachineModel::dcPower(double T_crank, double w_crank, double V, double T_w, double T_mag) const {
  const double T_em = emTorque(T_crank), w_em = p_.data.ratio * std::max(0.0, w_crank);
  return T_em * w_em + loss_.evaluate(T_em, w_em, std::max(0.0, V), T_w, T_mag).total();
}

ThermalNetwork::Vec EMachineModel::nodeHeat(const LossBreakdown& b) {
  ThermalNetwork::Vec q;
  q << b.copper_W, b.iron_W, b.rotor_W + b.windage_W, b.bearing_W;
  return q;
}

void EMachineModel::reset(double T_K) {
  if (!std::isfinite(T_K)) throw ModelDivergence("emachine", "initial temperature", "not finite");
  x_.setConstant(T_K);
  x0_ = x_;
  out_ = EMachineOutputs{};
  out_.dc_voltage_V = p_.envelope.nominal_voltage_V;
  out_.winding_T_K = out_.stator_T_K = out_.magnet_T_K = out_.housing_T_K = T_K;
  out_.limits = limits(0.0, p_.envelope.nominal_voltage_V, T_K, T_K);
  checkTemperatures();
}

void EMachineModel::checkTemperatures() const {
  static const char* names[] = {"winding temperature", "stator temperature", "magnet (rotor) temperature",
                                "housing temperature"};
  for (int i = 0; i < ThermalNetwork::N; ++i) {
    const double T = x_(i);
    if (!std::isfinite(T) || T < p_.numerics.min_temperature_K || T > p_.numerics.max_temperature_K)
      throw ModelDivergence("emachine", names[i],
                            "left [" + std::to_string(p_.numerics.min_temperature_K) + ", " +
                                std::to_string(p_.numerics.max_temperature_K) + "] K: " + std::to_string(T));
  }
}

void EMachineModel::step(double dt, const EMachineInputs& in) {
  requireFinite(in.torque_request_Nm, "torque_request_Nm");
  requireFinite(in.crank_speed_rad_s, "crank_speed_rad_s");
  requireFinite(in.dc_voltage_V, "dc_voltage_V");
  requireFinite(in.coolant_T_K, "coolant_T_K");
  requireFinite(in.engine_T_K, "engine_T_K");
  if (!std::isfinite(dt) || !(dt > 0.0)) throw ModelDivergence("emachine", "time step", "must be finite and > 0");

  const double w_c = std::max(0.0, in.crank_speed_rad_s);
  const double w_em = p_.data.ratio * w_c;
  const double V = std::max(0.0, in.dc_voltage_V);
  // Live limits with the temperatures at the step start; clamp the request.
  const CrankLimits lim0 = limits(w_c, V, x_(0), x_(2));
  const double T_crank = std::min(lim0.max_live, std::max(lim0.min_live, in.torque_request_Nm));
  const double T_em = emTorque(T_crank);
  const double P_em = T_em * w_em, P_crank = T_crank * w_c;
  const double P_ratio = P_em - P_crank;
  const LossBreakdown b = loss_.evaluate(T_em, w_em, V, x_(0), x_(2));
  const double P_dc = P_em + b.total();

  // Thermal network, exact over the step.
  const ThermalNetwork::Vec q = nodeHeat(b);
  ThermalNetwork::Vec xi;
  net_.step(dt, q, in.coolant_T_K, in.engine_T_K, x_, xi);
  const ThermalNetwork::Vec& g = net_.coolantConductance();
  const ThermalNetwork::Vec& ge = net_.engineConductance();
  double Q_housing = 0.0, Q_engine = 0.0;
  for (int i = 0; i < ThermalNetwork::N; ++i) {
    Q_housing += g(i) * (xi(i) - in.coolant_T_K * dt);
    Q_engine += ge(i) * (in.engine_T_K * dt - xi(i));
  }
  const double Q_coolant = Q_housing + b.inverter() * dt;

  // Bookkeeping.
  EMachineOutputs& o = out_;
  o.torque_request_Nm = in.torque_request_Nm;
  o.torque_Nm = T_crank;
  o.crank_speed_rad_s = w_c;
  o.em_speed_rad_s = w_em;
  o.em_torque_Nm = T_em;
  o.dc_voltage_V = V;
  o.dc_power_W = P_dc;
  o.dc_current_A = V > 0.0 ? P_dc / V : 0.0;
  o.phase_current_A = b.i_A;
  o.loss = b;
  o.ratio_loss_W = P_ratio;
  o.total_loss_W = b.total() + P_ratio;
  o.lt_heat_W = Q_coolant / dt;
  o.engine_heat_W = Q_engine / dt;
  (P_crank >= 0.0 ? o.mech_motoring_J : o.mech_generating_J) += P_crank * dt;
  (P_dc >= 0.0 ? o.dc_drawn_J : o.dc_returned_J) += P_dc * dt;
  o.dc_J += P_dc * dt;
  o.copper_J += b.copper_W * dt;
  o.iron_J += b.iron_W * dt;
  o.rotor_J += b.rotor_W * dt;
  o.mechanical_J += (b.bearing_W + b.windage_W) * dt;
  o.inverter_J += b.inverter() * dt;
  o.ratio_J += P_ratio * dt;
  o.heat_to_coolant_J += Q_coolant;
  o.heat_from_engine_J += Q_engine;
  const ThermalNetwork::Vec& C = net_.capacity();
  o.stored_change_J = C.dot(x_ - x0_);
  o.energy_residual_J = o.dc_J + o.heat_from_engine_J - (o.mech_motoring_J + o.mech_generating_J) -
                        o.ratio_J - o.heat_to_coolant_J - o.stored_change_J;
  o.time_s += dt;
  o.winding_T_K = x_(0);
  o.stator_T_K = x_(1);
  o.magnet_T_K = x_(2);
  o.housing_T_K = x_(3);
  checkTemperatures();
  o.limits = limits(w_c, V, x_(0), x_(2));
}

}  // namespace hbt::emachine
