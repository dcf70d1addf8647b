// ROS bridge of the crank-angle-resolved 1D engine (engine_model:=1d): converts messages and
// parameters, nothing else. Model: hbt::engine_1d::Engine1D (../engine_1d.hpp).
//
// Inputs  (stamped t_k): /vehicle/engine_command (imposed speed, torque request, ambient;
//                        /ems/engine_command in the hybrid, private parameter loops/ems);
//                        /cooling/state (coolant -> friction, wall temperatures) and
//                        /aftertreatment/state (back-pressure -> turbine-outlet boundary) when
//                        loops/cooling and loops/aftertreatment are set (engine_ports.hpp).
// Outputs (stamped t_k): /engine/state, /engine/exhaust, /engine/heat (same as the map engine).
// Parameters: private namespace = config/engine_1d.yaml (loaded by the launch file, as for every
// participant; `config_file` names it); the files it names (cylinder, turbo, reference map) are
// read from its folder, so that config:=DIR uses DIR's copies and errors name each file and
// key; `solver` (fsm|tvd,
// optional) overrides engine_1d/solver. Without the aftertreatment and cooling nodes the
// back-pressure comes from the model's documented constant-orifice default and the coolant is
// at the model's thermostat temperature (Engine1DInputs::coolant_T_K, 363.15 K).
// Diagnostics (README "Diagnostics"): warning boost_limited (the smoke limiter -- minimum lambda,
// i.e. too little boost air -- holds the fuel for engine/duration_s, config/diagnostics.yaml);
// key/values the coupled gas-dynamic/cylinder sub-steps (in the window and in all), lambda, boost.
#pragma once
#include <hybrid_bus_twin/EngineCommand.h>

#include <memory>

#include "cosim/engine_ports.hpp"
#include "cosim/participant.hpp"
#include "engine_1d/engine_1d.hpp"

namespace hbt::engine1d {

class Engine1DParticipant : public cosim::Participant {
 public:
  Engine1DParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void checkWarnings(cosim::core::Nanos t) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;

 private:
  std::unique_ptr<Engine1D> engine_;
  cosim::Input<hybrid_bus_twin::EngineCommand>* command_ = nullptr;
  cosim::EnginePorts ports_;
  double speed_rad_s_ = 0.0, ambient_T_K_ = 298.15;
  const double coolant_T_K_ = Engine1DInputs{}.coolant_T_K;  // warm default without a cooling node
  cosim::EngineLoopInputs loops_;
  double used_coolant_T_K_ = 0.0, back_pressure_Pa_ = 0.0;  // loop inputs of the last step
  double request_Nm_ = 0.0;       // torque request of the last step [Nm]
  long gas_steps_at_status_ = 0;  // sub-steps counted at the last status
  cosim::core::Warning* boost_limited_ = nullptr;
};

}  // namespace hbt::engine1d
