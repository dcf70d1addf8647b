// ROS bridge of the 48 V P1 e-machine: converts messages and parameters, nothing else. Model:
// hbt::emachine::EMachineModel (../emachine_model.hpp).
//
// Inputs  (stamped t_k): /ems/command (EmsCommand: em_torque_request_nm, engine_speed_rad_s --
//                        both at the crank), /battery/state (BatteryState: terminal_voltage_v),
//                        /cooling/state (CoolingState: coolant_lt_temperature_k) only when the
//                        cooling participant runs; otherwise the LT coolant is at
//                        the ambient temperature.
// Output  (stamped t_k): /emachine/state (EMachineState): delivered crank torque, DC power,
//                        losses, temperatures, live (derated) / peak / continuous crank torque
//                        limits, lt_heat_w for the cooling node, cumulative energies.
// Parameters: private namespace = config/emachine.yaml (data/vemp_file relative to the package,
// /scenario/package_dir); /scenario/ambient_temperature_c (initial state: every node at ambient,
// cold start; coolant without a cooling participant).
// Diagnostics (docs/diagnostics.md): warning emachine_derating (derating_factor below
// diagnostics/derating_factor_below for diagnostics/duration_s of config/emachine.yaml); key/values
// derating factor, live limits, winding/magnet temperatures.
#pragma once
#include <hybrid_bus_twin/BatteryState.h>
#include <hybrid_bus_twin/CoolingState.h>
#include <hybrid_bus_twin/EmsCommand.h>

#include <memory>

#include "cosim/participant.hpp"
#include "emachine/emachine_warnings.hpp"
#include "emachine/emachine_model.hpp"

namespace hbt::emachine {

class EMachineParticipant : public cosim::Participant {
 public:
  EMachineParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void checkWarnings(cosim::core::Nanos t) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;

 private:
  std::unique_ptr<EMachineModel> model_;
  EMachineWarnings warnings_;  // diagnostics/ of config/emachine.yaml
  cosim::Input<hybrid_bus_twin::EmsCommand>* ems_ = nullptr;
  cosim::Input<hybrid_bus_twin::BatteryState>* battery_ = nullptr;
  cosim::Input<hybrid_bus_twin::CoolingState>* cooling_ = nullptr;  // the cooling participant runs only
  cosim::Output state_pub_;
  double ambient_T_K_ = 298.15;
  cosim::core::Warning* derating_ = nullptr;
};

}  // namespace hbt::emachine
