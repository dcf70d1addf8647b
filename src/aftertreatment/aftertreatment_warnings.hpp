// Threshold of the aftertreatment participant's warning ats_below_light_off: the `diagnostics:`
// section of config/aftertreatment.yaml (read by cosim::Participant::readWarningThresholds,
// required). The SCR not lit off (AftertreatmentState.light_off false) for light_off_grace_s
// without a break. ROS-free.
#pragma once
#include <string>

#include "common/params.hpp"

namespace hbt::aftertreatment {

struct AftertreatmentWarnings {
  double light_off_grace_s = 300.0;  ///< SCR not lit off for this long [s]

  void declare(ParamSet& ps) {
    ps.add("light_off_grace_s", light_off_grace_s, "s", 0.0, 1e5,
           "ats_below_light_off: SCR not lit off for this long");
  }
};

}  // namespace hbt::aftertreatment
