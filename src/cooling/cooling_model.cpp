#include "cooling/cooling_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/errors.hpp"

namespace hbt::cooling {

namespace {
double clamp01(double x) { return std::min(1.0, std::max(0.0, x)); }
double lagFactor(double h, double tau) { return tau > 0.0 ? std::exp(-h / tau) : 0.0; }
}  // namespace

CoolingModel::CoolingModel(const CoolingParams& p, const std::string& file) : p_(p), file_(file) {
  p_.validate(file);
  const auto& ht = p_.ht;
  C_m_ = ht.metal_mass_kg * ht.metal_cp_J_kgK + ht.oil_mass_kg * ht.oil_cp_J_kgK;
  C_c_ = ht.coolant_volume_m3 * ht.coolant_density_kg_m3 * ht.coolant_cp_J_kgK;
  C_l_ = p_.lt.coolant_volume_m3 * ht.coolant_density_kg_m3 * ht.coolant_cp_J_kgK +
         p_.lt.component_heat_capacity_J_K;

  const auto& r = p_.radiator;
  RadiatorRating rh;
  rh.heat_W = r.rated_heat_W;
  rh.coolant_in_K = r.rated_coolant_in_K;
  rh.air_in_K = r.rated_air_in_K;
  rh.air_mass_flow_kg_s = r.rated_air_mass_flow_kg_s;
  rh.coolant_mass_flow_kg_s = r.rated_coolant_mass_flow_kg_s;
  rh.air_side_resistance_fraction = r.air_side_resistance_fraction;
  rh.air_flow_exponent = r.air_flow_exponent;
  rh.coolant_flow_exponent = r.coolant_flow_exponent;
  rad_ht_ = Radiator(rh, p_.air.cp_J_kgK, ht.coolant_cp_J_kgK, file, "radiator/");

  const auto& l = p_.lt;
  RadiatorRating rl = rh;  // same construction (fin/tube exponents) as the HT radiator
  rl.heat_W = l.radiator_rated_heat_W;
  rl.coolant_in_K = l.radiator_rated_coolant_in_K;
  rl.air_in_K = l.radiator_rated_air_in_K;
  rl.air_mass_flow_kg_s = l.radiator_rated_air_mass_flow_kg_s;
  rl.coolant_mass_flow_kg_s = l.pump_rated_flow_m3_s * ht.coolant_density_kg_m3;
  rad_lt_ = Radiator(rl, p_.air.cp_J_kgK, ht.coolant_cp_J_kgK, file, "lt/radiator_");

  const auto& f = p_.fan;
  dp_rated_ = f.rated_power_W * f.efficiency / f.rated_flow_m3_s;
  dp0_ = dp_rated_ / (1.0 - 1.0 / f.free_delivery_ratio);
  K_sys_ = dp_rated_ / (f.rated_flow_m3_s * f.rated_flow_m3_s);
  flow_free_r_ = f.free_delivery_ratio * f.rated_flow_m3_s;
  reset(units::celsiusToK(25.0));
}

void CoolingModel::reset(double ambient_T_K) { reset(ambient_T_K, ambient_T_K, ambient_T_K, ambient_T_K); }

void CoolingModel::reset(double ambient_T_K, double metal_T_K, double coolant_ht_T_K, double coolant_lt_T_K) {
  T_m_ = T_m0_ = metal_T_K;
  T_c_ = T_c0_ = T_w_ = coolant_ht_T_K;
  T_l_ = T_l0_ = coolant_lt_T_K;
  T_p_ = T_w_ - 0.5 * p_.thermostat.hysteresis_K;  // on the heating branch
  eng_ = 0.0;
  w_lt_ = p_.lt.pump_idle_speed_rad_s;
  heater_valve_open_ = T_c_ >= p_.heater.min_coolant_K;
  out_ = CoolingOutputs{};
  out_.coolant_ht_T_K = T_c_;
  out_.metal_T_K = T_m_;
  out_.coolant_lt_T_K = T_l_;
  out_.ht_air_in_T_K = ambient_T_K;
  out_.thermostat_opening = openingFromPlay(T_p_);
  out_.warmup_time_s = T_c_ >= p_.thermostat.opening_start_K ? 0.0 : -1.0;
}

double CoolingModel::openingFromPlay(double T_p) const {
  const auto& t = p_.thermostat;
  return clamp01((T_p + 0.5 * t.hysteresis_K - t.opening_start_K) / (t.full_open_K - t.opening_start_K));
}

double CoolingModel::ltPumpTarget(double T_l) const {
  const auto& l = p_.lt;
  const double s = clamp01((T_l - l.pump_rule_low_K) / (l.pump_rule_high_K - l.pump_rule_low_K));
  return l.pump_idle_speed_rad_s + (l.pump_max_speed_rad_s - l.pump_idle_speed_rad_s) * s;
}

CoolingModel::AirPoint CoolingModel::airPath(double n, double v, double rho) const {
  const auto& f = p_.fan;
  const double sr = rho > 0.0 ? rho / f.rated_air_density_kg_m3 : 1.0;  // all pressures ∝ ρ
  const double x = std::max(0.0, n) / f.rated_speed_rad_s;  // n/n_r
  const double a = dp0_ * x * x;
  const double b = dp0_ * x / flow_free_r_;
  const double q_ram = f.ram_recovery * std::abs(v) * f.grille_area_m2;
  const double c = a + K_sys_ * q_ram * q_ram;
  const double q = (-b + std::sqrt(b * b + 4.0 * K_sys_ * c)) / (2.0 * K_sys_);
  const double dp = sr * (a - b * q);
  const double power = dp >= 0.0 ? dp * q / f.efficiency : dp * q * f.efficiency;
  return {q, dp, power};
}

void CoolingModel::checkFinite(const CoolingInputs& in) const {
  const char* where = "cooling step input";
  auto chk = [&](double v, const char* key) {
    if (!std::isfinite(v)) throw InputError(where, key, "not finite");
  };
  chk(in.engine_heat_W, "engine_heat_W");
  chk(in.pump_speed_rad_s, "pump_speed_rad_s");
  chk(in.vehicle_speed_m_s, "vehicle_speed_m_s");
  chk(in.ambient_T_K, "ambient_T_K");
  chk(in.ambient_p_Pa, "ambient_p_Pa");
  chk(in.lt_heat_W, "lt_heat_W");
  chk(in.em_engine_heat_W, "em_engine_heat_W");
  chk(in.fan_demand, "fan_demand");
  chk(in.cabin_heat_demand_W, "cabin_heat_demand_W");
  chk(in.cabin_T_K, "cabin_T_K");
  chk(in.aux_heater_heat_W, "aux_heater_heat_W");
  if (!(in.ambient_T_K > 200.0 && in.ambient_T_K < 350.0))
    throw InputError(where, "ambient_T_K", "outside [200, 350] K");
  if (!(in.ambient_p_Pa > 2e4 && in.ambient_p_Pa < 2e5))
    throw InputError(where, "ambient_p_Pa", "outside [2e4, 2e5] Pa");
}

void CoolingModel::step(double dt_s, const CoolingInputs& in) {
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) throw InputError("cooling step input", "dt", "must be > 0");
  checkFinite(in);
  const int n = std::max(1, static_cast<int>(std::ceil(dt_s / p_.numerics.max_substep_s - 1e-9)));
  const double h = dt_s / n;
  for (int i = 0; i < n; ++i) substep(h, in);
}

