#include "ems/ems_model.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace hbt::ems {

EmsModel::EmsModel(const EmsParams& p, const FuelModel& fuel, const EmLimitModel* em_limits)
    : p_(p), fuel_(fuel), em_limits_(em_limits) {
  reset();
}

void EmsModel::reset() {
  state_ = State::Running;
  soc_integral_ = 0.0;
  on_time_s_ = kRunningForever_s;  // the engine starts running
  crank_time_s_ = 0.0;
  d_ = EmsDecision{};
}

double EmsModel::equivalenceFactor(double soc) const {
  const auto& e = p_.ecms;
  return std::clamp(e.equivalence_factor + e.soc_kp * (e.soc_target - soc), e.s_min, e.s_max);
}

const EmsDecision& EmsModel::step(double dt, const EmsInputs& in) {
  const double vals[] = {in.crank_torque_demand_Nm, in.wheel_brake_demand_Nm, in.engine_speed_rad_s,
                         in.crank_to_wheel_ratio, in.engine_max_torque_Nm, in.engine_min_torque_Nm,
                         in.em_max_torque_Nm, in.em_min_torque_Nm, in.em_winding_T_K, in.em_magnet_T_K,
                         in.dc_voltage_V, in.dcdc_power_W, in.soc, in.battery_T_K, in.discharge_limit_W,
                         in.charge_limit_W, in.coolant_T_K, in.scr_T_K};
  for (double x : vals)
    if (!std::isfinite(x)) throw ModelDivergence("ems", "inputs", "non-finite input");
  if (!(dt > 0.0)) throw ModelDivergence("ems", "dt", "must be > 0");
  return decide(dt, withLiveLimits(in));
}

EmsInputs EmsModel::withLiveLimits(const EmsInputs& in) const {
  EmsInputs x = in;
  if (em_limits_)
    em_limits_->liveLimits(std::max(0.0, in.engine_speed_rad_s), in.dc_voltage_V, in.em_winding_T_K,
                           in.em_magnet_T_K, x.em_max_torque_Nm, x.em_min_torque_Nm);
  if (!std::isfinite(x.em_max_torque_Nm) || !std::isfinite(x.em_min_torque_Nm))
    throw ModelDivergence("ems", "e-machine limit model", "non-finite live limit");
  return x;
}

double EmsModel::dischargeShare_W(const EmsInputs& in, double f_T) const {
  return std::max(0.0, in.discharge_limit_W * f_T * (1.0 - p_.battery.limit_margin) - in.dcdc_power_W);
}

double EmsModel::chargeShare_W(const EmsInputs& in) const {
  return std::max(0.0, in.charge_limit_W * (1.0 - p_.battery.limit_margin) + in.dcdc_power_W);
}

double EmsModel::batteryBound(double T, double P_avail, const EmsInputs& in) const {
  const double w = std::max(0.0, in.engine_speed_rad_s);
  if (T == 0.0 || w <= 0.0) return T;
  const auto& e = p_.ecms;
  if (!em_limits_) {  // the controller's constant efficiencies
    const double bound = T > 0.0 ? P_avail * e.em_motor_efficiency / w : -P_avail / (w * e.em_generator_efficiency);
    return T > 0.0 ? std::min(T, bound) : std::max(T, bound);
  }
  // electric power the pack sees for crank torque x: drawn (> 0) motoring, returned (> 0) generating
  const double sign = T > 0.0 ? 1.0 : -1.0;
  auto pack_W = [&](double x) {
    return sign * em_limits_->dcPower_W(x, w, in.dc_voltage_V, in.em_winding_T_K, in.em_magnet_T_K);
  };
  if (pack_W(T) <= P_avail) return T;
  double ok = 0.0, over = T;  // |x| at or below ok fits, at over does not
  if (pack_W(0.0) > P_avail) return 0.0;  // the machine's own losses exceed the share at zero torque
  while (std::fabs(over - ok) > 1e-6) {
    const double mid = 0.5 * (ok + over);
    if (pack_W(mid) <= P_avail) ok = mid;
    else over = mid;
  }
  return ok;
}

