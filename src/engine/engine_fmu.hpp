// The engine participant as an FMI 2.0 Co-Simulation FMU (src/fmi/export), whichever model runs
// it: the map engine (src/engine_map/fmu) and the 1D engine (src/engine_1d/fmu) include this after
// their generated variables header (<model>_fmu_variables.hpp; both specs declare the same
// variables) and hand it their EngineModel built from resources/. ROS-free.
//
// What the engine participant (node/engine_participant.cpp) does, in the FMU's variables:
//   fmi2ExitInitializationMode: EngineModel::reset at scenario.ambient_temperature_c [degC -> K]
//     (idle speed, torque 0, the standard atmosphere), the outputs written;
//   fmi2DoStep(h): engineInputs (engine_interface/engine_io.hpp, the conversion the node uses) of
//     the inputs held for the step -> EngineModel::step(h) -> writeEngineState, writeExhaustState,
//     writeEngineHeat into engine.state.*, engine.exhaust.*, engine.heat.*.
//   the warning boost_limited (docs/diagnostics.md): engine.warning.boost_limited is true while the
//     participant's warning is raised: EngineModel::boostLimited(margin_nm) judged by
//     cosim::core::Warning (persistence duration_s) at every state time, t = 0 included, with the
//     thresholds of the `diagnostics:` section of the model's YAML in resources/ (EngineWarnings)
//     -- the node's rule, code and values. State time t [ns]: the sum of the step sizes.
// Inputs: ems|vehicle.engine_command.* (the EMS's command in the hybrid, the vehicle's otherwise:
// the importer feeds the alternative that runs), cooling.state.coolant_ht_temperature_k,
// cooling.state.oil_temperature_k, aftertreatment.state.back_pressure_pa. The loop inputs start at
// 0 = none: an FMU whose cooling or aftertreatment is not fed runs the model's own warm engine and
// exhaust system, as the node does without those participants.
#pragma once
#include <memory>
#include <utility>

#include "common/units.hpp"
#include "cosim/core/diagnostics.hpp"
#include "engine/engine_warnings.hpp"
#include "engine_interface/engine_io.hpp"
#include "engine_interface/engine_model.hpp"
#include "fmi/export/exported_model.hpp"

namespace hbt::fmi::exported {

class EngineFmu : public generated::VariablesModel {
 public:
  /// `warnings`: the thresholds of the model's YAML (fmi/export/resource_params.hpp readResourceWarnings).
  EngineFmu(std::unique_ptr<engine::EngineModel> model, const engine::EngineWarnings& warnings)
      : model_(std::move(model)),
        warnings_(warnings),
        boost_limited_("boost_limited", cosim::core::toNanos(warnings.duration_s)) {}

  void initialize() override {
    ambient_T_K_ = units::celsiusToK(v_.scenario.ambient_temperature_c);
    model_->reset(ambient_T_K_);  // idle speed, torque 0, standard atmosphere
    t_ns_ = 0;
    writeOutputs();
  }

  void doStep(double h_s) override {
    model_->step(h_s, engine::engineInputs(v_.ems_or_vehicle_engine_command, &v_.cooling_state,
                                           &v_.aftertreatment_state, ambient_T_K_));
    t_ns_ += cosim::core::toNanos(h_s);
    writeOutputs();
  }

 private:
  void writeOutputs() {
    engine::writeEngineState(model_->outputs(), v_.engine_state);
    engine::writeExhaustState(model_->outputs(), v_.engine_exhaust);
    engine::writeEngineHeat(model_->outputs(), v_.engine_heat);
    boost_limited_.update(t_ns_, model_->boostLimited(warnings_.margin_nm));
    v_.engine_warning.boost_limited = boost_limited_.active();
  }

  std::unique_ptr<engine::EngineModel> model_;
  engine::EngineWarnings warnings_;
  cosim::core::Warning boost_limited_;  // the node's persistence rule (cosim::Participant::addWarning)
  cosim::core::Nanos t_ns_ = 0;         // state time [ns]
  double ambient_T_K_ = 0.0;  // the scenario ambient [K]: the start, and a command without one
};

}  // namespace hbt::fmi::exported