void CoolingModel::substep(double h, const CoolingInputs& in) {
  SubstepState s;
  s.h = h;
  s.Ta = in.ambient_T_K;
  const double rho_air = in.ambient_p_Pa / (p_.air.R_J_kgK * s.Ta);
  s.w_p = std::max(0.0, in.pump_speed_rad_s);
  htPumpAndThermostat(s);
  fanAndAirFlow(in, rho_air, s);
  ltPump(s);
  s.G_lt = rad_lt_.conductance_W_K(s.m_air, s.m_lt);
  s.G_ht = rad_ht_.conductance_W_K(s.m_air, s.m_rad);
  s.pre = s.C_air > 0.0 ? s.G_lt / s.C_air : 0.0;  // T_air,HT,in - T_a = pre θ_l
  heaterLoad(in, s);
  const double T_c_old = T_c_;
  solveTemperatures(in, s);
  updateLags(in, s);
  recordOutputs(in, s, T_c_old);
}

// HT pump (∝ speed) and the thermostat's radiator share of its flow, frozen at the start.
void CoolingModel::htPumpAndThermostat(SubstepState& s) const {
  const auto& ht = p_.ht;
  const double xp = s.w_p / ht.pump_rated_speed_rad_s;
  s.q_pump = ht.pump_rated_flow_m3_s * xp;
  s.pump_W = ht.pump_rated_head_Pa * ht.pump_rated_flow_m3_s * xp * xp * xp / ht.pump_efficiency;
  s.y = openingFromPlay(T_p_);
  const double y_eff = p_.thermostat.leak_fraction + (1.0 - p_.thermostat.leak_fraction) * s.y;
  s.q_rad = y_eff * s.q_pump;
  s.m_rad = ht.coolant_density_kg_m3 * s.q_rad;
}

