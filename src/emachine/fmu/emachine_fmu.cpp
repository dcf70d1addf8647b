// The e-machine as an FMI 2.0 Co-Simulation FMU (src/fmi/export): EMachineModel
// (../emachine_model.hpp) over the variables generated from emachine_fmu.yaml. Each fmi2DoStep
// of h does what the participant's step does (node/emachine_participant.cpp): the inputs held for
// the step -> emachineInputs -> EMachineModel::step(h) -> writeEMachineState (emachine_io.hpp, the
// one conversion both use). The cooling inputs start at the ambient, as the node's coolant
// without a cooling participant. Parameters: resources/emachine.yaml; its data/vemp_file is read
// from resources/ under its own file name.
// The warning emachine_derating (docs/diagnostics.md): emachine.warning.emachine_derating is true
// while the participant's warning is raised: EMachineWarnings::derating(derating_factor) judged by
// cosim::core::Warning (persistence duration_s) at every state time, t = 0 included, with the
// thresholds of the diagnostics: section of resources/emachine.yaml -- the node's rule, code and
// values. State time t [ns]: the sum of the step sizes.
#include <memory>

#include "common/units.hpp"
#include "cosim/core/diagnostics.hpp"
#include "fmi/export/resource_params.hpp"
#include "emachine/emachine_io.hpp"
#include "emachine/emachine_model.hpp"
#include "emachine/emachine_warnings.hpp"
#include "emachine_fmu_variables.hpp"

namespace hbt::fmi::exported {
namespace {

class EMachineFmu : public generated::VariablesModel {
 public:
  explicit EMachineFmu(const std::string& resources_dir)
      : file_(resources_dir + "/emachine.yaml"),
        p_(readResourceParams<emachine::EMachineParams>(file_)),
        warnings_(readResourceWarnings<emachine::EMachineWarnings>(file_)),
        derating_("emachine_derating", cosim::core::toNanos(warnings_.duration_s)) {
    p_.data.vemp_file = resourceFile(resources_dir, p_.data.vemp_file);
    model_ = std::make_unique<emachine::EMachineModel>(p_, file_);  // reads and checks the .vemp
  }

  void initialize() override {
    ambient_T_K_ = units::celsiusToK(v_.scenario.ambient_temperature_c);
    v_.cooling_state.coolant_lt_temperature_k = v_.cooling_state.metal_temperature_k = ambient_T_K_;
    model_->reset(ambient_T_K_);  // cold start: every node at ambient
    t_ns_ = 0;
    writeOutputs();
  }

  void doStep(double h_s) override {
    model_->step(h_s, emachine::emachineInputs(v_.ems_command, v_.battery_state, &v_.cooling_state, ambient_T_K_));
    t_ns_ += cosim::core::toNanos(h_s);
    writeOutputs();
  }

 private:
  void writeOutputs() {
    emachine::writeEMachineState(model_->outputs(), v_.emachine_state);
    derating_.update(t_ns_, warnings_.derating(model_->outputs().limits.derating_factor));
    v_.emachine_warning.emachine_derating = derating_.active();
  }

  std::string file_;
  emachine::EMachineParams p_;
  std::unique_ptr<emachine::EMachineModel> model_;
  emachine::EMachineWarnings warnings_;
  cosim::core::Warning derating_;  // the node's persistence rule (cosim::Participant::addWarning)
  cosim::core::Nanos t_ns_ = 0;    // state time [ns]
  double ambient_T_K_ = 0.0;
};

}  // namespace

std::unique_ptr<ExportedModel> makeExportedModel(const std::string& resources_dir) {
  return std::make_unique<EMachineFmu>(resources_dir);
}

}  // namespace hbt::fmi::exported
