// Commented rosparam YAML file -> hbt::ParamSource, for tools and tests that run without a ROS
// master (the nodes get the same flat keys from the parameter server, cosim/param_loader.hpp).
// Nested mappings are flattened with '/' ("cylinder/geometry/bore_m"); numbers become double,
// true/false bool, other scalars strings, sequences of numbers std::vector<double>. Errors
// (missing file, YAML syntax, a non-numeric list element) raise hbt::InputError naming the file
// and the key or line.
#pragma once
#include <string>

#include "common/params.hpp"

namespace hbt {

ParamSource readYamlParams(const std::string& path);
/// Same, from text; `file_name` is used in error messages.
ParamSource parseYamlParams(const std::string& text, const std::string& file_name);

/// Reads `path` into the fields `ps` declares: applyParams (an unknown key, a bad value is named
/// first), then requireKeys (every declared key is in the file but an intended default). The one
/// call for a file read on its own; throws InputError naming `path` and the key.
void applyParamFile(const ParamSet& ps, const std::string& path);

}  // namespace hbt
