#include "engine_map/node/engine_map_participant.hpp"

#include <hybrid_bus_twin/EngineHeat.h>
#include <hybrid_bus_twin/EngineState.h>
#include <hybrid_bus_twin/ExhaustState.h>

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
  command_ = &addInput<hybrid_bus_twin::EngineCommand>("/vehicle/engine_command");
  state_pub_ = addOutput<hybrid_bus_twin::EngineState>("/engine/state");
  exhaust_pub_ = addOutput<hybrid_bus_twin::ExhaustState>("/engine/exhaust");
  heat_pub_ = addOutput<hybrid_bus_twin::EngineHeat>("/engine/heat");
}

void EngineMapParticipant::step(const ros::Time& t, double dt_s) {
  const auto& cmd = command_->at(t);
  MapEngineInputs in;
  in.speed_rad_s = cmd.engine_speed_rad_s;
  in.torque_request_Nm = cmd.torque_request_nm;
  in.ambient_T_K = cmd.ambient_temperature_k > 0.0 ? cmd.ambient_temperature_k : ambient_T_K_;
  in.ambient_p_Pa = cmd.ambient_pressure_pa > 0.0 ? cmd.ambient_pressure_pa : 101325.0;
  in.fuel_enabled = cmd.engine_on;
  speed_rad_s_ = in.speed_rad_s;
  engine_->step(dt_s, in);
}

void EngineMapParticipant::publishOutputs(const ros::Time& t) {
  const MapEngineOutputs& o = engine_->outputs();
  hybrid_bus_twin::EngineState s;
  s.header.stamp = t;
  s.engine_speed_rad_s = speed_rad_s_;
  s.brake_torque_nm = o.brake_torque_Nm;
  s.torque_max_nm = engine_->fullLoadTorque(speed_rad_s_);
  s.torque_min_nm = engine_->motoringTorque(speed_rad_s_);
  s.fuel_mass_flow_kg_s = o.fuel_mass_flow_kg_s;
  s.fuel_mass_kg = o.fuel_mass_kg;
  s.boost_pressure_pa = o.gas.boost_pressure_Pa;
  s.turbo_speed_rad_s = 0.0;  // no turbocharger in the map model
  s.lambda = o.gas.lambda;
  s.positive_work_j = o.positive_work_J;
  s.motoring_work_j = o.motoring_work_J;
  state_pub_.publish(s);

  hybrid_bus_twin::ExhaustState x;
  x.header.stamp = t;
  x.mass_flow_kg_s = o.gas.exhaust_mass_flow_kg_s;
  x.temperature_k = o.gas.exhaust_T_K > 0.0 ? o.gas.exhaust_T_K : ambient_T_K_;
  x.y_o2 = o.gas.comp.y_O2;
  x.y_co2 = o.gas.comp.y_CO2;
  x.y_h2o = o.gas.comp.y_H2O;
  x.y_n2 = o.gas.comp.y_N2;
  x.nox_mass_flow_kg_s = o.gas.nox_mass_flow_kg_s;
  x.nox_mass_kg = o.nox_mass_kg;
  exhaust_pub_.publish(x);

  hybrid_bus_twin::EngineHeat h;
  h.header.stamp = t;
  h.heat_to_coolant_w = o.gas.coolant_heat_W;
  h.coolant_pump_speed_rad_s = speed_rad_s_;  // mechanical pump driven 1:1 by the crank
  heat_pub_.publish(h);
}

}  // namespace hbt::engine_map
