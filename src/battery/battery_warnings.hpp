// Threshold of the battery participant's warning battery_limited: the `diagnostics:` section of
// config/battery.yaml (read by cosim::Participant::readWarningThresholds, required). The power
// request exceeded the pack's power limits (BatteryState.request_limited) for duration_s. ROS-free.
#pragma once
#include <string>

#include "common/params.hpp"

namespace hbt::battery {

struct BatteryWarnings {
  double duration_s = 0.0;  ///< request beyond the power limits for this long [s]

  void declare(ParamSet& ps) { ps.add("duration_s", duration_s, "s", 0.0, 3600.0, "battery_limited: persistence"); }
};

}  // namespace hbt::battery
