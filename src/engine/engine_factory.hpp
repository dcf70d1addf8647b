// The engine-model factory: the twin's engine models by name, each built from its YAML. ROS-free;
// it sits above the models (src/engine_map, src/engine_1d, which implement the interface of
// src/engine_interface) and beneath the engine participant (node/), which only hands it the
// parameters of its private namespace.
//   map: config/engine_map.yaml -> MapEngineParams (every key checked; data files relative to the
//        package directory)
//   1d:  config/engine_1d.yaml -> Engine1DParams (its sub-files -- cylinder, turbo, reference map
//        -- read beside that YAML, so config:=DIR uses DIR's copies); `solver` (fsm | tvd; empty =
//        the file's engine_1d/solver) overrides the pipe solver (launch argument solver)
// Throws InputError naming the file and the key.
#pragma once
#include <memory>
#include <string>

#include "common/params.hpp"
#include "engine_interface/engine_model.hpp"

namespace hbt::engine {

/// The engine models (launch argument `engine`): "map" | "1d". Anything else throws
/// InputError(where, key) naming the value and the choices.
void checkEngineModelName(const std::string& name, const std::string& where, const std::string& key);

/// The model `model` from `params` (its YAML's keys, flattened, without the node's own keys) read
/// from `file`; data paths relative to `package_dir`.
std::unique_ptr<EngineModel> makeEngineModel(const std::string& model, const ParamSource& params,
                                             const std::string& file, const std::string& package_dir,
                                             const std::string& solver = "");

}  // namespace hbt::engine
