// ROS bridge of the vehicle (bus, driver, automatic transmission, crankshaft): converts messages
// and parameters, nothing else. Models: hbt::vehicle::VehicleModel (../vehicle_model.hpp) and the
// mission pre-processor hbt::mission::buildMissionProfile (src/mission), run once at start-up.
//
// Inputs  (stamped t_k): /engine/state (EngineState: brake torque, torque limits);
//                        /cooling/state (CoolingState: fan shaft power on the crank; the heater
//                        circulation pump's 24 V load, booked with the HVAC's) when the
//                        cooling participant runs (else aux/fan_default_W);
//                        /hvac/state (HvacState: A/C compressor shaft power on the crank, the
//                        HVAC's 24 V load via the alternator or the DC/DC) when the hvac runs.
//                        Hybrid (the EMS runs): /ems/command (EmsCommand: engine
//                        on/off, friction brake after regeneration) and /emachine/state
//                        (EMachineState: actual crank torque, live motoring limit).
// Outputs (stamped t_k): /vehicle/state (VehicleState), /vehicle/to_cooling (VehicleToCooling),
//                        baseline: /vehicle/engine_command (EngineCommand);
//                        hybrid: /vehicle/driver_demand (DriverDemand) for the EMS instead.
// Parameters: private namespace = config/vehicle.yaml; beside it in the scenario's config folder
// (cosim::scenarioConfigFile): aux/<aux_set>.yaml and gearbox/<gearbox_set>.yaml (the sets the
// scenario names: /scenario/aux_set, gearbox_set), mission.yaml (the mission, planned for this
// bus: src/mission/scenario_mission.hpp), engine_map.yaml (its idle_speed_rad_s is the crank's
// start and the idle governor's set point: one definition of the idle speed), and in the hybrid
// emachine.yaml (the P1 rotor's inertia x ratio² joins the crank's);
// /scenario/{ambient_temperature_c, payload_kg, cycle_file, out_dir, package_dir}.
// Side outputs at start-up: <out_dir>/profile.csv (time-based target profile) and
// <out_dir>/stops.csv (stop positions and times); the mission duration in its ANNOUNCE.
// Diagnostics (docs/diagnostics.md): warning driver_not_tracking (|target - actual speed| beyond
// the diagnostics/ thresholds of config/vehicle.yaml, ../vehicle_warnings.hpp, while the pedal that would close the gap is not saturated);
// key/values speed, target, error, gear, pedals, distance.
#pragma once
#include <hybrid_bus_twin/HvacState.h>
#include <hybrid_bus_twin/CoolingState.h>
#include <hybrid_bus_twin/EMachineState.h>
#include <hybrid_bus_twin/EmsCommand.h>
#include <hybrid_bus_twin/EngineState.h>

#include <functional>
#include <memory>

#include "cosim/participant.hpp"
#include "vehicle/vehicle_warnings.hpp"
#include "mission/mission_profile.hpp"
#include "vehicle/vehicle_model.hpp"

namespace hbt::vehicle {

class VehicleParticipant : public cosim::Participant {
 public:
  VehicleParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  bool finished() const override { return t_s_ >= profile_.duration_s() - 1e-9; }
  void checkWarnings(cosim::core::Nanos t) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;

 private:
  // configure(), in stages
  void readSet(const std::string& file, const std::string& prefix, const std::function<void(ParamSet&)>& declare);
  void readScenarioSets(VehicleParams& p);
  void readEngineIdleSpeed(VehicleParams& p);
  void readPayloadAndAmbient(VehicleParams& p);
  void addEMachineInertia(VehicleParams& p);
  void buildMission(const VehicleParams& p, const std::string& pkg);
  void declareTopics();
  std::unique_ptr<VehicleModel> model_;
  VehicleWarnings warnings_;  // diagnostics/ of config/vehicle.yaml
  mission::MissionProfile profile_;
  cosim::Input<hybrid_bus_twin::EngineState>* engine_ = nullptr;
  cosim::Input<hybrid_bus_twin::CoolingState>* cooling_ = nullptr;  // the cooling participant runs only
  cosim::Input<hybrid_bus_twin::HvacState>* hvac_ = nullptr;        // the hvac participant runs only
  cosim::Input<hybrid_bus_twin::EmsCommand>* ems_ = nullptr;         // hybrid (the EMS runs) only
  cosim::Input<hybrid_bus_twin::EMachineState>* em_ = nullptr;       // hybrid (the EMS runs) only
  cosim::Output state_pub_, command_pub_, cooling_pub_, demand_pub_;
  double last_engine_max_Nm_ = 0.0, last_engine_min_Nm_ = 0.0;
  bool engine_on_ = true;
  cosim::core::Warning* not_tracking_ = nullptr;
  std::unique_ptr<cosim::core::Hysteresis> speed_error_;  // |target - actual| [km/h]
  double t_s_ = 0.0, ambient_T_K_ = 298.15;
};

}  // namespace hbt::vehicle
