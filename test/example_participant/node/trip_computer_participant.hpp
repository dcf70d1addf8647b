// The trip computer's ROS bridge: converts messages and parameters, nothing else. Model:
// hbt::example::TripComputer (../trip_computer.hpp).
// Inputs  (stamped t_k): /engine/state (fuel_mass_kg, engine_speed_rad_s), /vehicle/state
//                        (distance_m, speed_m_s).
// Output  (stamped t_k + P): /trip_computer/display (ProbeSignal, values in topics.yaml).
// Parameters: its YAML (trip_computer.yaml): the model's keys, cosim/macro_step_s, diagnostics/.
// Diagnostics: warning long_idle (standstill idling longer than diagnostics/idle_s).
#pragma once
#include <hybrid_bus_twin/EngineState.h>
#include <hybrid_bus_twin/VehicleState.h>

#include <memory>

#include "cosim/participant.hpp"
#include "example_participant/trip_computer.hpp"
#include "example_participant/trip_computer_warnings.hpp"

namespace hbt::example {

class TripComputerParticipant : public cosim::Participant {
 public:
  TripComputerParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void checkWarnings(cosim::core::Nanos t) override;

 private:
  std::unique_ptr<TripComputer> model_;
  TripComputerWarnings warnings_;
  cosim::Input<hybrid_bus_twin::EngineState>* engine_ = nullptr;
  cosim::Input<hybrid_bus_twin::VehicleState>* vehicle_ = nullptr;
  cosim::Output display_pub_;
  cosim::core::Warning* long_idle_ = nullptr;
};

}  // namespace hbt::example
