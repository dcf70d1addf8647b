#include "ems/node/ems_participant.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/EmsCommand.h>
#include <hybrid_bus_twin/EngineCommand.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "cosim/param_loader.hpp"

namespace hbt::ems {

void EmsParticipant::configure() {
  EmsParams p;
  ParamSet ps;
  p.declare(ps);
  cosim::applyRosParams(pnh_, ps, configFile());
  p.validate(configFile());
  // The controller's engine model: the map engine's YAML, checked on its own (errors name it).
  const std::string engine_file = cosim::scenarioConfigFile(nh_, "engine_map.yaml");
  std::string pkg;
  nh_.param<std::string>("/scenario/package_dir", pkg, ".");
  engine_map::MapEngineParams mp;
  ParamSet mps;
  mp.declare(mps);
  applyParamFile(mps, engine_file);
  fuel_ = std::make_unique<MapFuelModel>(std::make_unique<engine_map::MapEngine>(mp, pkg));
  // stop-start with either engine: both stop by fuel cut and are cranked by the e-machine
  // through the vehicle's crank dynamics (ems/README.md "Decision per step")
  em_limits_ = std::make_unique<MachineLimitModel>(emachineModel());
  model_ = std::make_unique<EmsModel>(p, *fuel_, em_limits_.get());
  ambient_T_K_ = cosim::scenarioAmbient_K(nh_);
  ambient_p_Pa_ = cosim::scenarioAmbientPressure_Pa(nh_);

  demand_ = &addInputFrom<hybrid_bus_twin::DriverDemand>("vehicle", "driver_demand");
  vehicle_ = &addInputFrom<hybrid_bus_twin::VehicleState>("vehicle", "state");
  em_ = &addInputFrom<hybrid_bus_twin::EMachineState>("emachine", "state");
  battery_ = &addInputFrom<hybrid_bus_twin::BatteryState>("battery", "state");
  if (inScenario("cooling")) cooling_ = &addInputFrom<hybrid_bus_twin::CoolingState>("cooling", "state");
  if (inScenario("aftertreatment")) ats_ = &addInputFrom<hybrid_bus_twin::AftertreatmentState>("aftertreatment", "state");
  if (inScenario("hvac")) hvac_ = &addInputFrom<hybrid_bus_twin::HvacState>("hvac", "state");
  command_pub_ = addOwnOutput<hybrid_bus_twin::EmsCommand>("command");
  engine_pub_ = addOwnOutput<hybrid_bus_twin::EngineCommand>("engine_command");
  last_demand_.ambient_temperature_k = ambient_T_K_;
  last_demand_.ambient_pressure_pa = ambient_p_Pa_;
}

std::unique_ptr<emachine::EMachineModel> EmsParticipant::emachineModel() const {
  // the e-machine's YAML, checked on its own (errors name it), as the e-machine node reads it
  const std::string file = cosim::scenarioConfigFile(nh_, "emachine.yaml");
  emachine::EMachineParams p;
  ParamSet ps;
  p.declare(ps);
  applyParamFile(ps, file);
  p.data.vemp_file = cosim::resolvePackagePath(nh_, p.data.vemp_file);
  return std::make_unique<emachine::EMachineModel>(p, file);
}

void EmsParticipant::step(const ros::Time& t, double dt_s) {
  const auto& d = demand_->at(t);
  const auto& m = em_->at(t);
  const auto& b = battery_->at(t);
  EmsInputs in;
  in.crank_torque_demand_Nm = d.crank_torque_request_nm;
  in.wheel_brake_demand_Nm = d.wheel_brake_request_nm;
  in.engine_speed_rad_s = d.engine_speed_rad_s;
  in.crank_to_wheel_ratio = d.crank_to_wheel_ratio;
  in.stopped = d.stopped;
  in.start_request = d.start_request;
  in.engine_max_torque_Nm = d.engine_max_torque_nm;
  in.engine_min_torque_Nm = d.engine_min_torque_nm;
  in.em_max_torque_Nm = m.torque_max_nm;
  in.em_min_torque_Nm = m.torque_min_nm;
  in.em_winding_T_K = m.winding_temperature_k;
  in.em_magnet_T_K = m.magnet_temperature_k;
  in.dc_voltage_V = b.terminal_voltage_v;
  in.dcdc_power_W = vehicle_->at(t).dcdc_power_w;  // the DC/DC's draw the battery adds this step
  in.soc = b.soc;
  in.battery_T_K = b.cell_temperature_k;
  in.discharge_limit_W = b.discharge_power_limit_w;
  in.charge_limit_W = b.charge_power_limit_w;
  if (cooling_) in.coolant_T_K = cooling_->at(t).coolant_ht_temperature_k;
  if (ats_) in.scr_T_K = ats_->at(t).scr_temperature_k;
  if (hvac_) in.climate_run_request = hvac_->at(t).engine_run_request;
  model_->step(dt_s, in);
  last_demand_ = d;
}

void EmsParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  const EmsDecision& e = model_->decision();
  kv.push_back({"mode", std::to_string(static_cast<int>(e.mode))});
  kv.push_back({"reason", std::to_string(static_cast<int>(e.reason))});
  kv.push_back({"equivalence_factor", formatNumber(e.equivalence_factor)});
  kv.push_back({"engine_on", e.engine_on ? "true" : "false"});
  kv.push_back({"engine_stops", std::to_string(e.engine_stops)});
  kv.push_back({"engine_starts", std::to_string(e.engine_starts)});
  kv.push_back({"warmup_inhibit_time_s", formatNumber(e.warmup_inhibit_time_s)});
}

void EmsParticipant::publishOutputs(const ros::Time& t) {
  const EmsDecision& e = model_->decision();
  hybrid_bus_twin::EmsCommand c;
  c.header.stamp = t;
  c.engine_torque_request_nm = e.engine_torque_request_Nm;
  c.em_torque_request_nm = e.em_torque_request_Nm;
  c.friction_brake_request_nm = e.friction_brake_Nm;
  c.engine_on = e.engine_on;
  c.mode = static_cast<uint8_t>(e.mode);
  c.reason = static_cast<uint8_t>(e.reason);
  c.engine_speed_rad_s = last_demand_.engine_speed_rad_s;
  c.ambient_temperature_k = last_demand_.ambient_temperature_k;
  c.equivalence_factor = e.equivalence_factor;
  c.cost_w = e.cost_W;
  c.warm = e.warm;
  c.engine_stops = e.engine_stops;
  c.engine_starts = e.engine_starts;
  c.stopped_time_s = e.stopped_time_s;
  c.cranking_time_s = e.cranking_time_s;
  c.warmup_inhibit_time_s = e.warmup_inhibit_time_s;
  command_pub_.publish(boost::make_shared<hybrid_bus_twin::EmsCommand>(c));

  hybrid_bus_twin::EngineCommand ec;
  ec.header.stamp = t;
  ec.engine_speed_rad_s = last_demand_.engine_speed_rad_s;
  ec.torque_request_nm = e.engine_torque_request_Nm;
  ec.engine_on = e.engine_on;
  ec.ambient_temperature_k = last_demand_.ambient_temperature_k;
  ec.ambient_pressure_pa = last_demand_.ambient_pressure_pa;
  engine_pub_.publish(boost::make_shared<hybrid_bus_twin::EngineCommand>(ec));
}

}  // namespace hbt::ems
