#include "engine_1d/controllers.hpp"

#include <algorithm>
#include <cmath>

#include "common/units.hpp"

namespace hbt::engine_1d {

EngineControllers::EngineControllers(const Engine1DConfig& cfg, double afr, double fuel_ref)
    : cfg_(cfg),
      boost_(cfg.boost_speed_rpm, cfg.boost_load, cfg.boost_pressure_ratio, "engine_1d",
             "engine_1d/control/boost_pressure_ratio"),
      torque_model_(cfg.torque_dead_angle_deg),
      afr_(afr),
      fuel_ref_(fuel_ref) {
  PidGains f;
  f.kp = cfg.fuel_kp;
  f.ki = cfg.fuel_ki;
  f.u_min = -cfg.fuel_trim_max * fuel_ref;
  f.u_max = cfg.fuel_trim_max * fuel_ref;
  fuel_pid_ = Pid(f);
  PidGains w;
  w.kp = cfg.wg_kp;
  w.ki = cfg.wg_ki;
  w.u_min = 0.0;
  w.u_max = 1.0;
  wg_pid_ = Pid(w);
}

void EngineControllers::reset(double a, double torque_Nm) {
  fuel_pid_.reset(0.0);
  torque_model_.reset(torque_Nm);
  wg_pid_.reset(cfg_.wg_ki > 0.0 ? std::clamp(a, 0.0, 1.0) / cfg_.wg_ki : 0.0);
}

double EngineControllers::limitedRequest(double req, double fl, double mot) {
  return std::clamp(req, std::min(mot, fl), fl);
}

double EngineControllers::boostTarget(double omega, double load, double p_amb) const {
  // (ω·30)/π, not units::radpsToRpm(ω) = ω/(π/30): a last-bit difference in the rpm of the boost
  // map moves the 1D engine's NOx by ~1e-8 (relative) in a 20 s Urban run.
  return boost_(omega * 30.0 / units::kPi, std::clamp(load, 0.0, 1.0)) * p_amb;
}

ControlCommand EngineControllers::update(double dt, const ControlInputs& in) {
  ControlCommand c;
  const double treq = limitedRequest(in.torque_request, in.full_load, in.motoring);
  c.torque_target_Nm = treq;
  // expected brake torque from the requests so far, then this step's request joins the history
  c.torque_model_Nm = torque_model_.expected();
  torque_model_.push(units::radToDeg(in.omega * dt), treq);
  const double cycles_per_s = cfg_.cylinders * in.omega / (4.0 * units::kPi);  // cylinder-cycles per second
  // --- boost ---
  const double load = in.full_load > 0.0 ? std::max(treq, 0.0) / in.full_load : 0.0;
  c.boost_target_Pa = boostTarget(in.omega, load, in.ambient_p);
  c.wastegate_opening = wg_pid_.update(in.boost - c.boost_target_Pa, dt);
  // --- fuel ---
  c.fuel_cut = !in.fuel_enabled || in.torque_request <= in.motoring || cycles_per_s <= 0.0;
  if (c.fuel_cut) {
    fuel_pid_.reset(0.0);
    return c;
  }
  c.feedforward_kg = std::max(in.feedforward_fuel_kg_s, 0.0) / cycles_per_s;
  c.smoke_limit_kg = in.air_flow / cycles_per_s / (cfg_.lambda_smoke * afr_);
  const double e = c.torque_model_Nm - in.brake_torque;
  const double i_before = fuel_pid_.integral();
  const double trim = fuel_pid_.update(e, dt);
  const double m = c.feedforward_kg + trim;
  c.fuel_per_cycle_kg = std::clamp(m, 0.0, c.smoke_limit_kg);
  c.smoke_limited = m > c.smoke_limit_kg;
  if ((c.smoke_limited && e > 0.0) || (m < 0.0 && e < 0.0)) fuel_pid_.reset(i_before);
  return c;
}

}  // namespace hbt::engine_1d
