#include "battery/node/battery_participant.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/BatteryState.h>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "cosim/param_loader.hpp"

namespace hbt::battery {

void BatteryParticipant::configure() {
  BatteryParams p;
  ParamSet ps;
  p.declare(ps);
  cosim::applyRosParams(pnh_, ps, configFile());
  readPackSet(p);
  p.cell.table_file = cosim::resolvePackagePath(nh_, p.cell.table_file);
  ambient_T_K_ = cosim::scenarioAmbient_K(nh_);
  model_ = std::make_unique<BatteryModel>(p, configFile());
  if (cosim::scenarioWarmStart(nh_))  // mid-shift: cells above the air (warm_start/), SOC = pack/initial_soc
    model_->resetWarm(ambient_T_K_ + p.thermal.warm_cell_above_ambient_K,
                      ambient_T_K_ + p.thermal.warm_housing_above_ambient_K);
  else
    model_->reset(ambient_T_K_);  // cold start: cells at ambient, SOC = pack/initial_soc
  emachine_ = &addInputFrom<hybrid_bus_twin::EMachineState>("emachine", "state");
  vehicle_ = &addInputFrom<hybrid_bus_twin::VehicleState>("vehicle", "state");
  state_pub_ = addOwnOutput<hybrid_bus_twin::BatteryState>("state");
  BatteryWarnings warnings;  // diagnostics/ of config/battery.yaml
  readWarningThresholds(warnings);
  limited_ = &addWarning("battery_limited", warnings.duration_s);
}

// The pack set (launch argument pack, /scenario/battery_pack): config/battery_pack/<name>.yaml
// replaces the groups pack/ and housing/ of config/battery.yaml; every key of both groups is
// required in that file, errors name it and the key. Empty: battery.yaml's own pack.
void BatteryParticipant::readPackSet(BatteryParams& p) {
  std::string name;
  if (!nh_.getParam("/scenario/battery_pack", name) || name.empty()) return;
  ParamSet ps;
  p.declarePackSet(ps);
  applyParamFile(ps, cosim::scenarioConfigFile(nh_, "battery_pack/" + name + ".yaml"));
}

void BatteryParticipant::checkWarnings(cosim::core::Nanos t) {
  const BatteryOutputs& o = model_->outputs();
  if (limited_->update(t, o.request_limited))
    limited_->setMessage(cosim::core::formatText(
        "power request %.2f kW outside the limits (discharge %.2f kW, charge %.2f kW): %.2f kW "
        "unmet at SOC %.3f, cells %.1f degC", 1e-3 * o.request_W, 1e-3 * o.discharge_power_limit_W,
        1e-3 * o.charge_power_limit_W, 1e-3 * o.unmet_power_W, o.soc, units::kToCelsius(o.cell_T_K)));
}

void BatteryParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  const BatteryOutputs& o = model_->outputs();
  kv.push_back({"soc", formatNumber(o.soc)});
  kv.push_back({"cell_temperature_c", formatNumber(units::kToCelsius(o.cell_T_K))});
  kv.push_back({"discharge_power_limit_kw", formatNumber(1e-3 * o.discharge_power_limit_W)});
  kv.push_back({"charge_power_limit_kw", formatNumber(1e-3 * o.charge_power_limit_W)});
  kv.push_back({"limited_time_s", formatNumber(o.limited_time_s)});
  kv.push_back({"housing_temperature_c", formatNumber(units::kToCelsius(o.housing_T_K))});
  kv.push_back({"fan_on", o.fan_on ? "true" : "false"});
}

void BatteryParticipant::step(const ros::Time& t, double dt_s) {
  const auto& e = emachine_->at(t);
  BatteryInputs in;
  dcdc_power_W_ = vehicle_->at(t).dcdc_power_w;
  in.power_request_W = e.electrical_power_w + dcdc_power_W_;
  in.air_T_K = ambient_T_K_;
  in.air_speed_m_s = vehicle_->at(t).speed_m_s;  // over the roof-mounted housing
  model_->step(dt_s, in);
}

void BatteryParticipant::publishOutputs(const ros::Time& t) {
  const BatteryOutputs& o = model_->outputs();
  hybrid_bus_twin::BatteryState s;
  s.header.stamp = t;
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
  s.dcdc_power_w = dcdc_power_W_;
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
  state_pub_.publish(boost::make_shared<hybrid_bus_twin::BatteryState>(s));
}

}  // namespace hbt::battery
