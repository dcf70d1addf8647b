// Shared support of the battery tests: the shipped parameters as the node reads them
// (config/battery.yaml, then a pack set of config/battery_pack/ replacing its pack/ and housing/
// groups when one is named).
#pragma once
#include <string>

#include "battery/battery_params.hpp"
#include "common/yaml_params.hpp"

namespace hbt::battery::test {

inline BatteryParams shippedParams(const std::string& pack_set_file = "") {
  BatteryParams p;
  ParamSet ps;
  p.declare(ps);
  applyParams(ps, readYamlParams("config/battery.yaml"), {"cosim/"});
  if (!pack_set_file.empty()) {
    ParamSet set;
    p.declarePackSet(set);
    applyParamFile(set, pack_set_file);
  }
  return p;
}

}  // namespace hbt::battery::test
