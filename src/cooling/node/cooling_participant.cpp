#include "cooling/node/cooling_participant.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/CoolingState.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "cosim/param_loader.hpp"

namespace hbt::cooling {

void CoolingParticipant::configure() {
  CoolingParams p;
  ParamSet ps;
  p.declare(ps);
  cosim::applyRosParams(pnh_, ps, configFile());
  ambient_T_K_ = cosim::scenarioAmbient_K(nh_);
  ambient_p_Pa_ = cosim::scenarioAmbientPressure_Pa(nh_);
  model_ = std::make_unique<CoolingModel>(p, configFile());
  if (cosim::scenarioWarmStart(nh_))  // a bus mid-shift: warm_start/ of config/cooling.yaml
    model_->reset(ambient_T_K_, p.warm_start.metal_K, p.warm_start.coolant_ht_K,
                  ambient_T_K_ + p.warm_start.coolant_lt_above_ambient_K, p.warm_start.oil_K);
  else
    model_->reset(ambient_T_K_);  // cold start: metal, oil, HT and LT coolant at ambient
  last_in_.ambient_T_K = ambient_T_K_;
  last_in_.ambient_p_Pa = ambient_p_Pa_;
  heat_ = &addInputFrom<hybrid_bus_twin::EngineHeat>("engine", "heat");
  vehicle_ = &addInputFrom<hybrid_bus_twin::VehicleToCooling>("vehicle", "to_cooling");
  if (inScenario("emachine")) emachine_ = &addInputFrom<hybrid_bus_twin::EMachineState>("emachine", "state");
  if (inScenario("hvac")) hvac_ = &addInputFrom<hybrid_bus_twin::HvacState>("hvac", "state");
  state_pub_ = addOwnOutput<hybrid_bus_twin::CoolingState>("state");
  readWarningThresholds(warnings_);
  warnings_.validate(configFile());
  overheat_ = &addWarning("coolant_overheat", warnings_.duration_s);
  overheat_level_ = std::make_unique<cosim::core::Hysteresis>(warnings_.overheat_c, warnings_.overheat_release_c);
}

void CoolingParticipant::checkWarnings(cosim::core::Nanos t) {
  const CoolingOutputs& o = model_->outputs();
  const double T_c = units::kToCelsius(o.coolant_ht_T_K);
  const CoolingWarnings& d = warnings_;
  if (overheat_->update(t, overheat_level_->update(T_c)))
    overheat_->setMessage(cosim::core::formatText(
        "HT coolant %.1f degC above %.1f degC for %.1f s (thermostat %.2f open, fan engaged %.2f)",
        T_c, d.overheat_c, d.duration_s, o.thermostat_opening, o.fan_engagement));
}

void CoolingParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  const CoolingOutputs& o = model_->outputs();
  kv.push_back({"coolant_ht_temperature_c", formatNumber(units::kToCelsius(o.coolant_ht_T_K))});
  kv.push_back({"coolant_lt_temperature_c", formatNumber(units::kToCelsius(o.coolant_lt_T_K))});
  kv.push_back({"thermostat_opening", formatNumber(o.thermostat_opening)});
  kv.push_back({"fan_engagement", formatNumber(o.fan_engagement)});
  kv.push_back({"fan_drive_power_w", formatNumber(o.fan_drive_power_W)});
}

void CoolingParticipant::step(const ros::Time& t, double dt_s) {
  const auto& h = heat_->at(t);
  const auto& v = vehicle_->at(t);
  CoolingTotals now;  // cumulative since t = 0: their step means (step_inputs.hpp)
  now.engine_heat_J = h.heat_to_coolant_j;
  now.engine_oil_heat_J = h.heat_to_oil_j;
  now.pump_angle_rad = h.coolant_pump_angle_rad;
  CoolingInputs point;  // the sample's own values: the first step and what is not averaged
  point.engine_heat_W = h.heat_to_coolant_w;
  point.engine_oil_heat_W = h.heat_to_oil_w;
  point.pump_speed_rad_s = h.coolant_pump_speed_rad_s;
  point.vehicle_speed_m_s = v.vehicle_speed_m_s;
  point.ambient_T_K = v.ambient_temperature_k > 0.0 ? v.ambient_temperature_k : ambient_T_K_;
  point.ambient_p_Pa = ambient_p_Pa_;
  point.fan_demand = v.fan_demand;
  now.gearbox_cooler_heat_J = v.gearbox_cooler_heat_j;  // the AT's oil cooler (first step: 0 W)
  if (emachine_) {  // e-machine + inverter heat into the LT coolant (hybrid)
    const auto& m = emachine_->at(t);
    now.lt_heat_J = m.heat_to_coolant_energy_j;
    point.lt_heat_W = m.lt_heat_w;
    now.em_engine_heat_J = m.heat_from_engine_energy_j;  // out of the engine metal
    point.em_engine_heat_W = m.engine_heat_w;
  }
  if (hvac_) {  // the cabin's demand, the fuel-fired heater's heat (hvac:=on)
    const auto& a = hvac_->at(t);
    point.cabin_from_hvac = true;
    point.cabin_heat_demand_W = a.heating_demand_w;
    point.cabin_T_K = a.cabin_temperature_k;
    point.aux_heater_heat_W = a.aux_heater_heat_w;
    now.aux_heater_heat_J = a.aux_heater_heat_j;
  }
  const CoolingInputs in = inputs_.next(now, point, dt_s);
  model_->step(dt_s, in);
  last_in_ = in;
}

