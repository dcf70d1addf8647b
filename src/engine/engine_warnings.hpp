// Thresholds of the engine participant's warning boost_limited: the `diagnostics:` section of the
// engine model's YAML (config/engine_map.yaml | engine_1d.yaml; read by
// cosim::Participant::readWarningThresholds, every key required). ROS-free.
//   map engine: the request above the PT1 (turbo build-up) dynamic full-load limit by more than
//               margin_nm while that limit is itself below the static full load by more than
//               margin_nm, for duration_s;
//   1D engine:  the smoke limiter (minimum lambda) holds the fuel for duration_s (no margin).
#pragma once
#include <string>

#include "common/params.hpp"

namespace hbt::engine {

struct EngineWarnings {
  double duration_s = 3.0;  ///< limited for this long without a break [s]
  double margin_nm = 50.0;  ///< map engine: request above the PT1 limit by more than this [Nm]

  /// `model`: map | 1d (engine_factory.hpp); margin_nm is the map engine's only.
  void declare(ParamSet& ps, const std::string& model) {
    ps.add("duration_s", duration_s, "s", 0.0, 3600.0, "boost_limited: persistence");
    if (model == "map")
      ps.add("margin_nm", margin_nm, "Nm", 0.0, 1000.0,
             "boost_limited: request above the PT1 full-load limit by more than this");
  }
};

}  // namespace hbt::engine
