// Test support: loads config/engine_1d_cylinder.yaml into the cylinder (and rig) parameters.
#pragma once
#include <cstdlib>
#include <string>

#include "common/params.hpp"
#include "cylinder/cylinder_params.hpp"
#include "cylinder/rig.hpp"
#include "common/yaml_params.hpp"

namespace hbt::cylinder::test {

inline std::string sourceDir() {
  const char* s = std::getenv("HBT_SOURCE_DIR");
  return s ? s : ".";
}

inline CylinderParams loadParams(RigParams* rig = nullptr) {
  const ParamSource src = readYamlParams(sourceDir() + "/config/engine_1d_cylinder.yaml");
  CylinderParams cp;
  ParamSet ps;
  cp.declare(ps);
  if (rig) rig->declare(ps);
  applyParams(ps, src, rig ? std::vector<std::string>{} : std::vector<std::string>{"cylinder_rig/"});
  cp.finalize(src.file);
  return cp;
}

}  // namespace hbt::cylinder::test
