#include "emachine/node/emachine_participant.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/EMachineState.h>

#include "common/errors.hpp"
#include "emachine/emachine_io.hpp"
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
  if (derating_->update(t, warnings_.derating(o.limits.derating_factor)))
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
  const hybrid_bus_twin::CoolingState* cooling = cooling_ ? &cooling_->at(t) : nullptr;
  model_->step(dt_s, emachineInputs(ems_->at(t), battery_->at(t), cooling, ambient_T_K_));
}

void EMachineParticipant::publishOutputs(const ros::Time& t) {
  auto s = boost::make_shared<hybrid_bus_twin::EMachineState>();
  s->header.stamp = t;
  writeEMachineState(model_->outputs(), *s);
  state_pub_.publish(s);
}

}  // namespace hbt::emachine
