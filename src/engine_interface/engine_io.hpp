// The one conversion between the engine's messages and its model interface (ROS-free): used by the
// ROS participant (src/engine/node/engine_participant.cpp, engine_ports.hpp) with the generated
// message types and by the FMU exports (src/engine_map/fmu, src/engine_1d/fmu) with plain structs
// whose members carry the same field names (generated from msg/*.msg, src/fmi/export). Field
// names and units: msg/EngineCommand.msg, msg/CoolingState.msg, msg/AftertreatmentState.msg
// (inputs), msg/EngineState.msg, msg/ExhaustState.msg, msg/EngineHeat.msg (outputs).
//
// Inputs of a step (the policies of engine_model.hpp):
//   ω [rad/s] = engine_speed_rad_s, T_req [N m] = torque_request_nm, fuel = engine_on
//   ambient T [K] = ambient_temperature_k of the command, <= 0 (none): the scenario ambient
//   ambient p [Pa] = ambient_pressure_pa (<= 0: the standard atmosphere, EngineModel::step)
//   coolant T, oil T [K] = coolant_ht_temperature_k, oil_temperature_k of the cooling's state,
//   back-pressure [Pa] = back_pressure_pa of the aftertreatment's state; a participant that does
//   not run (nullptr) gives 0 = none (the model's own warm engine / exhaust system)
// Outputs: EngineOutputs field by field (SI both sides); the mechanical coolant pump turns 1:1
// with the crank (EngineHeat.coolant_pump_*); the ExhaustState fields the engine does not model
// (NOx as ppm, HC, CO) are 0.
#pragma once
#include "engine_interface/engine_model.hpp"

namespace hbt::engine {

/// The model's inputs of one step from the command and the loop states held for it (nullptr:
/// that participant does not run); scenario_ambient_T_K [K] for a command without an ambient.
template <class EngineCommand, class CoolingState, class AftertreatmentState>
EngineInputs engineInputs(const EngineCommand& cmd, const CoolingState* cooling, const AftertreatmentState* ats,
                          double scenario_ambient_T_K) {
  EngineInputs in;
  in.speed_rad_s = cmd.engine_speed_rad_s;
  in.torque_request_Nm = cmd.torque_request_nm;
  in.ambient_T_K = cmd.ambient_temperature_k > 0.0 ? cmd.ambient_temperature_k : scenario_ambient_T_K;
  in.ambient_p_Pa = cmd.ambient_pressure_pa;  // <= 0: the standard atmosphere (EngineModel::step)
  in.fuel_enabled = cmd.engine_on;
  in.coolant_T_K = cooling ? cooling->coolant_ht_temperature_k : 0.0;
  in.oil_T_K = cooling ? cooling->oil_temperature_k : 0.0;
  in.back_pressure_Pa = ats ? ats->back_pressure_pa : 0.0;
  return in;
}

/// EngineState's fields (all but the header).
template <class EngineState>
void writeEngineState(const EngineOutputs& v, EngineState& s) {
  s.engine_speed_rad_s = v.speed_rad_s;
  s.brake_torque_nm = v.brake_torque_Nm;
  s.torque_max_nm = v.max_torque_Nm;
  s.torque_min_nm = v.min_torque_Nm;
  s.fuel_mass_flow_kg_s = v.fuel_mass_flow_kg_s;
  s.fuel_mass_kg = v.fuel_mass_kg;
  s.positive_work_j = v.positive_work_J;
  s.motoring_work_j = v.motoring_work_J;
  s.boost_pressure_pa = v.boost_pressure_Pa;
  s.charge_air_temperature_k = v.charge_air_T_K;
  s.turbo_speed_rad_s = v.turbo_speed_rad_s;
  s.lambda = v.lambda;
  s.coolant_temperature_k = v.coolant_T_K;
  s.oil_temperature_k = v.oil_T_K;
  s.back_pressure_pa = v.back_pressure_Pa;
  s.friction_correction_nm = v.friction_correction_Nm;
  s.pumping_correction_nm = v.pumping_correction_Nm;
}

/// ExhaustState's fields (all but the header).
template <class ExhaustState>
void writeExhaustState(const EngineOutputs& v, ExhaustState& x) {
  x.mass_flow_kg_s = v.exhaust_mass_flow_kg_s;
  x.temperature_k = v.exhaust_T_K;
  x.y_o2 = v.y_O2;
  x.y_co2 = v.y_CO2;
  x.y_h2o = v.y_H2O;
  x.y_n2 = v.y_N2;
  x.nox_mass_flow_kg_s = v.nox_mass_flow_kg_s;
  x.nox_mass_kg = v.nox_mass_kg;
  x.mass_kg = v.exhaust_mass_kg;
  x.mass_temperature_kg_k = v.exhaust_mass_T_kg_K;
  x.temperature_time_k_s = v.exhaust_T_time_K_s;
  x.o2_mass_kg = v.o2_mass_kg;
  x.co2_mass_kg = v.co2_mass_kg;
  x.h2o_mass_kg = v.h2o_mass_kg;
  x.nox_ppm = 0.0;  // not modelled by the engine (the aftertreatment works on mass flows)
  x.hc_mass_flow_kg_s = 0.0;
  x.co_mass_flow_kg_s = 0.0;
  x.hc_mass_kg = 0.0;
  x.co_mass_kg = 0.0;
}

/// EngineHeat's fields (all but the header).
template <class EngineHeat>
void writeEngineHeat(const EngineOutputs& v, EngineHeat& h) {
  h.heat_to_coolant_w = v.heat_to_coolant_W;
  h.heat_to_coolant_j = v.heat_to_coolant_J;
  h.heat_to_oil_w = v.heat_to_oil_W;
  h.heat_to_oil_j = v.heat_to_oil_J;
  h.coolant_pump_speed_rad_s = v.speed_rad_s;  // mechanical pump driven 1:1 by the crank
  h.coolant_pump_angle_rad = v.crank_angle_rad;
}

}  // namespace hbt::engine
