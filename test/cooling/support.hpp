// Test support: config/cooling.yaml into CoolingParams, as the node reads it.
#pragma once
#include "common/yaml_params.hpp"
#include "cooling/cooling_params.hpp"

namespace hbt::cooling::test {

inline CoolingParams yamlParams() {
  CoolingParams p;
  ParamSet ps;
  p.declare(ps);
  // cosim/ keys (the node's macro step) belong to the participant base class, as in the node
  applyParams(ps, readYamlParams("config/cooling.yaml"), {"cosim/"});
  return p;
}

}  // namespace hbt::cooling::test