const EmsDecision& EmsModel::decide(double dt, const EmsInputs& in) {
  const auto& ss = p_.stop_start;
  const bool engine_warm = in.coolant_T_K >= p_.warmup.coolant_warm_K;
  const bool warm = engine_warm && in.scr_T_K >= p_.warmup.scr_warm_K;
  d_.warm = warm;
  if (!warm) d_.warmup_inhibit_time_s += dt;
  d_.friction_brake_Nm = in.wheel_brake_demand_Nm;
  const double w = std::max(in.engine_speed_rad_s, 0.0);

  // 1. Stop-start.
  Reason standing = Reason::EcmsOptimum;  // why a standing engine keeps running (if it does)
  if (state_ == State::Running && in.stopped && !in.start_request) {
    if (!ss.enabled) {
      standing = Reason::StopStartDisabled;
    } else if (!warm) {
      standing = Reason::WarmupInhibit;
    } else if (in.soc < ss.soc_min_to_stop) {
      standing = Reason::SocLow;
    } else if (in.discharge_limit_W < ss.min_discharge_power_W) {
      standing = Reason::BatteryLimit;
    } else if (in.climate_run_request) {
      standing = Reason::ClimateRequest;
    } else if (warm && in.soc >= ss.soc_min_to_stop && in.discharge_limit_W >= ss.min_discharge_power_W &&
               on_time_s_ >= ss.min_on_time_s) {
      state_ = State::Stopped;
      ++d_.engine_stops;
    }
  }
  if (state_ == State::Stopped) {
    Reason why = Reason::StandstillStop;
    if (in.start_request || !in.stopped) why = Reason::DriveOff;
    else if (in.soc < ss.soc_restart) why = Reason::SocRestart;
    else if (!engine_warm) why = Reason::CooledRestart;
    else if (in.climate_run_request) why = Reason::ClimateRequest;
    if (why != Reason::StandstillStop) {
      state_ = State::Cranking;
      crank_time_s_ = 0.0;
      ++d_.engine_starts;
    } else {
      d_.stopped_time_s += dt;
      d_.engine_torque_request_Nm = d_.em_torque_request_Nm = d_.cost_W = 0.0;
      d_.engine_on = false;
      d_.mode = Mode::Stopped;
      d_.reason = why;
      return d_;
    }
    d_.reason = why;
  }
  if (state_ == State::Cranking) {
    if (w >= ss.firing_speed_rad_s) {
      state_ = State::Running;
      on_time_s_ = 0.0;
    } else {
      crank_time_s_ += dt;
      d_.cranking_time_s += dt;
      if (crank_time_s_ > ss.max_crank_time_s)
        throw ModelDivergence("ems", "stop_start/max_crank_time_s",
                              "engine start failed: the crank stayed below the firing speed (e-machine "
                              "or battery limits too low for stop_start/crank_torque_Nm?)");
      double T = std::min(ss.crank_torque_Nm, std::max(0.0, in.em_max_torque_Nm));
      if (w > 1.0) T = batteryBound(T, dischargeShare_W(in, 1.0), in);
      d_.engine_torque_request_Nm = 0.0;
      d_.em_torque_request_Nm = std::max(0.0, T);
      d_.engine_on = false;
      d_.mode = Mode::Cranking;
      return d_;
    }
  }
  on_time_s_ += dt;
  d_.engine_on = true;

  // 2. Regenerative braking, 3. ECMS.
  if (in.wheel_brake_demand_Nm > 0.0) {
    regen(in);
    return d_;
  }
  ecms(in, warm, dt);
  if (standing != Reason::EcmsOptimum) d_.reason = standing;
  return d_;
}

void EmsModel::regen(const EmsInputs& in) {
  const double w = in.engine_speed_rad_s, i = in.crank_to_wheel_ratio;
  d_.engine_torque_request_Nm = in.crank_torque_demand_Nm;
  d_.em_torque_request_Nm = 0.0;
  d_.friction_brake_Nm = in.wheel_brake_demand_Nm;
  d_.mode = Mode::EngineOnly;
  if (!(i > 0.0) || w < p_.regen.min_engine_speed_rad_s) {
    d_.reason = Reason::NotConnected;
    return;
  }
  const double em_lim = std::max(0.0, -in.em_min_torque_Nm);
  const double bat_lim = -batteryBound(-em_lim, chargeShare_W(in), in);
  const double want = in.wheel_brake_demand_Nm / i;
  double T = std::min({em_lim, bat_lim, want});
  // all of it regenerated, or the binding limit (the friction brake takes the rest)
  d_.reason = T >= want ? Reason::EcmsOptimum : (em_lim <= bat_lim ? Reason::EmLimit : Reason::BatteryLimit);
  T = std::max(0.0, T);
  d_.em_torque_request_Nm = -T;
  d_.friction_brake_Nm = std::max(0.0, in.wheel_brake_demand_Nm - i * T);
  d_.mode = T > 0.0 ? Mode::Regen : Mode::EngineOnly;
}

