#include "battery/node/battery_participant.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/BatteryState.h>

#include "battery/battery_io.hpp"
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
  const auto& v = vehicle_->at(t);
  dcdc_power_W_ = v.dcdc_power_w;
  model_->step(dt_s, batteryInputs(emachine_->at(t), v, ambient_T_K_));
}

void BatteryParticipant::publishOutputs(const ros::Time& t) {
  auto s = boost::make_shared<hybrid_bus_twin::BatteryState>();
  s->header.stamp = t;
  writeBatteryState(model_->outputs(), dcdc_power_W_, *s);
  state_pub_.publish(s);
}

}  // namespace hbt::battery
