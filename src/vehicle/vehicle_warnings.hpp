// Thresholds of the vehicle participant's warning driver_not_tracking: the `diagnostics:` section
// of config/vehicle.yaml (read by cosim::Participant::readWarningThresholds, every key required).
// |target - actual speed| above speed_error_kmh (until it falls below speed_error_release_kmh)
// for duration_s while the driver still has authority. ROS-free.
#pragma once
#include <string>

#include "common/errors.hpp"
#include "common/params.hpp"

namespace hbt::vehicle {

struct VehicleWarnings {
  double speed_error_kmh = 3.0;          ///< |target - actual| above this [km/h] ...
  double speed_error_release_kmh = 2.0;  ///< ... until it falls below this [km/h] (hysteresis)
  double duration_s = 5.0;               ///< ... for this long, pedal not saturated [s]

  void declare(ParamSet& ps) {
    ps.add("speed_error_kmh", speed_error_kmh, "km/h", 0.1, 100.0,
           "driver_not_tracking: |target - actual speed| above this");
    ps.add("speed_error_release_kmh", speed_error_release_kmh, "km/h", 0.0, 100.0,
           "driver_not_tracking: condition ends below this");
    ps.add("duration_s", duration_s, "s", 0.0, 3600.0, "driver_not_tracking: persistence");
  }
  void validate(const std::string& file) const {
    if (speed_error_release_kmh > speed_error_kmh)
      throw InputError(file, "diagnostics/speed_error_release_kmh", "must not exceed diagnostics/speed_error_kmh");
  }
};

}  // namespace hbt::vehicle
