// ROS bridge of the cooling system: converts messages and parameters, nothing else. Model:
// hbt::cooling::CoolingModel (../cooling_model.hpp).
//
// Inputs  (stamped t_k): /engine/heat (EngineHeat: heat_to_coolant_j and coolant_pump_angle_rad
//                        differenced over this node's macro step = the mean heat and pump speed of
//                        the last 0.1 s, ../step_inputs.hpp),
//                        /vehicle/to_cooling (VehicleToCooling: vehicle speed, ambient T, fan_demand).
// Output  (stamped t_k): /cooling/state (CoolingState). fan_power_w is the signed fan shaft
//                        power (> 0 absorbed, < 0 windmilling = returned to the shaft);
//                        fan_drive_power_w the same at the crank incl. the viscous-clutch slip.
// Parameters: private namespace = config/cooling.yaml; /scenario/ambient_temperature_c (initial
// state: everything at ambient, cold start); /scenario/ambient_pressure_pa (default the standard atmosphere).
// Hybrid (the emachine participant runs): /emachine/state lt_heat_w (e-machine housing +
// inverter heat into the LT coolant) feeds the LT circuit; baseline: 0 W (the circuit idles).
// HVAC (the hvac participant runs, hvac:=on): /hvac/state heating_demand_w and cabin_temperature_k
// drive the convectors instead of heater/'s balance point, and aux_heater_heat_j (differenced
// over the step) is the fuel-fired heater's heat into the HT coolant.
// Diagnostics (docs/diagnostics.md): warning coolant_overheat (HT coolant above diagnostics/overheat_c
// until below diagnostics/overheat_release_c, for diagnostics/duration_s of config/cooling.yaml);
// key/values coolant temperatures, thermostat opening, fan engagement and power.
#pragma once
#include "common/units.hpp"
#include <hybrid_bus_twin/EMachineState.h>
#include <hybrid_bus_twin/EngineHeat.h>
#include <hybrid_bus_twin/HvacState.h>
#include <hybrid_bus_twin/VehicleToCooling.h>

#include <memory>

#include "cooling/cooling_model.hpp"
#include "cooling/step_inputs.hpp"
#include "cosim/participant.hpp"
#include "cooling/cooling_warnings.hpp"

namespace hbt::cooling {

class CoolingParticipant : public cosim::Participant {
 public:
  CoolingParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void checkWarnings(cosim::core::Nanos t) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;

 private:
  std::unique_ptr<CoolingModel> model_;
  CoolingWarnings warnings_;  // diagnostics/ of config/cooling.yaml
  cosim::Input<hybrid_bus_twin::EngineHeat>* heat_ = nullptr;
  cosim::Input<hybrid_bus_twin::VehicleToCooling>* vehicle_ = nullptr;
  cosim::Input<hybrid_bus_twin::EMachineState>* emachine_ = nullptr;  // the emachine runs (hybrid) only
  cosim::Input<hybrid_bus_twin::HvacState>* hvac_ = nullptr;          // the hvac runs (hvac:=on) only
  cosim::Output state_pub_;
  double ambient_T_K_ = 298.15, ambient_p_Pa_ = units::kStandardAtmosphere_Pa;
  CoolingInputs last_in_;
  StepInputs inputs_;                                          // step means of the producers' totals
  cosim::core::Warning* overheat_ = nullptr;
  std::unique_ptr<cosim::core::Hysteresis> overheat_level_;    // HT coolant [degC]
};

}  // namespace hbt::cooling
