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
// Inputs: ems|vehicle.engine_command.* (the EMS's command in the hybrid, the vehicle's otherwise:
// the importer feeds the alternative that runs), cooling.state.coolant_ht_temperature_k,
// cooling.state.oil_temperature_k, aftertreatment.state.back_pressure_pa. The loop inputs start at
// 0 = none: an FMU whose cooling or aftertreatment is not fed runs the model's own warm engine and
// exhaust system, as the node does without those participants.
#pragma once
#include <memory>
#include <utility>

#include "common/units.hpp"
#include "engine_interface/engine_io.hpp"
#include "engine_interface/engine_model.hpp"
#include "fmi/export/exported_model.hpp"

namespace hbt::fmi::exported {

class EngineFmu : public generated::VariablesModel {
 public:
  explicit EngineFmu(std::unique_ptr<engine::EngineModel> model) : model_(std::move(model)) {}

  void initialize() override {
    ambient_T_K_ = units::celsiusToK(v_.scenario.ambient_temperature_c);
    model_->reset(ambient_T_K_);  // idle speed, torque 0, standard atmosphere
    writeOutputs();
  }

  void doStep(double h_s) override {
    model_->step(h_s, engine::engineInputs(v_.ems_or_vehicle_engine_command, &v_.cooling_state,
                                           &v_.aftertreatment_state, ambient_T_K_));
    writeOutputs();
  }

 private:
  void writeOutputs() {
    engine::writeEngineState(model_->outputs(), v_.engine_state);
    engine::writeExhaustState(model_->outputs(), v_.engine_exhaust);
    engine::writeEngineHeat(model_->outputs(), v_.engine_heat);
  }

  std::unique_ptr<engine::EngineModel> model_;
  double ambient_T_K_ = 0.0;  // the scenario ambient [K]: the start, and a command without one
};

}  // namespace hbt::fmi::exported
