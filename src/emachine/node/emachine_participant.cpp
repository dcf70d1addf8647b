#include "emachine/node/emachine_participant.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/EMachineState.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "cosim/param_loader.hpp"

namespace hbt::emachine {

void EMachineParticipant::configure() {
  EMachineParams p;
  ParamSet ps;
  p.declare(ps);
  cosim::applyRosParams(pnh_, ps, configFile());
  p.data.vemp_file = cosim::resolvePackagePath(nh_, p.data.vemp_file);
  ambient_T_K_ = cosim::scenarioAmbient_K(nh_);
  model_ = std::make_unique<EMachineModel>(p, configFile());
  model_->reset(ambient_T_K_);  // cold start: every node at ambient
  ems_ = &addInputFrom<hybrid_bus_twin::EmsCommand>("ems", "command");
  battery_ = &addInputFrom<hybrid_bus_twin::BatteryState>("battery", "state");
  if (inScenario("cooling")) cooling_ = &addInputFrom<hybrid_bus_twin::CoolingState>("cooling", "state");
  state_pub_ = addOwnOutput<hybrid_bus_twin::EMachineState>("state");
  readWarningThresholds(warnings_);
  derating_ = &addWarning("emachine_derating", warnings_.duration_s);
}

void EMachineParticipant::checkWarnings(cosim::core::Nanos t) {
  const EMachineOutputs& o = model_->outputs();
  if (derating_->update(t, o.limits.derating_factor < warnings_.derating_factor_below))
    derating_->setMessage(cosim::core::formatText(
        "thermal derating: live torque limit %.3f of the peak (winding %.1f degC, magnet %.1f degC)",
        o.limits.derating_factor, units::kToCelsius(o.winding_T_K), units::kToCelsius(o.magnet_T_K)));
}

void EMachineParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  const EMachineOutputs& o = model_->outputs();
  kv.push_back({"derating_factor", formatNumber(o.limits.derating_factor)});
  kv.push_back({"torque_max_live_nm", formatNumber(o.limits.max_live)});
  kv.push_back({"torque_min_live_nm", formatNumber(o.limits.min_live)});
  kv.push_back({"winding_temperature_c", formatNumber(units::kToCelsius(o.winding_T_K))});
  kv.push_back({"magnet_temperature_c", formatNumber(units::kToCelsius(o.magnet_T_K))});
}

void EMachineParticipant::step(const ros::Time& t, double dt_s) {
  const auto& cmd = ems_->at(t);
  EMachineInputs in;
  in.torque_request_Nm = cmd.em_torque_request_nm;
  in.crank_speed_rad_s = cmd.engine_speed_rad_s;
  in.dc_voltage_V = battery_->at(t).terminal_voltage_v;
  if (cooling_) {
    const auto& c = cooling_->at(t);
    in.coolant_T_K = c.coolant_lt_temperature_k;
    in.engine_T_K = c.metal_temperature_k;  // flywheel housing and crankshaft: the engine structure
  } else {
    in.coolant_T_K = in.engine_T_K = ambient_T_K_;
  }
  model_->step(dt_s, in);
}

void EMachineParticipant::publishOutputs(const ros::Time& t) {
  const EMachineOutputs& o = model_->outputs();
  hybrid_bus_twin::EMachineState s;
  s.header.stamp = t;
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
  state_pub_.publish(boost::make_shared<hybrid_bus_twin::EMachineState>(s));
}

}  // namespace hbt::emachine
