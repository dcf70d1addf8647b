// The battery as an FMI 2.0 Co-Simulation FMU (src/fmi/export): BatteryModel
// (../battery_model.hpp) over the variables generated from battery_fmu.yaml. Each fmi2DoStep
// of h does what the participant's step does (node/battery_participant.cpp): the inputs held for
// the step -> batteryInputs -> BatteryModel::step(h) -> writeBatteryState (battery_io.hpp, the
// one conversion both use). The parameters come from resources/battery.yaml (the pack of that
// file; its cell/table_file is read from resources/ under its own file name).
#include <memory>

#include "battery/battery_io.hpp"
#include "battery/battery_model.hpp"
#include "battery_fmu_variables.hpp"
#include "common/units.hpp"
#include "fmi/export/resource_params.hpp"

namespace hbt::fmi::exported {
namespace {

class BatteryFmu : public generated::VariablesModel {
 public:
  explicit BatteryFmu(const std::string& resources_dir)
      : file_(resources_dir + "/battery.yaml"), p_(readResourceParams<battery::BatteryParams>(file_)) {
    p_.cell.table_file = resourceFile(resources_dir, p_.cell.table_file);
    model_ = std::make_unique<battery::BatteryModel>(p_, file_);  // reads and checks the cell table
  }

  void initialize() override {
    air_T_K_ = units::celsiusToK(v_.scenario.ambient_temperature_c);
    model_->reset(air_T_K_);  // cold start: cells at ambient, SOC = pack/initial_soc
    battery::writeBatteryState(model_->outputs(), dcdc_power_W_, v_.battery_state);
  }

  void doStep(double h_s) override {
    dcdc_power_W_ = v_.vehicle_state.dcdc_power_w;
    model_->step(h_s, battery::batteryInputs(v_.emachine_state, v_.vehicle_state, air_T_K_));
    battery::writeBatteryState(model_->outputs(), dcdc_power_W_, v_.battery_state);
  }

 private:
  std::string file_;
  battery::BatteryParams p_;
  std::unique_ptr<battery::BatteryModel> model_;
  double air_T_K_ = 0.0, dcdc_power_W_ = 0.0;  // the DC/DC load of the last step [W]
};

}  // namespace

std::unique_ptr<ExportedModel> makeExportedModel(const std::string& resources_dir) {
  return std::make_unique<BatteryFmu>(resources_dir);
}

}  // namespace hbt::fmi::exported
