// Thresholds of the cooling participant's warning coolant_overheat: the `diagnostics:` section of
// config/cooling.yaml (read by cosim::Participant::readWarningThresholds, every key required).
// HT coolant above overheat_c (until below overheat_release_c) for duration_s. ROS-free.
#pragma once
#include <string>

#include "common/errors.hpp"
#include "common/params.hpp"

namespace hbt::cooling {

struct CoolingWarnings {
  double overheat_c = 105.0;          ///< HT coolant above this [degC] ...
  double overheat_release_c = 102.0;  ///< ... until below this [degC] (hysteresis)
  double duration_s = 5.0;            ///< ... for this long [s]

  void declare(ParamSet& ps) {
    ps.add("overheat_c", overheat_c, "degC", 50.0, 150.0, "coolant_overheat: HT coolant above this");
    ps.add("overheat_release_c", overheat_release_c, "degC", 50.0, 150.0,
           "coolant_overheat: condition ends below this");
    ps.add("duration_s", duration_s, "s", 0.0, 3600.0, "coolant_overheat: persistence");
  }
  void validate(const std::string& file) const {
    if (overheat_release_c > overheat_c)
      throw InputError(file, "diagnostics/overheat_release_c", "must not exceed diagnostics/overheat_c");
  }
};

}  // namespace hbt::cooling
