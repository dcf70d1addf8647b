// The engine participant's small factory: the engine model named by `model` (map | 1d), built
// from the participant's private parameters (the model's YAML, loaded there by the launch from
// `config_file`, as for every participant).
//   map: config/engine_map.yaml -> MapEngineParams (every key checked; data files relative to the
//        package, /scenario/package_dir)
//   1d:  config/engine_1d.yaml -> Engine1DParams (its sub-files -- cylinder, turbo, reference map
//        -- read beside that YAML, so config:=DIR uses DIR's copies); private `solver` (fsm | tvd,
//        optional) overrides engine_1d/solver
// The node's own keys (config_file, model, solver, loops/..., cosim/...) are no model keys.
// Throws InputError naming the file and the key.
#pragma once
#include <ros/ros.h>

#include <memory>
#include <string>

#include "engine/engine_model.hpp"

namespace hbt::engine {

std::unique_ptr<EngineModel> makeEngineModel(const std::string& model, const ros::NodeHandle& nh,
                                             const ros::NodeHandle& pnh, const std::string& config_file);

}  // namespace hbt::engine
