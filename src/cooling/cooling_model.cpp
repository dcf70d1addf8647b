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
  const double rho_c = ht.coolant_density_kg_m3 * ht.coolant_cp_J_kgK;  // [J/(m^3 K)]
  NetworkCapacities C;
  C.metal = ht.metal_mass_kg * ht.metal_cp_J_kgK;
  C.oil = ht.oil_mass_kg * ht.oil_cp_J_kgK;
  C.engine_loop = ht.engine_loop_volume_m3 * rho_c;
  C.radiator = ht.radiator_volume_m3 * rho_c;
  C.convector = p_.heater.loop_volume_m3 * rho_c;
  C.lt = p_.lt.coolant_volume_m3 * rho_c + p_.lt.component_heat_capacity_J_K;
  network_ = CoolantNetwork(C);

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

void CoolingModel::reset(double ambient_T_K) { reset(ambient_T_K, ambient_T_K, ambient_T_K, ambient_T_K, ambient_T_K); }

void CoolingModel::reset(double ambient_T_K, double metal_T_K, double coolant_ht_T_K, double coolant_lt_T_K,
                         double oil_T_K) {
  T_.metal = metal_T_K;
  T_.oil = oil_T_K;
  T_.engine_loop = T_.radiator = T_.convector = T_w_ = coolant_ht_T_K;
  T_.lt = coolant_lt_T_K;
  T0_ = T_;
  T_p_ = T_w_ - 0.5 * p_.thermostat.hysteresis_K;  // on the heating branch
  eng_ = 0.0;
  w_lt_ = p_.lt.pump_idle_speed_rad_s;
  heater_valve_open_ = T_.engine_loop >= p_.heater.min_coolant_K;
  convectors_warm_ = T_.convector >= p_.heater.min_coolant_K;
  out_ = CoolingOutputs{};
  out_.coolant_ht_T_K = T_.engine_loop;
  out_.radiator_coolant_T_K = T_.radiator;
  out_.convector_coolant_T_K = T_.convector;
  out_.metal_T_K = T_.metal;
  out_.oil_T_K = T_.oil;
  out_.coolant_lt_T_K = T_.lt;
  out_.ht_air_in_T_K = ambient_T_K;
  out_.thermostat_opening = openingFromPlay(T_p_);
  out_.warmup_time_s = T_.engine_loop >= p_.thermostat.opening_start_K ? 0.0 : -1.0;
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
  chk(in.engine_oil_heat_W, "engine_oil_heat_W");
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
  chk(in.gearbox_cooler_heat_W, "gearbox_cooler_heat_W");
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
  heaterValve(in, s);
  heaterLoad(in, s);
  const double T_c_old = T_.engine_loop;
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

// Heater valve and heater-loop flow: the valve (with its lockout hysteresis on the engine
// outlet) lets the heater loop into the circuit only while heating is wanted; the loop then
// takes its share of the HT pump flow, or, with the engine (and its pump) standing, the
// electric circulation pump's flow. The convectors' own lockout (no cold air) senses the water
// they hold, with the same thresholds. The fuel-fired heater in the loop runs the electric
// circulation pump while it burns (its flow circulates the loop; with the valve shut the loop
// exchanges nothing with the engine).
void CoolingModel::heaterValve(const CoolingInputs& in, SubstepState& s) {
  const auto& hp = p_.heater;
  const double T_c = T_.engine_loop, T_v = T_.convector;
  if (T_c >= hp.min_coolant_K) heater_valve_open_ = true;
  if (T_c < hp.min_coolant_K - hp.lockout_hysteresis_K) heater_valve_open_ = false;
  if (T_v >= hp.min_coolant_K) convectors_warm_ = true;
  if (T_v < hp.min_coolant_K - hp.lockout_hysteresis_K) convectors_warm_ = false;
  s.heating_wanted = in.cabin_from_hvac ? in.cabin_heat_demand_W > 0.0 : s.Ta < hp.balance_temperature_K;
  s.valve_open = heater_valve_open_ && s.heating_wanted;
  if (in.aux_heater_heat_W > 0.0) s.e_pump_W = hp.electric_pump_power_W;  // the heater's pump
  if (!s.valve_open) return;
  if (s.w_p > 0.0) {
    s.q_heater = hp.loop_flow_fraction * s.q_pump;
  } else if (hp.electric_pump_flow_m3_s > 0.0) {
    s.q_heater = hp.electric_pump_flow_m3_s;
    s.e_pump_W = hp.electric_pump_power_W;
  }
}

// Cabin heat taken from the convector volume: Q = min(D, q0 + g θ_v), the cabin's demand D or
// what the convectors deliver at their water temperature, G_h (T_v - T_ref) = q0 + g θ_v with
// T_ref the ambient (heater/ balance point) or the cabin (the hvac participant's demand).
void CoolingModel::heaterLoad(const CoolingInputs& in, SubstepState& s) const {
  if (!s.heating_wanted || !convectors_warm_) return;
  const auto& hp = p_.heater;
  const double T_ref = in.cabin_from_hvac ? in.cabin_T_K : s.Ta;
  if (!(T_.convector > T_ref)) return;  // the convectors cannot heat the cabin
  s.heater_demand_W = in.cabin_from_hvac ? in.cabin_heat_demand_W
                                         : hp.cabin_UA_W_K * (hp.balance_temperature_K - s.Ta);
  s.heater_g = hp.conductance_W_K;
  s.heater_q0 = -hp.conductance_W_K * (T_ref - s.Ta);
  s.heater_on = s.heater_demand_W > 0.0;
}

// Backward Euler of the thermal network (coolant_network.hpp) with this substep's coefficients.
void CoolingModel::solveTemperatures(const CoolingInputs& in, SubstepState& s) {
  const auto& ht = p_.ht;
  const double rho_cp = ht.coolant_density_kg_m3 * ht.coolant_cp_J_kgK;
  NetworkCoefficients k;
  k.G_mc = ht.metal_to_coolant_UA_W_K;
  k.G_s = ht.surface_loss_UA_W_K;
  k.G_om = ht.oil_to_metal_UA_W_K;
  k.G_oc = ht.oil_cooler_UA_W_K;
  k.W_rad = rho_cp * s.q_rad;
  k.W_heater = rho_cp * s.q_heater;
  k.G_ht = s.G_ht;
  k.preheat = s.pre;
  k.G_lt = s.G_lt;
  k.Q_engine = in.engine_heat_W - in.em_engine_heat_W;  // net heat into the metal: minus what the P1 flange takes
  k.Q_aux = in.gearbox_cooler_heat_W;     // into the engine loop
  k.Q_loop = in.aux_heater_heat_W;        // the fuel-fired heater sits in the heater loop
  k.Q_lt = in.lt_heat_W;
  k.Q_oil = in.engine_oil_heat_W;
  // Heater Q = min(D, q0 + g θ_v) taken at the new convector temperature: the branch the old
  // temperature picks, solved again on the other branch if the new temperature picks that one.
  const NetworkState T_old = T_;
  const auto setBranch = [&](bool capacity_limited) {
    k.q_heater = !s.heater_on ? 0.0 : capacity_limited ? s.heater_q0 : s.heater_demand_W;
    k.g_heater = s.heater_on && capacity_limited ? s.heater_g : 0.0;
  };
  const auto limited = [&](const NetworkState& T) {
    return s.heater_q0 + s.heater_g * (T.convector - s.Ta) < s.heater_demand_W;
  };
  const bool first = limited(T_old);
  setBranch(first);
  s.flux = network_.step(s.h, s.Ta, k, T_);
  if (s.heater_on && limited(T_) != first) {
    T_ = T_old;
    setBranch(!first);
    s.flux = network_.step(s.h, s.Ta, k, T_);
  }
  checkTemperatures();
}

void CoolingModel::checkTemperatures() const {
  const auto& nm = p_.numerics;
  auto chk = [&](double T, const char* what) {
    if (!std::isfinite(T) || T < nm.min_temperature_K || T > nm.max_temperature_K)
      throw ModelDivergence("cooling", what,
                            "= " + std::to_string(T) + " K outside [" + std::to_string(nm.min_temperature_K) +
                                ", " + std::to_string(nm.max_temperature_K) + "] K");
  };
  chk(T_.metal, "engine metal temperature");
  chk(T_.oil, "engine oil temperature");
  chk(T_.engine_loop, "HT coolant temperature");
  chk(T_.radiator, "HT radiator coolant temperature");
  chk(T_.convector, "HT convector coolant temperature");
  chk(T_.lt, "LT coolant temperature");
}

// Lags with the new coolant temperatures (exact exponential update): thermostat wax and its
// play, fan clutch, LT pump speed.
void CoolingModel::updateLags(const CoolingInputs& in, const SubstepState& s) {
  const double h = s.h;
  const auto& f = p_.fan;
  const auto& tp = p_.thermostat;
  const double T_c = T_.engine_loop;
  T_w_ = T_c + (T_w_ - T_c) * lagFactor(h, tp.wax_time_constant_s);
  const double hh = 0.5 * tp.hysteresis_K;
  T_p_ = std::min(std::max(T_p_, T_w_ - hh), T_w_ + hh);
  const double e_target =
      std::max(clamp01((T_c - f.engage_start_K) / (f.engage_full_K - f.engage_start_K)), clamp01(in.fan_demand));
  eng_ = e_target + (eng_ - e_target) * lagFactor(h, f.clutch_time_constant_s);
  const double w_target = ltPumpTarget(T_.lt);
  w_lt_ = w_target + (w_lt_ - w_target) * lagFactor(h, p_.lt.pump_time_constant_s);
}

// Bookkeeping: exactly the fluxes of the implicit update.
void CoolingModel::recordOutputs(const CoolingInputs& in, const SubstepState& s, double T_c_old) {
  const double h = s.h;
  const auto& tp = p_.thermostat;
  CoolingOutputs& o = out_;
  const double T_c = T_.engine_loop;
  if (o.warmup_time_s < 0.0 && T_c >= tp.opening_start_K) {
    const double frac = T_c > T_c_old ? (tp.opening_start_K - T_c_old) / (T_c - T_c_old) : 1.0;
    o.warmup_time_s = o.time_s + h * std::min(1.0, std::max(0.0, frac));
  }
  o.time_s += h;
  o.coolant_ht_T_K = T_c;
  o.radiator_coolant_T_K = T_.radiator;
  o.convector_coolant_T_K = T_.convector;
  o.metal_T_K = T_.metal;
  o.oil_T_K = T_.oil;
  o.coolant_lt_T_K = T_.lt;
  o.heater_valve_open = s.valve_open;
  o.heater_loop_flow_m3_s = s.q_heater;
  o.electric_pump_power_W = s.e_pump_W;
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
  const NetworkFluxes& f = s.flux;
  o.radiator_ht_heat_W = f.radiator_ht;
  o.radiator_lt_heat_W = f.radiator_lt;
  o.heater_heat_W = f.heater;
  o.aux_heater_heat_W = in.aux_heater_heat_W;
  o.surface_loss_W = f.surface;
  o.oil_cooler_heat_W = f.oil_cooler;
  o.air_volume_flow_m3_s = s.air.flow_m3_s;
  o.air_mass_flow_kg_s = s.m_air;
  o.coolant_flow_m3_s = s.q_pump;
  o.radiator_coolant_flow_m3_s = s.q_rad;
  o.ht_air_in_T_K = s.Ta + s.pre * (T_.lt - s.Ta);
  o.fan_energy_J += s.air.power_W * h;
  o.fan_drive_energy_J += s.fan_drive_W * h;
  o.pump_energy_J += s.pump_W * h;
  o.lt_pump_energy_J += s.lt_in_W * h;
  o.electric_pump_energy_J += s.e_pump_W * h;
  o.engine_heat_J += in.engine_heat_W * h;
  o.engine_oil_heat_J += in.engine_oil_heat_W * h;
  o.oil_cooler_J += f.oil_cooler * h;
  o.lt_heat_J += in.lt_heat_W * h;
  o.em_engine_heat_W = in.em_engine_heat_W;
  o.em_engine_heat_J += in.em_engine_heat_W * h;
  o.aux_heater_J += in.aux_heater_heat_W * h;
  o.gearbox_cooler_J += in.gearbox_cooler_heat_W * h;
  o.radiator_ht_J += f.radiator_ht * h;
  o.radiator_lt_J += f.radiator_lt * h;
  o.heater_J += f.heater * h;
  o.surface_loss_J += f.surface * h;
  o.stored_change_J = network_.storedSince_J(T_, T0_);
  o.energy_residual_J = o.engine_heat_J + o.engine_oil_heat_J + o.lt_heat_J + o.aux_heater_J + o.gearbox_cooler_J - o.em_engine_heat_J - o.radiator_ht_J -
                        o.radiator_lt_J - o.heater_J - o.surface_loss_J - o.stored_change_J;
}

}  // namespace hbt::cooling
