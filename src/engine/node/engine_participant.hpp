// ROS bridge of the engine, whichever model runs it (/scenario/engine_model: map | 1d, the
// launch argument engine): converts messages and parameters, nothing else. Models behind the
// ROS-free interface engine::EngineModel (../../engine_interface/engine_model.hpp: its units, equations and the start,
// ambient, loop and exhaust-temperature policies): engine_map::MapEngineModel (VECTO maps + PT1
// torque build-up) and engine_1d::Engine1DModel (crank-angle-resolved 1D engine), built by
// makeEngineModel (../engine_factory.hpp). The conversion messages <-> model is
// engine_interface/engine_io.hpp, the one the engine FMUs use (../engine_fmu.hpp).
//
// Inputs  (stamped t_k): /vehicle/engine_command (EngineCommand: imposed speed, torque request,
//                        engine on, ambient T and p; /ems/engine_command when the EMS
//                        runs: the hybrid); /cooling/state (coolant temperature) and
//                        /aftertreatment/state (back-pressure) when those participants run
//                        (engine_ports.hpp).
// Outputs (stamped t_k): /engine/state (EngineState), /engine/exhaust (ExhaustState),
//                        /engine/heat (EngineHeat).
// Parameters: /scenario/engine_model (map | 1d, required; anything else: InputError naming it);
// private namespace = the model's YAML (config/engine_map.yaml | config/engine_1d.yaml, named by
// `config_file`); /scenario/engine_solver (1d only, fsm | tvd; empty: the YAML's); /scenario/ambient_temperature_c
// (the start temperature; the command's ambient temperature drives the steps), /scenario/package_dir.
// Initial state: the model's reset() at its idle speed (engine_map.yaml idle_speed_rad_s), torque
// 0, the scenario ambient temperature and the standard atmosphere (units::kStandardAtmosphere_Pa);
// a command without an ambient pressure (<= 0) means the standard atmosphere as well.
// Diagnostics (docs/diagnostics.md): warning boost_limited (EngineModel::boostLimited: map = the
// request above the PT1 dynamic full load, the turbo's build-up, by more than diagnostics/margin_nm
// while that limit is itself below the static full load; 1D = the smoke limiter -- minimum
// lambda -- holds the fuel; for diagnostics/duration_s of the model's YAML, ../engine_warnings.hpp); key/values model,
// speed, request, brake torque, then the model's own (map: dynamic and static full load, fuel
// cut; 1D: gas-dynamic/cylinder sub-steps in the window and in all, lambda, boost, smoke limiter).
#pragma once
#include <hybrid_bus_twin/EngineCommand.h>

#include <memory>

#include "cosim/participant.hpp"
#include "engine_interface/engine_model.hpp"
#include "engine/engine_warnings.hpp"
#include "engine/node/engine_ports.hpp"

namespace hbt::engine {

class EngineParticipant : public cosim::Participant {
 public:
  EngineParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void checkWarnings(cosim::core::Nanos t) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;

 private:
  std::unique_ptr<EngineModel> model_;
  EngineWarnings warnings_;  // diagnostics/ of the model's YAML
  cosim::Input<hybrid_bus_twin::EngineCommand>* command_ = nullptr;
  EngineLoopInputs loops_;
  EnginePorts ports_;
  double ambient_T_K_ = 298.15;  // scenario ambient [K]: the start, and a command without one
  cosim::core::Warning* boost_limited_ = nullptr;
};

}  // namespace hbt::engine
