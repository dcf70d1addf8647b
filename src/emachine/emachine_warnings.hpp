// Thresholds of the e-machine participant's warning emachine_derating: the `diagnostics:` section
// of config/emachine.yaml (read by cosim::Participant::readWarningThresholds, every key required).
// Thermal derating active: EMachineState.derating_factor (live / peak torque limit) below
// derating_factor_below for duration_s. ROS-free.
#pragma once
#include <string>

#include "common/params.hpp"

namespace hbt::emachine {

struct EMachineWarnings {
  double derating_factor_below = 1.0;  ///< live/peak torque limit below this [-] (1.0 = any derating)
  double duration_s = 0.0;             ///< for this long [s]

  /// The warning's condition (the node's and the FMU's): the live/peak torque limit
  /// (EMachineOutputs::limits.derating_factor) below derating_factor_below.
  bool derating(double derating_factor) const { return derating_factor < derating_factor_below; }

  void declare(ParamSet& ps) {
    ps.add("derating_factor_below", derating_factor_below, "-", 0.0, 1.0,
           "emachine_derating: live/peak torque limit below this");
    ps.add("duration_s", duration_s, "s", 0.0, 3600.0, "emachine_derating: persistence");
  }
};

}  // namespace hbt::emachine
