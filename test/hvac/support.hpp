// Test support: config/hvac.yaml into HvacParams, as the node reads it.
#pragma once
#include "common/yaml_params.hpp"
#include "hvac/hvac_params.hpp"

namespace hbt::hvac::test {

inline HvacParams yamlParams() {
  HvacParams p;
  ParamSet ps;
  p.declare(ps);
  // cosim/ and diagnostics/ belong to the participant base class, as in the node
  applyParams(ps, readYamlParams("config/hvac.yaml"), {"cosim/", "diagnostics/"});
  return p;
}

}  // namespace hbt::hvac::test
