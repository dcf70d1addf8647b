// The one conversion between the e-machine's messages and its model (ROS-free): used by the ROS
// participant (node/emachine_participant.cpp) with the generated message types and by the FMU
// export (fmu/emachine_fmu.cpp) with plain structs whose members carry the same field names
// (generated from msg/*.msg, src/fmi/export). Field names and units: msg/EmsCommand.msg,
// msg/BatteryState.msg, msg/CoolingState.msg, msg/EMachineState.msg.
//
//   crank torque request [N m], crank speed [rad/s]  <- the EMS command (at the crank)
//   DC voltage [V]                                   <- the battery's terminal voltage
//   LT coolant [K], engine structure [K]             <- the cooling participant (coolant LT,
//        metal: flywheel housing and crankshaft); without one, both at the ambient air
#pragma once
#include "emachine/emachine_model.hpp"

namespace hbt::emachine {

/// The model's inputs of one step; cooling = nullptr when no cooling participant runs.
template <class EmsCommand, class BatteryState, class CoolingState>
EMachineInputs emachineInputs(const EmsCommand& cmd, const BatteryState& battery, const CoolingState* cooling,
                              double ambient_T_K) {
  EMachineInputs in;
  in.torque_request_Nm = cmd.em_torque_request_nm;
  in.crank_speed_rad_s = cmd.engine_speed_rad_s;
  in.dc_voltage_V = battery.terminal_voltage_v;
  if (cooling) {
    in.coolant_T_K = cooling->coolant_lt_temperature_k;
    in.engine_T_K = cooling->metal_temperature_k;  // flywheel housing and crankshaft: the engine structure
  } else {
    in.coolant_T_K = in.engine_T_K = ambient_T_K;
  }
  return in;
}

/// EMachineState's fields (all but the header) from the model's outputs.
template <class EMachineState>
void writeEMachineState(const EMachineOutputs& o, EMachineState& s) {
  s.torque_nm = o.torque_Nm;
  s.speed_rad_s = o.crank_speed_rad_s;
  s.electrical_power_w = o.dc_power_W;
  s.loss_power_w = o.total_loss_W;
  s.torque_max_nm = o.limits.max_live;
  s.torque_min_nm = o.limits.min_live;
  s.winding_temperature_k = o.winding_T_K;
  s.magnet_temperature_k = o.magnet_T_K;
  s.stator_temperature_k = o.stator_T_K;
  s.torque_request_nm = o.torque_request_Nm;
  s.em_torque_nm = o.em_torque_Nm;
  s.em_speed_rad_s = o.em_speed_rad_s;
  s.dc_voltage_v = o.dc_voltage_V;
  s.dc_current_a = o.dc_current_A;
  s.phase_current_a = o.phase_current_A;
  s.housing_temperature_k = o.housing_T_K;
  s.lt_heat_w = o.lt_heat_W;
  s.engine_heat_w = o.engine_heat_W;
  s.copper_loss_w = o.loss.copper_W;
  s.iron_loss_w = o.loss.iron_W;
  s.rotor_loss_w = o.loss.rotor_W;
  s.mechanical_loss_w = o.loss.bearing_W + o.loss.windage_W;
  s.inverter_loss_w = o.loss.inverter();
  s.ratio_loss_w = o.ratio_loss_W;
  s.torque_max_peak_nm = o.limits.max_peak;
  s.torque_min_peak_nm = o.limits.min_peak;
  s.torque_max_continuous_nm = o.limits.max_cont;
  s.torque_min_continuous_nm = o.limits.min_cont;
  s.derating_factor = o.limits.derating_factor;
  s.mech_motoring_energy_j = o.mech_motoring_J;
  s.mech_generating_energy_j = o.mech_generating_J;
  s.electrical_energy_j = o.dc_J;
  s.electrical_drawn_energy_j = o.dc_drawn_J;
  s.electrical_returned_energy_j = o.dc_returned_J;
  s.copper_loss_energy_j = o.copper_J;
  s.iron_loss_energy_j = o.iron_J;
  s.rotor_loss_energy_j = o.rotor_J;
  s.mechanical_loss_energy_j = o.mechanical_J;
  s.inverter_loss_energy_j = o.inverter_J;
  s.ratio_loss_energy_j = o.ratio_J;
  s.heat_to_coolant_energy_j = o.heat_to_coolant_J;
  s.heat_from_engine_energy_j = o.heat_from_engine_J;
  s.stored_energy_change_j = o.stored_change_J;
  s.energy_residual_j = o.energy_residual_J;
}

}  // namespace hbt::emachine
