#include "hvac/node/hvac_participant.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/HvacState.h>

#include "common/errors.hpp"
#include "cosim/param_loader.hpp"

namespace hbt::hvac {

void HvacParticipant::configure() {
  HvacParams p;
  ParamSet ps;
  p.declare(ps);
  cosim::applyRosParams(pnh_, ps, configFile());
  ambient_T_K_ = cosim::scenarioAmbient_K(nh_);
  ambient_p_Pa_ = cosim::scenarioAmbientPressure_Pa(nh_);
  double payload_kg = 0.0;
  if (!nh_.getParam("/scenario/payload_kg", payload_kg))
    throw InputError("scenario (launch argument)", "payload", "missing (/scenario/payload_kg)");
  model_ = std::make_unique<HvacModel>(p, payload_kg, configFile());
  // cold: the cabin at ambient (a morning start); warm: in service, at the nearest set point
  model_->reset(cosim::scenarioWarmStart(nh_) ? model_->inServiceCabin_K(ambient_T_K_) : ambient_T_K_);
  heating_setpoint_K_ = p.controller.heating_setpoint_K;
  cooling_setpoint_K_ = p.controller.cooling_setpoint_K;
  cooling_ = &addInputFrom<hybrid_bus_twin::CoolingState>("cooling", "state");
  vehicle_ = &addInputFrom<hybrid_bus_twin::VehicleState>("vehicle", "state");
  state_pub_ = addOwnOutput<hybrid_bus_twin::HvacState>("state");
  readWarningThresholds(warnings_);
  discomfort_ = &addWarning("cabin_discomfort", warnings_.duration_s);
}

void HvacParticipant::step(const ros::Time& t, double dt_s) {
  const auto& c = cooling_->at(t);
  const auto& v = vehicle_->at(t);
  HvacInputs in;
  in.ambient_T_K = ambient_T_K_;
  in.ambient_p_Pa = ambient_p_Pa_;
  in.heater_water_T_K = AuxHeater::waterAtHeater(c.coolant_ht_temperature_k, c.convector_coolant_temperature_k,
                                                 c.heater_valve_open && c.heater_loop_flow_m3_s > 0.0);
  // the convectors' heat: the exact mean of cooling's steps since our last sample (its total)
  in.coolant_heat_W = started_ ? (c.heater_j - prev_heater_J_) / dt_s : c.heater_heat_w;
  prev_heater_J_ = c.heater_j;
  started_ = true;
  in.vehicle_speed_m_s = v.speed_m_s;
  in.engine_running = v.engine_on;
  model_->step(dt_s, in);
}

void HvacParticipant::checkWarnings(cosim::core::Nanos t) {
  const double T = model_->outputs().cabin_T_K;
  const bool cold = T < heating_setpoint_K_ - warnings_.band_K, hot = T > cooling_setpoint_K_ + warnings_.band_K;
  if (discomfort_->update(t, cold || hot))
    discomfort_->setMessage(cosim::core::formatText(
        "cabin %.1f degC more than %.1f K %s its set point for %.0f s", units::kToCelsius(T), warnings_.band_K,
        cold ? "below" : "above", warnings_.duration_s));
}

void HvacParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  const HvacOutputs& o = model_->outputs();
  kv.push_back({"cabin_temperature_c", formatNumber(units::kToCelsius(o.cabin_T_K))});
  kv.push_back({"heating_demand_w", formatNumber(o.heating_demand_W)});
  kv.push_back({"aux_heater_on", o.aux_heater_on ? "true" : "false"});
  kv.push_back({"compressor_power_w", formatNumber(o.compressor_power_W)});
}

void HvacParticipant::publishOutputs(const ros::Time& t) {
  const HvacOutputs& o = model_->outputs();
  auto s = boost::make_shared<hybrid_bus_twin::HvacState>();
  s->header.stamp = t;
  s->cabin_temperature_k = o.cabin_T_K;
  s->heating_demand_w = o.heating_demand_W;
  s->cooling_demand_w = o.cooling_demand_W;
  s->doors_open = o.doors_open;
  s->aux_heater_on = o.aux_heater_on;
  s->engine_run_request = o.engine_run_request;
  s->aux_heater_heat_w = o.aux_heater_heat_W;
  s->aux_heater_fuel_rate_kg_s = o.aux_heater_fuel_kg_s;
  s->ac_cooling_w = o.ac_cooling_W;
  s->compressor_power_w = o.compressor_power_W;
  s->cop = o.cop;
  s->electric_power_w = o.electric_power_W;
  s->coolant_heat_w = o.coolant_heat_W;
  s->people_heat_w = o.people_W;
  s->solar_heat_w = o.solar_W;
  s->body_loss_w = o.body_W;
  s->fresh_air_loss_w = o.fresh_air_W;
  s->door_loss_w = o.doors_W;
  s->coolant_heat_j = o.coolant_heat_J;
  s->people_heat_j = o.people_J;
  s->solar_heat_j = o.solar_J;
  s->ac_cooling_j = o.ac_cooling_J;
  s->body_loss_j = o.body_J;
  s->fresh_air_loss_j = o.fresh_air_J;
  s->door_loss_j = o.doors_J;
  s->stored_energy_change_j = o.stored_change_J;
  s->energy_residual_j = o.energy_residual_J;
  s->aux_heater_heat_j = o.aux_heater_heat_J;
  s->aux_heater_fuel_kg = o.aux_heater_fuel_kg;
  s->compressor_energy_j = o.compressor_energy_J;
  s->electric_energy_j = o.electric_energy_J;
  state_pub_.publish(s);
}

}  // namespace hbt::hvac
