#include "engine_1d/engine_1d_model.hpp"

#include <algorithm>
#include <cstdio>

#include "common/units.hpp"

namespace hbt::engine_1d {

Engine1DModel::Engine1DModel(const Engine1DParams& p, const std::string& repo_root)
    : engine_(p, repo_root) {}

void Engine1DModel::resetModel(const engine::EngineInputs& in) {
  engine_.reset(in.speed_rad_s, 0.0, in.ambient_T_K, in.ambient_p_Pa, kWarmCoolant_K);
  gas_steps_at_status_ = 0;
  positive_work_J_ = motoring_work_J_ = 0.0;
  copyOutputs(in.speed_rad_s, true);
}

void Engine1DModel::stepModel(double dt_s, const engine::EngineInputs& in) {
  Engine1DInputs e;
  e.speed_rad_s = in.speed_rad_s;
  e.torque_request_Nm = in.torque_request_Nm;
  e.ambient_T_K = in.ambient_T_K;
  e.ambient_p_Pa = in.ambient_p_Pa;
  e.back_pressure_Pa = in.back_pressure_Pa;  // <= 0: the engine's own orifice law
  e.coolant_T_K = in.coolant_T_K > 0.0 ? in.coolant_T_K : kWarmCoolant_K;
  e.oil_T_K = in.oil_T_K;  // <= 0 (no cooling node): the coolant + the cylinder's oil offset
  e.fuel_enabled = in.fuel_enabled;
  engine_.step(dt_s, e);
  copyOutputs(in.speed_rad_s, in.fuel_enabled);
  const double work_J = out_.brake_torque_Nm * std::max(in.speed_rad_s, 0.0) * dt_s;
  (work_J > 0.0 ? positive_work_J_ : motoring_work_J_) += work_J;
  out_.positive_work_J = positive_work_J_;
  out_.motoring_work_J = motoring_work_J_;
}

void Engine1DModel::copyOutputs(double w, bool fuel_enabled) {
  const Engine1DOutputs& o = engine_.outputs();
  engine::EngineOutputs& v = out_;
  v.brake_torque_Nm = fuel_enabled ? o.brake_torque_Nm : o.crank_torque_Nm;
  v.max_torque_Nm = engine_.fullLoadTorque(w);
  v.min_torque_Nm = engine_.motoringTorque(w);
  v.friction_correction_Nm = v.pumping_correction_Nm = 0.0;
  v.fuel_mass_flow_kg_s = o.fuel_mass_flow_kg_s;
  v.fuel_mass_kg = o.fuel_mass_kg;
  v.positive_work_J = positive_work_J_;
  v.motoring_work_J = motoring_work_J_;
  v.boost_pressure_Pa = o.boost_pressure_Pa;
  v.charge_air_T_K = o.intake_manifold_T_K;
  v.turbo_speed_rad_s = o.turbo_speed_rad_s;
  v.lambda = o.lambda;
  v.exhaust_mass_flow_kg_s = o.exhaust_mass_flow_kg_s;
  v.exhaust_T_K = o.exhaust_T_K;
  v.y_O2 = o.exhaust.y_O2;
  v.y_CO2 = o.exhaust.y_CO2;
  v.y_H2O = o.exhaust.y_H2O;
  v.y_N2 = o.exhaust.y_N2;
  v.nox_mass_flow_kg_s = o.nox_mass_flow_kg_s;
  v.nox_mass_kg = o.nox_mass_kg;
  v.heat_to_coolant_W = o.coolant_heat_W;
  v.heat_to_coolant_J = o.coolant_heat_J;
  v.heat_to_oil_W = o.oil_heat_W;
  v.heat_to_oil_J = o.oil_heat_J;
  v.friction_W = o.friction_W;
}

std::string Engine1DModel::boostLimitedMessage(double duration_s) const {
  const Engine1DOutputs& o = engine_.outputs();
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "smoke limiter holding the fuel for %.1f s: lambda %.2f, boost %.0f kPa (target %.0f kPa), "
                "request %.0f Nm, brake torque %.0f Nm at %.0f rpm", duration_s, o.lambda,
                1e-3 * o.boost_pressure_Pa, 1e-3 * o.boost_target_Pa, inputs().torque_request_Nm,
                o.brake_torque_Nm, units::radpsToRpm(inputs().speed_rad_s));
  return buf;
}

void Engine1DModel::diagnosticValues(std::vector<engine::EngineDiagnosticValue>& kv) {
  using K = engine::EngineDiagnosticValue::Kind;
  const Engine1DOutputs& o = engine_.outputs();
  kv.push_back({"gas_steps_window", static_cast<double>(o.gas_steps - gas_steps_at_status_), K::kCount});
  kv.push_back({"gas_steps_total", static_cast<double>(o.gas_steps), K::kCount});
  gas_steps_at_status_ = o.gas_steps;
  kv.push_back({"lambda", o.lambda, K::kNumber});
  kv.push_back({"boost_kpa", 1e-3 * o.boost_pressure_Pa, K::kNumber});
  kv.push_back({"smoke_limited", o.smoke_limited ? 1.0 : 0.0, K::kFlag});
  // its own thread CPU since reset [s]: a measurement, in /diagnostics, never in run.bag
  kv.push_back({"thread_cpu_total_s", o.cpu_time_total_s, K::kNumber});
}

}  // namespace hbt::engine_1d
