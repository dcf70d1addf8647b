// The e-machine as an FMI 2.0 Co-Simulation FMU (src/fmi/export): EMachineModel
// (../emachine_model.hpp) over the variables generated from emachine_fmu.yaml. Each fmi2DoStep
// of h does what the participant's step does (node/emachine_participant.cpp): the inputs held for
// the step -> emachineInputs -> EMachineModel::step(h) -> writeEMachineState (emachine_io.hpp, the
// one conversion both use). The cooling inputs start at the ambient, as the node's coolant
// without a cooling participant. Parameters: resources/emachine.yaml; its data/vemp_file is read
// from resources/ under its own file name.
#include <memory>

#include "common/units.hpp"
#include "fmi/export/resource_params.hpp"
#include "emachine/emachine_io.hpp"
#include "emachine/emachine_model.hpp"
#include "emachine_fmu_variables.hpp"

namespace hbt::fmi::exported {
namespace {

class EMachineFmu : public generated::VariablesModel {
 public:
  explicit EMachineFmu(const std::string& resources_dir)
      : file_(resources_dir + "/emachine.yaml"), p_(readResourceParams<emachine::EMachineParams>(file_)) {
    p_.data.vemp_file = resourceFile(resources_dir, p_.data.vemp_file);
    model_ = std::make_unique<emachine::EMachineModel>(p_, file_);  // reads and checks the .vemp
  }

  void initialize() override {
    ambient_T_K_ = units::celsiusToK(v_.scenario.ambient_temperature_c);
    v_.cooling_state.coolant_lt_temperature_k = v_.cooling_state.metal_temperature_k = ambient_T_K_;
    model_->reset(ambient_T_K_);  // cold start: every node at ambient
    emachine::writeEMachineState(model_->outputs(), v_.emachine_state);
  }

  void doStep(double h_s) override {
    model_->step(h_s, emachine::emachineInputs(v_.ems_command, v_.battery_state, &v_.cooling_state, ambient_T_K_));
    emachine::writeEMachineState(model_->outputs(), v_.emachine_state);
  }

 private:
  std::string file_;
  emachine::EMachineParams p_;
  std::unique_ptr<emachine::EMachineModel> model_;
  double ambient_T_K_ = 0.0;
};

}  // namespace

std::unique_ptr<ExportedModel> makeExportedModel(const std::string& resources_dir) {
  return std::make_unique<EMachineFmu>(resources_dir);
}

}  // namespace hbt::fmi::exported
