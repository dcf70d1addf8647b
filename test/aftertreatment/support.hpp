// Test support: loads config/aftertreatment.yaml into AtsParams.
#pragma once
#include <cstdlib>
#include <string>

#include "aftertreatment/ats_params.hpp"
#include "common/yaml_params.hpp"

namespace hbt::aftertreatment::test {

inline std::string sourceDir() {
  const char* s = std::getenv("HBT_SOURCE_DIR");
  return s ? s : ".";
}

inline AtsParams loadParams() {
  const std::string file = sourceDir() + "/config/aftertreatment.yaml";
  AtsParams p;
  ParamSet ps;
  p.declare(ps);
  // cosim/ keys (the node's macro step) belong to the participant base class, as in the node
  applyParams(ps, readYamlParams(file), {"cosim/"});
  p.validate(file);
  return p;
}

/// Params without any can loss (no convection, radiation or forced flow on the can).
inline AtsParams adiabatic(AtsParams p) {
  p.h_natural_W_m2K = 0.0;
  p.can_emissivity = 0.0;
  p.underbody_air_factor = 0.0;
  return p;
}

}  // namespace hbt::aftertreatment::test