void CoolingParticipant::publishOutputs(const ros::Time& t) {
  const CoolingOutputs& o = model_->outputs();
  hybrid_bus_twin::CoolingState s;
  s.header.stamp = t;
  s.coolant_ht_temperature_k = o.coolant_ht_T_K;
  s.coolant_lt_temperature_k = o.coolant_lt_T_K;
  s.thermostat_opening = o.thermostat_opening;
  s.fan_speed_rad_s = o.fan_speed_rad_s;
  s.fan_power_w = o.fan_power_W;
  s.pump_power_w = o.pump_power_W;
  s.lt_pump_speed_rad_s = o.lt_pump_speed_rad_s;
  s.metal_temperature_k = o.metal_T_K;
  s.oil_temperature_k = o.oil_T_K;
  s.oil_cooler_heat_w = o.oil_cooler_heat_W;
  s.ht_air_in_temperature_k = o.ht_air_in_T_K;
  s.fan_drive_power_w = o.fan_drive_power_W;
  s.fan_engagement = o.fan_engagement;
  s.fan_pressure_rise_pa = o.fan_pressure_rise_Pa;
  s.air_volume_flow_m3_s = o.air_volume_flow_m3_s;
  s.air_mass_flow_kg_s = o.air_mass_flow_kg_s;
  s.coolant_flow_m3_s = o.coolant_flow_m3_s;
  s.radiator_coolant_flow_m3_s = o.radiator_coolant_flow_m3_s;
  s.lt_pump_power_w = o.lt_pump_power_W;
  s.lt_pump_hydraulic_power_w = o.lt_pump_hydraulic_power_W;
  s.radiator_ht_heat_w = o.radiator_ht_heat_W;
  s.radiator_lt_heat_w = o.radiator_lt_heat_W;
  s.heater_heat_w = o.heater_heat_W;
  s.aux_heater_heat_w = o.aux_heater_heat_W;
  s.surface_loss_w = o.surface_loss_W;
  s.engine_heat_w = last_in_.engine_heat_W;
  s.engine_oil_heat_w = last_in_.engine_oil_heat_W;
  s.lt_heat_w = last_in_.lt_heat_W;
  s.em_engine_heat_w = last_in_.em_engine_heat_W;
  s.fan_energy_j = o.fan_energy_J;
  s.fan_drive_energy_j = o.fan_drive_energy_J;
  s.pump_energy_j = o.pump_energy_J;
  s.lt_pump_energy_j = o.lt_pump_energy_J;
  s.engine_heat_j = o.engine_heat_J;
  s.engine_oil_heat_j = o.engine_oil_heat_J;
  s.oil_cooler_heat_j = o.oil_cooler_J;
  s.lt_heat_j = o.lt_heat_J;
  s.em_engine_heat_j = o.em_engine_heat_J;
  s.radiator_ht_j = o.radiator_ht_J;
  s.radiator_lt_j = o.radiator_lt_J;
  s.heater_j = o.heater_J;
  s.aux_heater_j = o.aux_heater_J;
  s.gearbox_cooler_heat_j = o.gearbox_cooler_J;
  s.surface_loss_j = o.surface_loss_J;
  s.stored_energy_change_j = o.stored_change_J;
  s.energy_residual_j = o.energy_residual_J;
  s.warmup_time_s = o.warmup_time_s;
  s.radiator_coolant_temperature_k = o.radiator_coolant_T_K;
  s.convector_coolant_temperature_k = o.convector_coolant_T_K;
  s.heater_valve_open = o.heater_valve_open;
  s.heater_loop_flow_m3_s = o.heater_loop_flow_m3_s;
  s.electric_pump_power_w = o.electric_pump_power_W;
  s.electric_pump_energy_j = o.electric_pump_energy_J;
  state_pub_.publish(boost::make_shared<hybrid_bus_twin::CoolingState>(s));
}

}  // namespace hbt::cooling