void EmsModel::ecms(const EmsInputs& in, bool warm, double dt) {
  const auto& e = p_.ecms;
  const double w = in.engine_speed_rad_s, Td = in.crank_torque_demand_Nm;
  soc_integral_ = std::clamp(soc_integral_ + (e.soc_target - in.soc) * dt, -1e3, 1e3);
  const double s = std::clamp(equivalenceFactor(in.soc) + e.soc_ki_per_s * soc_integral_, e.s_min, e.s_max);
  d_.equivalence_factor = s;
  d_.engine_torque_request_Nm = Td;
  d_.em_torque_request_Nm = 0.0;
  d_.mode = Mode::EngineOnly;
  if (Td <= in.engine_min_torque_Nm || w < 1.0) {  // overrun: motoring, nothing to split
    d_.reason = Reason::Overrun;
    d_.cost_W = 0.0;
    return;
  }
  // Upper bound (boost) and why it binds.
  Reason hi_why = Reason::EcmsOptimum;
  double f_T = std::clamp((p_.battery.assist_zero_K - in.battery_T_K) /
                          (p_.battery.assist_zero_K - p_.battery.assist_derate_start_K), 0.0, 1.0);
  double hi = std::max(0.0, in.em_max_torque_Nm);
  const double hi_bat = batteryBound(hi, dischargeShare_W(in, f_T), in);
  if (hi_bat < hi) { hi = hi_bat; hi_why = f_T < 1.0 ? Reason::BatteryHot : Reason::BatteryLimit; }
  hi = std::min(hi, Td - in.engine_min_torque_Nm);
  if (!warm) { hi = 0.0; hi_why = Reason::WarmupInhibit; }
  else if (in.soc < e.soc_min) { hi = 0.0; hi_why = Reason::SocLow; }
  // Lower bound (load-point shift = charging).
  Reason lo_why = Reason::EcmsOptimum;
  double lo = std::min(0.0, in.em_min_torque_Nm);
  const double lo_bat = batteryBound(lo, chargeShare_W(in), in);
  if (lo_bat > lo) { lo = lo_bat; lo_why = Reason::BatteryLimit; }
  lo = std::max(lo, Td - in.engine_max_torque_Nm);
  if (in.soc > e.soc_max) { lo = std::max(lo, 0.0); lo_why = Reason::SocHigh; }
  if (lo > hi) lo = hi;  // e.g. demand above the engine's maximum while boost is inhibited

  auto cost = [&](double Tem) {
    const double P_el = Tem >= 0.0 ? Tem * w / e.em_motor_efficiency : Tem * w * e.em_generator_efficiency;
    return fuel_.fuelRate_kg_s(w, Td - Tem) * units::kDieselLhv_J_kg + s * P_el;
  };
  double best_T = std::clamp(0.0, lo, hi), best_J = cost(best_T);
  const int n = std::max(3, e.candidates);
  for (int k = 0; k < n; ++k) {
    const double T = lo + (hi - lo) * k / (n - 1);
    const double J = cost(T);
    if (J < best_J - 1e-9 || (std::fabs(J - best_J) <= 1e-9 && std::fabs(T) < std::fabs(best_T))) {
      best_J = J;
      best_T = T;
    }
  }
  if (std::fabs(best_T) < e.min_boost_torque_Nm && lo <= 0.0 && hi >= 0.0) { best_T = 0.0; best_J = cost(0.0); }
  d_.em_torque_request_Nm = best_T;
  d_.engine_torque_request_Nm = Td - best_T;
  d_.cost_W = best_J;
  d_.mode = best_T > 0.0 ? Mode::Boost : (best_T < 0.0 ? Mode::LoadPointShift : Mode::EngineOnly);
  d_.reason = Reason::EcmsOptimum;
  const double tol = 1e-6 * (1.0 + std::fabs(hi - lo));
  if (best_T >= hi - tol && hi_why != Reason::EcmsOptimum) d_.reason = hi_why;
  else if (best_T <= lo + tol && lo_why != Reason::EcmsOptimum) d_.reason = lo_why;
  else if (best_T == 0.0 && !warm) d_.reason = Reason::WarmupInhibit;
}

}  // namespace hbt::ems
