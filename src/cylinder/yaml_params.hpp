// Minimal reader for the rosparam-style YAML files of the cylinder model (no external library):
// nested block mappings by indentation, scalars (numbers, true/false, plain or quoted strings),
// flow sequences of numbers "[a, b, c]" (may span lines), '#' comments. Keys are flattened with
// '/' ("cylinder/geometry/bore_m") into an hbt::ParamSource whose file is the path, so that
// hbt::applyParams names file and key on error. Anything else raises InputError(file, line).
// The ROS node fills the same flat keys from the parameter server instead.
#pragma once
#include <string>

#include "common/params.hpp"

namespace hbt::cyl {

ParamSource readYamlParams(const std::string& path);
ParamSource parseYamlParams(const std::string& text, const std::string& file_name);

}  // namespace hbt::cyl
