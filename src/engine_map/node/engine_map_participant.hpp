// ROS bridge of the map-based engine (engine_model:=map): converts messages and parameters,
// nothing else. Model: hbt::engine_map::MapEngine (../map_engine.hpp).
//
// Inputs  (stamped t_k): /vehicle/engine_command (EngineCommand: imposed speed, torque request;
//                        /ems/engine_command in the hybrid, private parameter loops/ems);
//                        /cooling/state, /aftertreatment/state when loops/cooling, loops/aftertreatment.
// Outputs (stamped t_k): /engine/state (EngineState), /engine/exhaust (ExhaustState),
//                        /engine/heat (EngineHeat).
// Parameters: private namespace = config/engine_map.yaml; /scenario/ambient_temperature_c.
// Diagnostics (README "Diagnostics"): warning boost_limited (the torque request above the PT1
// dynamic full-load limit -- the turbo's build-up -- by more than engine/margin_nm while that limit
// is itself below the static full load, config/diagnostics.yaml); key/values request, torque, limits.
#pragma once
#include <hybrid_bus_twin/EngineCommand.h>

#include <memory>

#include "cosim/engine_ports.hpp"
#include "cosim/participant.hpp"
#include "engine_map/map_engine.hpp"

namespace hbt::engine_map {

class EngineMapParticipant : public cosim::Participant {
 public:
  EngineMapParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void checkWarnings(cosim::core::Nanos t) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;

 private:
  std::unique_ptr<MapEngine> engine_;
  cosim::Input<hybrid_bus_twin::EngineCommand>* command_ = nullptr;
  cosim::EnginePorts ports_;
  cosim::EngineLoopInputs loops_;
  double coolant_T_K_ = 0.0, back_pressure_Pa_ = 0.0;  // loop inputs of the last step
  double speed_rad_s_ = 0.0, ambient_T_K_ = 298.15, last_cpu_s_ = 0.0;
  double request_Nm_ = 0.0;  // torque request of the last step [Nm]
  cosim::core::Warning* boost_limited_ = nullptr;
};

}  // namespace hbt::engine_map
