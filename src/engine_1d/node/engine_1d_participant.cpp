#include "engine_1d/node/engine_1d_participant.hpp"

#include "common/errors.hpp"
#include "common/units.hpp"
#include "cosim/param_loader.hpp"

namespace hbt::engine1d {

void Engine1DParticipant::configure() {
  std::string pkg;
  nh_.param<std::string>("/scenario/package_dir", pkg, ".");
  // like every participant: its YAML from the private namespace (the launch loaded it), less
  // the node's own keys; the sub-files it names are read beside that YAML
  ParamSource own = cosim::loadParamSource(pnh_, "", configFile());
  for (auto it = own.values.begin(); it != own.values.end();) {
    const std::string& k = it->first;
    const bool node_key = k == "config_file" || k == "solver" || k.rfind("loops/", 0) == 0 || k.rfind("cosim/", 0) == 0;
    it = node_key ? own.values.erase(it) : std::next(it);
  }
  if (own.values.empty()) throw InputError(configFile(), "engine_1d", "no parameters: the file is empty or was not loaded");
  Engine1DParams p = Engine1DParams::load(own, configFile());
  std::string solver;
  if (pnh_.getParam("solver", solver) && !solver.empty()) {
    p.engine.solver = solver;
    p.validate();
  }
  double ambient_c = 25.0;
  nh_.param("/scenario/ambient_temperature_c", ambient_c, 25.0);
  ambient_T_K_ = units::celsiusToK(ambient_c);
  engine_ = std::make_unique<Engine1D>(p, pkg);
  speed_rad_s_ = units::rpmToRadps(700.0);
  engine_->reset(speed_rad_s_, 0.0, ambient_T_K_, 101325.0, coolant_T_K_);
  bool hybrid = false;  // hybrid: the EMS's share of the demand (loops/ems), else the vehicle's
  pnh_.param("loops/ems", hybrid, false);
  command_ = &addInput<hybrid_bus_twin::EngineCommand>(hybrid ? "/ems/engine_command" : "/vehicle/engine_command");
  bool cooling = false, ats = false;
  pnh_.param("loops/cooling", cooling, false);
  pnh_.param("loops/aftertreatment", ats, false);
  if (cooling) loops_.cooling = &addInput<hybrid_bus_twin::CoolingState>("/cooling/state");
  if (ats) loops_.aftertreatment = &addInput<hybrid_bus_twin::AftertreatmentState>("/aftertreatment/state");
  ports_ = cosim::EnginePorts(addOutput<hybrid_bus_twin::EngineState>("/engine/state"),
                              addOutput<hybrid_bus_twin::ExhaustState>("/engine/exhaust"),
                              addOutput<hybrid_bus_twin::EngineHeat>("/engine/heat"));
  boost_limited_ = &addWarning("boost_limited", diagnosticsParams().engine.duration_s);
}

void Engine1DParticipant::checkWarnings(cosim::core::Nanos t) {
  const Engine1DOutputs& o = engine_->outputs();
  if (boost_limited_->update(t, o.smoke_limited))
    boost_limited_->setMessage(cosim::core::formatText(
        "smoke limiter holding the fuel for %.1f s: lambda %.2f, boost %.0f kPa (target %.0f kPa), "
        "request %.0f Nm, brake torque %.0f Nm at %.0f rpm", diagnosticsParams().engine.duration_s,
        o.lambda, 1e-3 * o.boost_pressure_Pa, 1e-3 * o.boost_target_Pa, request_Nm_,
        o.brake_torque_Nm, units::radpsToRpm(speed_rad_s_)));
}

void Engine1DParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  const Engine1DOutputs& o = engine_->outputs();
  kv.push_back({"gas_steps_window", std::to_string(o.gas_steps - gas_steps_at_status_)});
  kv.push_back({"gas_steps_total", std::to_string(o.gas_steps)});
  gas_steps_at_status_ = o.gas_steps;
  kv.push_back({"speed_rpm", formatNumber(units::radpsToRpm(speed_rad_s_))});
  kv.push_back({"torque_request_nm", formatNumber(request_Nm_)});
  kv.push_back({"brake_torque_nm", formatNumber(o.brake_torque_Nm)});
  kv.push_back({"lambda", formatNumber(o.lambda)});
  kv.push_back({"boost_kpa", formatNumber(1e-3 * o.boost_pressure_Pa)});
  kv.push_back({"smoke_limited", o.smoke_limited ? "true" : "false"});
}

void Engine1DParticipant::step(const ros::Time& t, double dt_s) {
  const auto& cmd = command_->at(t);
  Engine1DInputs in;
  in.speed_rad_s = cmd.engine_speed_rad_s;
  in.torque_request_Nm = cmd.torque_request_nm;
  in.ambient_T_K = cmd.ambient_temperature_k > 0.0 ? cmd.ambient_temperature_k : ambient_T_K_;
  in.ambient_p_Pa = cmd.ambient_pressure_pa > 0.0 ? cmd.ambient_pressure_pa : 101325.0;
  // <= 0 (no ATS node): the engine's own documented orifice model of the exhaust system
  in.back_pressure_Pa = back_pressure_Pa_ = loops_.backPressureAt(t);
  in.coolant_T_K = used_coolant_T_K_ = loops_.coolantAt(t, coolant_T_K_);
  in.fuel_enabled = cmd.engine_on;
  speed_rad_s_ = in.speed_rad_s;
  request_Nm_ = in.torque_request_Nm;
  engine_->step(dt_s, in);
}

void Engine1DParticipant::publishOutputs(const ros::Time& t) {
  const Engine1DOutputs& o = engine_->outputs();
  cosim::EnginePortValues v;
  v.speed_rad_s = speed_rad_s_;
  v.brake_torque_Nm = o.brake_torque_Nm;
  v.max_torque_Nm = engine_->fullLoadTorque(speed_rad_s_);
  v.min_torque_Nm = engine_->motoringTorque(speed_rad_s_);
  v.fuel_mass_flow_kg_s = o.fuel_mass_flow_kg_s;
  v.fuel_mass_kg = o.fuel_mass_kg;
  v.positive_work_J = o.positive_work_J;
  v.motoring_work_J = o.motoring_work_J;
  v.boost_pressure_Pa = o.boost_pressure_Pa;
  v.charge_air_T_K = o.intake_manifold_T_K;
  v.turbo_speed_rad_s = o.turbo_speed_rad_s;
  v.lambda = o.lambda;
  v.cpu_time_s = o.cpu_time_s;
  v.exhaust_mass_flow_kg_s = o.exhaust_mass_flow_kg_s;
  v.exhaust_T_K = o.exhaust_T_K > 0.0 ? o.exhaust_T_K : ambient_T_K_;
  v.y_O2 = o.exhaust.y_O2;
  v.y_CO2 = o.exhaust.y_CO2;
  v.y_H2O = o.exhaust.y_H2O;
  v.y_N2 = o.exhaust.y_N2;
  v.nox_mass_flow_kg_s = o.nox_mass_flow_kg_s;
  v.nox_mass_kg = o.nox_mass_kg;
  v.heat_to_coolant_W = o.coolant_heat_W;
  v.coolant_T_K = loops_.cooling ? used_coolant_T_K_ : 0.0;
  v.back_pressure_Pa = back_pressure_Pa_;
  v.heat_to_coolant_J = o.coolant_heat_J;
  ports_.publish(t, v);
}

}  // namespace hbt::engine1d
