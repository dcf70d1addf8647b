#include "engine_map/node/engine_map_participant.hpp"

#include "common/units.hpp"
#include "cosim/param_loader.hpp"

namespace hbt::engine_map {

void EngineMapParticipant::configure() {
  MapEngineParams p;
  ParamSet ps;
  p.declare(ps);
  cosim::applyRosParams(pnh_, ps, configFile());
  double ambient_c = 25.0;
  nh_.param("/scenario/ambient_temperature_c", ambient_c, 25.0);
  ambient_T_K_ = units::celsiusToK(ambient_c);
  std::string pkg;
  nh_.param<std::string>("/scenario/package_dir", pkg, ".");
  engine_ = std::make_unique<MapEngine>(p, pkg);
  speed_rad_s_ = engine_->minMapSpeed();
  engine_->reset(speed_rad_s_, 0.0, ambient_T_K_);
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

void EngineMapParticipant::checkWarnings(cosim::core::Nanos t) {
  const MapEngineOutputs& o = engine_->outputs();
  const double m = diagnosticsParams().engine.margin_nm;
  const bool limited = request_Nm_ > o.dynamic_max_torque_Nm + m && o.dynamic_max_torque_Nm < o.max_torque_Nm - m;
  if (boost_limited_->update(t, limited))
    boost_limited_->setMessage(cosim::core::formatText(
        "torque request %.0f Nm above the PT1 (turbo build-up) limit %.0f Nm, full load %.0f Nm, "
        "at %.0f rpm for %.1f s", request_Nm_, o.dynamic_max_torque_Nm, o.max_torque_Nm,
        units::radpsToRpm(speed_rad_s_), diagnosticsParams().engine.duration_s));
}

void EngineMapParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  const MapEngineOutputs& o = engine_->outputs();
  kv.push_back({"speed_rpm", formatNumber(units::radpsToRpm(speed_rad_s_))});
  kv.push_back({"torque_request_nm", formatNumber(request_Nm_)});
  kv.push_back({"brake_torque_nm", formatNumber(o.brake_torque_Nm)});
  kv.push_back({"dynamic_full_load_nm", formatNumber(o.dynamic_max_torque_Nm)});
  kv.push_back({"full_load_nm", formatNumber(o.max_torque_Nm)});
  kv.push_back({"fuel_cut", o.fuel_cut ? "true" : "false"});
}

void EngineMapParticipant::step(const ros::Time& t, double dt_s) {
  const auto& cmd = command_->at(t);
  MapEngineInputs in;
  in.speed_rad_s = cmd.engine_speed_rad_s;
  in.torque_request_Nm = cmd.torque_request_nm;
  in.ambient_T_K = cmd.ambient_temperature_k > 0.0 ? cmd.ambient_temperature_k : ambient_T_K_;
  in.ambient_p_Pa = cmd.ambient_pressure_pa > 0.0 ? cmd.ambient_pressure_pa : 101325.0;
  in.fuel_enabled = cmd.engine_on;
  in.coolant_T_K = coolant_T_K_ = loops_.coolantAt(t, 0.0);
  in.back_pressure_Pa = back_pressure_Pa_ = loops_.backPressureAt(t);
  speed_rad_s_ = in.speed_rad_s;
  request_Nm_ = in.torque_request_Nm;
  engine_->step(dt_s, in);
}

void EngineMapParticipant::publishOutputs(const ros::Time& t) {
  const MapEngineOutputs& o = engine_->outputs();
  cosim::EnginePortValues v;
  v.speed_rad_s = speed_rad_s_;
  v.brake_torque_Nm = o.brake_torque_Nm;
  const double dT = o.friction_correction_Nm + o.pumping_correction_Nm;  // cold oil + back-pressure
  v.max_torque_Nm = engine_->fullLoadTorque(speed_rad_s_) - dT;
  v.min_torque_Nm = engine_->motoringTorque(speed_rad_s_) - dT;
  v.coolant_T_K = coolant_T_K_;
  v.back_pressure_Pa = back_pressure_Pa_;
  v.friction_correction_Nm = o.friction_correction_Nm;
  v.pumping_correction_Nm = o.pumping_correction_Nm;
  v.fuel_mass_flow_kg_s = o.fuel_mass_flow_kg_s;
  v.fuel_mass_kg = o.fuel_mass_kg;
  v.positive_work_J = o.positive_work_J;
  v.motoring_work_J = o.motoring_work_J;
  v.boost_pressure_Pa = o.gas.boost_pressure_Pa;
  v.charge_air_T_K = o.gas.intake_manifold_T_K;
  v.turbo_speed_rad_s = 0.0;  // no turbocharger in the map model
  v.lambda = o.gas.lambda;
  v.exhaust_mass_flow_kg_s = o.gas.exhaust_mass_flow_kg_s;
  v.exhaust_T_K = o.gas.exhaust_T_K > 0.0 ? o.gas.exhaust_T_K : ambient_T_K_;
  v.y_O2 = o.gas.comp.y_O2;
  v.y_CO2 = o.gas.comp.y_CO2;
  v.y_H2O = o.gas.comp.y_H2O;
  v.y_N2 = o.gas.comp.y_N2;
  v.nox_mass_flow_kg_s = o.gas.nox_mass_flow_kg_s;
  v.nox_mass_kg = o.nox_mass_kg;
  v.heat_to_coolant_W = o.gas.coolant_heat_W;
  v.heat_to_coolant_J = o.coolant_heat_J;
  ports_.publish(t, v);
}

}  // namespace hbt::engine_map
