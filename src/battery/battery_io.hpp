// The one conversion between the battery's messages and its model (ROS-free): used by the ROS
// participant (node/battery_participant.cpp) with the generated message types and by the FMU
// export (fmu/battery_fmu.cpp) with plain structs whose members carry the same field names
// (generated from msg/*.msg, src/fmi/export). Field names and units: msg/EMachineState.msg,
// msg/VehicleState.msg, msg/BatteryState.msg.
//
//   P_request [W] = electrical_power_w (e-machine DC power, < 0 charging)
//                   + dcdc_power_w (the vehicle's DC/DC input for the 24 V consumers)
//   air speed over the (roof-mounted) housing [m/s] = speed_m_s of the vehicle
//   air temperature [K] = the scenario's ambient, constant
#pragma once
#include "battery/battery_model.hpp"

namespace hbt::battery {

/// The model's inputs of one step from the e-machine's and the vehicle's messages held for it.
template <class EMachineState, class VehicleState>
BatteryInputs batteryInputs(const EMachineState& e, const VehicleState& v, double air_T_K) {
  BatteryInputs in;
  in.power_request_W = e.electrical_power_w + v.dcdc_power_w;
  in.air_T_K = air_T_K;
  in.air_speed_m_s = v.speed_m_s;  // over the roof-mounted housing
  return in;
}

/// BatteryState's fields (all but the header) from the model's outputs; dcdc_power_W = the
/// DC/DC load included in the last step's request [W].
template <class BatteryState>
void writeBatteryState(const BatteryOutputs& o, double dcdc_power_W, BatteryState& s) {
  s.terminal_voltage_v = o.terminal_voltage_V;
  s.current_a = o.current_A;
  s.soc = o.soc;
  s.cell_temperature_k = o.cell_T_K;
  s.discharge_power_limit_w = o.discharge_power_limit_W;
  s.charge_power_limit_w = o.charge_power_limit_W;
  s.loss_power_w = o.loss_power_W;
  s.ocv_v = o.ocv_V;
  s.rc_voltage_v = o.rc_voltage_V;
  s.power_w = o.power_W;
  s.request_w = o.request_W;
  s.unmet_power_w = o.unmet_power_W;
  s.request_limited = o.request_limited;
  s.dcdc_power_w = dcdc_power_W;
  s.heat_power_w = o.loss_power_W;
  s.heat_to_air_w = o.heat_to_air_W;
  s.ventilation_heat_w = o.ventilation_heat_W;
  s.discharge_current_limit_a = o.discharge_current_limit_A;
  s.charge_current_limit_a = o.charge_current_limit_A;
  s.chemical_energy_j = o.chemical_energy_J;
  s.terminal_energy_j = o.terminal_energy_J;
  s.loss_energy_j = o.loss_energy_J;
  s.ohmic_loss_j = o.ohmic_loss_J;
  s.rc_loss_j = o.rc_loss_J;
  s.heat_to_air_j = o.heat_to_air_J;
  s.ventilation_heat_j = o.ventilation_heat_J;
  s.stored_heat_change_j = o.stored_heat_change_J;
  s.rc_stored_energy_change_j = o.rc_stored_energy_change_J;
  s.energy_residual_j = o.energy_residual_J;
  s.unmet_energy_j = o.unmet_energy_J;
  s.charge_throughput_ah = o.charge_throughput_Ah;
  s.limited_time_s = o.limited_time_s;
  s.housing_temperature_k = o.housing_T_K;
  s.enclosure_air_temperature_k = o.enclosure_air_T_K;
  s.fan_on = o.fan_on;
  s.fan_power_w = o.fan_power_W;
  s.fan_energy_j = o.fan_energy_J;
  s.fan_on_time_s = o.fan_on_time_s;
  s.thermal_conductance_w_k = o.overall_conductance_W_K;
  s.ventilation_conductance_w_k = o.ventilation_conductance_W_K;
}

}  // namespace hbt::battery
