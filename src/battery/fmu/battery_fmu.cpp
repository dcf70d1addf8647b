// The battery as an FMI 2.0 Co-Simulation FMU (src/fmi/export): BatteryModel
// (../battery_model.hpp) over the variables generated from battery_fmu.yaml. Each fmi2DoStep
// of h does what the participant's step does (node/battery_participant.cpp): the inputs held for
// the step -> batteryInputs -> BatteryModel::step(h) -> writeBatteryState (battery_io.hpp, the
// one conversion both use). The parameters come from resources/battery.yaml (the pack of that
// file; its cell/table_file is read from resources/ under its own file name).
// The warning battery_limited (docs/diagnostics.md): battery.warning.battery_limited is true while
// the participant's warning is raised: BatteryOutputs::request_limited judged by
// cosim::core::Warning (persistence diagnostics/duration_s of resources/battery.yaml,
// BatteryWarnings) at every state time, t = 0 included -- the node's rule, code and value. State
// time t [ns]: the sum of the step sizes.
#include <memory>

#include "battery/battery_io.hpp"
#include "battery/battery_model.hpp"
#include "battery/battery_warnings.hpp"
#include "battery_fmu_variables.hpp"
#include "common/units.hpp"
#include "cosim/core/diagnostics.hpp"
#include "fmi/export/resource_params.hpp"

namespace hbt::fmi::exported {
namespace {

class BatteryFmu : public generated::VariablesModel {
 public:
  explicit BatteryFmu(const std::string& resources_dir)
      : file_(resources_dir + "/battery.yaml"),
        p_(readResourceParams<battery::BatteryParams>(file_)),
        limited_("battery_limited",
                 cosim::core::toNanos(readResourceWarnings<battery::BatteryWarnings>(file_).duration_s)) {
    p_.cell.table_file = resourceFile(resources_dir, p_.cell.table_file);
    model_ = std::make_unique<battery::BatteryModel>(p_, file_);  // reads and checks the cell table
  }

  void initialize() override {
    air_T_K_ = units::celsiusToK(v_.scenario.ambient_temperature_c);
    model_->reset(air_T_K_);  // cold start: cells at ambient, SOC = pack/initial_soc
    t_ns_ = 0;
    writeOutputs();
  }

  void doStep(double h_s) override {
    dcdc_power_W_ = v_.vehicle_state.dcdc_power_w;
    model_->step(h_s, battery::batteryInputs(v_.emachine_state, v_.vehicle_state, air_T_K_));
    t_ns_ += cosim::core::toNanos(h_s);
    writeOutputs();
  }

 private:
  void writeOutputs() {
    battery::writeBatteryState(model_->outputs(), dcdc_power_W_, v_.battery_state);
    limited_.update(t_ns_, model_->outputs().request_limited);
    v_.battery_warning.battery_limited = limited_.active();
  }

  std::string file_;
  battery::BatteryParams p_;
  std::unique_ptr<battery::BatteryModel> model_;
  cosim::core::Warning limited_;  // the node's persistence rule (cosim::Participant::addWarning)
  cosim::core::Nanos t_ns_ = 0;   // state time [ns]
  double air_T_K_ = 0.0, dcdc_power_W_ = 0.0;  // the DC/DC load of the last step [W]
};

}  // namespace

std::unique_ptr<ExportedModel> makeExportedModel(const std::string& resources_dir) {
  return std::make_unique<BatteryFmu>(resources_dir);
}

}  // namespace hbt::fmi::exported
