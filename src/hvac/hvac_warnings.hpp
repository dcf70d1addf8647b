// Thresholds of the hvac participant's warning cabin_discomfort: the `diagnostics:` section of
// config/hvac.yaml (read by cosim::Participant::readWarningThresholds, every key required).
// The cabin more than band_K outside the dead band [heating, cooling set point] for duration_s.
// ROS-free.
#pragma once
#include "common/params.hpp"

namespace hbt::hvac {

struct HvacWarnings {
  double band_K = 5.0;        ///< cabin this far below the heating / above the cooling set point [K] ...
  double duration_s = 1800.0; ///< ... for this long [s]

  void declare(ParamSet& ps) {
    ps.add("band_K", band_K, "K", 0.0, 50.0, "cabin_discomfort: distance outside the set points");
    ps.add("duration_s", duration_s, "s", 0.0, 1e5, "cabin_discomfort: persistence");
  }
};

}  // namespace hbt::hvac
