#include "engine/node/engine_participant.hpp"

#include "common/units.hpp"
#include "cosim/param_loader.hpp"
#include "engine/engine_factory.hpp"

namespace hbt::engine {

void EngineParticipant::configure() {
  std::string pkg, solver;
  nh_.param<std::string>("/scenario/package_dir", pkg, ".");
  nh_.param<std::string>("/scenario/engine_solver", solver, "");  // empty: the YAML's
  ambient_T_K_ = cosim::scenarioAmbient_K(nh_);
  model_ = makeEngineModel(cosim::scenarioEngineModel(nh_), cosim::loadModelParams(pnh_, configFile()),
                           configFile(), pkg, solver);
  model_->reset(ambient_T_K_);  // idle speed, torque 0, standard atmosphere
  // hybrid: the EMS's share of the demand, else the vehicle's
  command_ = &addInputFrom<hybrid_bus_twin::EngineCommand>(inScenario("ems") ? "ems" : "vehicle", "engine_command");
  if (inScenario("cooling")) loops_.cooling = &addInputFrom<hybrid_bus_twin::CoolingState>("cooling", "state");
  if (inScenario("aftertreatment")) loops_.aftertreatment = &addInputFrom<hybrid_bus_twin::AftertreatmentState>("aftertreatment", "state");
  ports_ = EnginePorts(addOwnOutput<hybrid_bus_twin::EngineState>("state"),
                       addOwnOutput<hybrid_bus_twin::ExhaustState>("exhaust"),
                       addOwnOutput<hybrid_bus_twin::EngineHeat>("heat"));
  readWarningThresholds(warnings_, std::string(model_->name()));
  boost_limited_ = &addWarning("boost_limited", warnings_.duration_s);
}

void EngineParticipant::checkWarnings(cosim::core::Nanos t) {
  if (boost_limited_->update(t, model_->boostLimited(warnings_.margin_nm)))
    boost_limited_->setMessage(model_->boostLimitedMessage(warnings_.duration_s));
}

void EngineParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  using K = EngineDiagnosticValue::Kind;
  kv.push_back({"model", model_->name()});
  kv.push_back({"speed_rpm", formatNumber(units::radpsToRpm(model_->outputs().speed_rad_s))});
  kv.push_back({"torque_request_nm", formatNumber(model_->inputs().torque_request_Nm)});
  kv.push_back({"brake_torque_nm", formatNumber(model_->outputs().brake_torque_Nm)});
  std::vector<EngineDiagnosticValue> own;
  model_->diagnosticValues(own);
  for (const auto& v : own)
    kv.push_back({v.key, v.kind == K::kCount  ? std::to_string(static_cast<long long>(v.value))
                         : v.kind == K::kFlag ? (v.value != 0.0 ? "true" : "false")
                                              : formatNumber(v.value)});
}

void EngineParticipant::step(const ros::Time& t, double dt_s) {
  // 0 = none for a loop participant that does not run (engine_io.hpp)
  model_->step(dt_s, engineInputs(command_->at(t), loops_.coolingAt(t), loops_.aftertreatmentAt(t), ambient_T_K_));
}

void EngineParticipant::publishOutputs(const ros::Time& t) { ports_.publish(t, model_->outputs()); }

}  // namespace hbt::engine
