// Threshold of the trip computer's warning long_idle: the `diagnostics:` section of its YAML.
// The engine idles at standstill for longer than idle_s (fleet telematics flag such idling).
#pragma once
#include "common/params.hpp"

namespace hbt::example {

struct TripComputerWarnings {
  double idle_s = 120.0;  ///< standstill idling longer than this [s]
  void declare(ParamSet& ps) { ps.add("idle_s", idle_s, "s", 0.0, 1e5, "long_idle: standstill idling longer than this"); }
};

}  // namespace hbt::example