// Viscous fan at its clutch engagement and the air flow through the radiators.
void CoolingModel::fanAndAirFlow(const CoolingInputs& in, double rho_air, SubstepState& s) const {
  const auto& f = p_.fan;
  const double w_fan_in = s.w_p * f.drive_ratio;
  s.n_fan = w_fan_in * (f.min_speed_ratio + (f.max_speed_ratio - f.min_speed_ratio) * eng_);
  s.air = airPath(s.n_fan, in.vehicle_speed_m_s, rho_air);
  s.fan_drive_W =
      s.air.power_W > 0.0 && s.n_fan > 0.0 ? s.air.power_W * w_fan_in / s.n_fan : s.air.power_W;
  s.m_air = rho_air * s.air.flow_m3_s;
  s.C_air = s.m_air * p_.air.cp_J_kgK;
}

// LT pump: its (lagged) speed, limited by its drive, flow and powers.
void CoolingModel::ltPump(SubstepState& s) const {
  const auto& l = p_.lt;
  const double w_lt_in = s.w_p * l.pump_drive_ratio;
  s.w_lt = std::min(w_lt_, w_lt_in);
  const double xl = s.w_lt / l.pump_max_speed_rad_s;
  s.m_lt = p_.ht.coolant_density_kg_m3 * l.pump_rated_flow_m3_s * xl;
  s.lt_hyd_W = l.pump_rated_head_Pa * l.pump_rated_flow_m3_s * xl * xl * xl;
  const double lt_shaft_W = s.lt_hyd_W / l.pump_efficiency;
  s.lt_in_W = s.w_lt > 0.0 ? lt_shaft_W * w_lt_in / s.w_lt : 0.0;
}

// Cabin heater: the valve (with its lockout hysteresis) and the heat it takes, either the
// cabin's demand (constant) or, when the coolant cannot deliver it, a conductance: to the
// ambient (heater/ balance point) or to the cabin (the hvac participant's demand).
void CoolingModel::heaterLoad(const CoolingInputs& in, SubstepState& s) {
  const auto& hp = p_.heater;
  if (T_c_ >= hp.min_coolant_K) heater_valve_open_ = true;
  if (T_c_ < hp.min_coolant_K - hp.lockout_hysteresis_K) heater_valve_open_ = false;
  if (in.cabin_from_hvac) {
    if (!heater_valve_open_ || !(in.cabin_heat_demand_W > 0.0) || !(T_c_ > in.cabin_T_K)) return;
    if (hp.conductance_W_K * (T_c_ - in.cabin_T_K) >= in.cabin_heat_demand_W) {
      s.q_h_const = in.cabin_heat_demand_W;
    } else {  // Q = G_h (T_c,new - T_cab) = G_h θ_c - G_h (T_cab - T_a)
      s.g_h = hp.conductance_W_K;
      s.q_h_const = -hp.conductance_W_K * (in.cabin_T_K - s.Ta);
    }
    return;
  }
  if (s.Ta < hp.balance_temperature_K && heater_valve_open_) {
    const double demand = hp.cabin_UA_W_K * (hp.balance_temperature_K - s.Ta);
    if (hp.conductance_W_K * (T_c_ - s.Ta) >= demand) s.q_h_const = demand;
    else s.g_h = hp.conductance_W_K;
  }
}

// Backward Euler on θ = T - T_a; the heat flows of the implicit update and the new temperatures.
void CoolingModel::solveTemperatures(const CoolingInputs& in, SubstepState& s) {
  const auto& ht = p_.ht;
  const double h = s.h, Ta = s.Ta;
  const double G_mc = ht.metal_to_coolant_UA_W_K, G_s = ht.surface_loss_UA_W_K;
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b;
  A(0, 0) = C_m_ / h + G_mc + G_s;
  A(0, 1) = -G_mc;
  A(1, 0) = -G_mc;
  A(1, 1) = C_c_ / h + G_mc + s.G_ht + s.g_h;
  A(1, 2) = -s.G_ht * s.pre;
  A(2, 2) = C_l_ / h + s.G_lt;
  b(0) = C_m_ / h * (T_m_ - Ta) + in.engine_heat_W - in.em_engine_heat_W;
  b(1) = C_c_ / h * (T_c_ - Ta) - s.q_h_const + in.aux_heater_heat_W;
  b(2) = C_l_ / h * (T_l_ - Ta) + in.lt_heat_W;
  s.th = A.partialPivLu().solve(b);

  s.Q_lt = s.G_lt * s.th(2);
  s.Q_ht = s.G_ht * (s.th(1) - s.pre * s.th(2));
  s.Q_h = s.q_h_const + s.g_h * s.th(1);
  s.Q_s = G_s * s.th(0);
  T_m_ = Ta + s.th(0);
  T_c_ = Ta + s.th(1);
  T_l_ = Ta + s.th(2);
  const auto& nm = p_.numerics;
  auto chk = [&](double T, const char* what) {
    if (!std::isfinite(T) || T < nm.min_temperature_K || T > nm.max_temperature_K)
      throw ModelDivergence("cooling", what,
                            "= " + std::to_string(T) + " K outside [" + std::to_string(nm.min_temperature_K) +
                                ", " + std::to_string(nm.max_temperature_K) + "] K");
  };
  chk(T_m_, "engine metal temperature");
  chk(T_c_, "HT coolant temperature");
  chk(T_l_, "LT coolant temperature");
}

