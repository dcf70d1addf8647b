// Shared helpers of the turbo tests: repository root, default models built from the YAML
// defaults (the Scania maps under ../shared/data/turbo), a flat YAML -> ParamSource loader.
#pragma once
#include <cstdlib>
#include <string>

#include "turbo/turbo_config.hpp"

namespace hbt::turbo::test {

inline std::string repoRoot() {
  const char* d = std::getenv("HBT_SOURCE_DIR");
  return d ? std::string(d) : std::string(".");
}

inline std::string dataPath(const std::string& rel) {
  return repoRoot() + "/../shared/data/turbo/" + rel;
}

/// Models with the built-in defaults (identical to config/engine_1d_turbo.yaml).
inline const Turbocharger& defaultTurbo() {
  static const Turbocharger t = buildTurbocharger(TurboConfig{}, repoRoot());
  return t;
}

}  // namespace hbt::turbo::test