// Lags with the new coolant temperatures (exact exponential update): thermostat wax and its
// play, fan clutch, LT pump speed.
void CoolingModel::updateLags(const CoolingInputs& in, const SubstepState& s) {
  const double h = s.h;
  const auto& f = p_.fan;
  const auto& tp = p_.thermostat;
  T_w_ = T_c_ + (T_w_ - T_c_) * lagFactor(h, tp.wax_time_constant_s);
  const double hh = 0.5 * tp.hysteresis_K;
  T_p_ = std::min(std::max(T_p_, T_w_ - hh), T_w_ + hh);
  const double e_target =
      std::max(clamp01((T_c_ - f.engage_start_K) / (f.engage_full_K - f.engage_start_K)), clamp01(in.fan_demand));
  eng_ = e_target + (eng_ - e_target) * lagFactor(h, f.clutch_time_constant_s);
  const double w_target = ltPumpTarget(T_l_);
  w_lt_ = w_target + (w_lt_ - w_target) * lagFactor(h, p_.lt.pump_time_constant_s);
}

// Bookkeeping: exactly the fluxes of the implicit update.
void CoolingModel::recordOutputs(const CoolingInputs& in, const SubstepState& s, double T_c_old) {
  const double h = s.h;
  const auto& tp = p_.thermostat;
  CoolingOutputs& o = out_;
  if (o.warmup_time_s < 0.0 && T_c_ >= tp.opening_start_K) {
    const double frac = T_c_ > T_c_old ? (tp.opening_start_K - T_c_old) / (T_c_ - T_c_old) : 1.0;
    o.warmup_time_s = o.time_s + h * std::min(1.0, std::max(0.0, frac));
  }
  o.time_s += h;
  o.coolant_ht_T_K = T_c_;
  o.metal_T_K = T_m_;
  o.coolant_lt_T_K = T_l_;
  o.thermostat_opening = s.y;
  o.fan_engagement = eng_;
  o.fan_speed_rad_s = s.n_fan;
  o.fan_power_W = s.air.power_W;
  o.fan_drive_power_W = s.fan_drive_W;
  o.fan_pressure_rise_Pa = s.air.dp_Pa;
  o.pump_power_W = s.pump_W;
  o.lt_pump_speed_rad_s = s.w_lt;
  o.lt_pump_power_W = s.lt_in_W;
  o.lt_pump_hydraulic_power_W = s.lt_hyd_W;
  o.radiator_ht_heat_W = s.Q_ht;
  o.radiator_lt_heat_W = s.Q_lt;
  o.heater_heat_W = s.Q_h;
  o.aux_heater_heat_W = in.aux_heater_heat_W;
  o.surface_loss_W = s.Q_s;
  o.air_volume_flow_m3_s = s.air.flow_m3_s;
  o.air_mass_flow_kg_s = s.m_air;
  o.coolant_flow_m3_s = s.q_pump;
  o.radiator_coolant_flow_m3_s = s.q_rad;
  o.ht_air_in_T_K = s.Ta + s.pre * s.th(2);
  o.fan_energy_J += s.air.power_W * h;
  o.fan_drive_energy_J += s.fan_drive_W * h;
  o.pump_energy_J += s.pump_W * h;
  o.lt_pump_energy_J += s.lt_in_W * h;
  o.engine_heat_J += in.engine_heat_W * h;
  o.lt_heat_J += in.lt_heat_W * h;
  o.em_engine_heat_W = in.em_engine_heat_W;
  o.em_engine_heat_J += in.em_engine_heat_W * h;
  o.aux_heater_J += in.aux_heater_heat_W * h;
  o.radiator_ht_J += s.Q_ht * h;
  o.radiator_lt_J += s.Q_lt * h;
  o.heater_J += s.Q_h * h;
  o.surface_loss_J += s.Q_s * h;
  o.stored_change_J = C_m_ * (T_m_ - T_m0_) + C_c_ * (T_c_ - T_c0_) + C_l_ * (T_l_ - T_l0_);
  o.energy_residual_J = o.engine_heat_J + o.lt_heat_J + o.aux_heater_J - o.em_engine_heat_J - o.radiator_ht_J -
                        o.radiator_lt_J - o.heater_J - o.surface_loss_J - o.stored_change_J;
}

}  // namespace hbt::cooling
