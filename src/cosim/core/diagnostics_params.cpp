#include "cosim/core/diagnostics_params.hpp"

#include "common/errors.hpp"

namespace hbt::cosim::core {

void DiagnosticsParams::declare(ParamSet& ps) {
  ps.setPrefix("");
  ps.add("period_s", period_s, "s", 0.001, 3600.0, "simulated time between two statuses");
  ps.setPrefix("vehicle/");
  ps.add("speed_error_kmh", vehicle.speed_error_kmh, "km/h", 0.1, 100.0,
         "driver_not_tracking: |target - actual speed| above this");
  ps.add("speed_error_release_kmh", vehicle.speed_error_release_kmh, "km/h", 0.0, 100.0,
         "driver_not_tracking: condition ends below this");
  ps.add("duration_s", vehicle.duration_s, "s", 0.0, 3600.0, "driver_not_tracking: persistence");
  ps.setPrefix("engine/");
  ps.add("duration_s", engine.duration_s, "s", 0.0, 3600.0, "boost_limited: persistence");
  ps.add("margin_nm", engine.margin_nm, "Nm", 0.0, 1000.0,
         "boost_limited (map engine): request above the PT1 full-load limit by more than this");
  ps.setPrefix("aftertreatment/");
  ps.add("light_off_grace_s", aftertreatment.light_off_grace_s, "s", 0.0, 1e5,
         "ats_below_light_off: SCR not lit off for this long");
  ps.setPrefix("emachine/");
  ps.add("derating_factor_below", emachine.derating_factor_below, "-", 0.0, 1.0,
         "emachine_derating: live/peak torque limit below this");
  ps.add("duration_s", emachine.duration_s, "s", 0.0, 3600.0, "emachine_derating: persistence");
  ps.setPrefix("battery/");
  ps.add("duration_s", battery.duration_s, "s", 0.0, 3600.0, "battery_limited: persistence");
  ps.setPrefix("cooling/");
  ps.add("overheat_c", cooling.overheat_c, "degC", 50.0, 150.0, "coolant_overheat: HT coolant above this");
  ps.add("overheat_release_c", cooling.overheat_release_c, "degC", 50.0, 150.0,
         "coolant_overheat: condition ends below this");
  ps.add("duration_s", cooling.duration_s, "s", 0.0, 3600.0, "coolant_overheat: persistence");
  ps.setPrefix("");
}

void DiagnosticsParams::validate(const std::string& file) const {
  if (vehicle.speed_error_release_kmh > vehicle.speed_error_kmh)
    throw InputError(file, "vehicle/speed_error_release_kmh", "must not exceed vehicle/speed_error_kmh");
  if (cooling.overheat_release_c > cooling.overheat_c)
    throw InputError(file, "cooling/overheat_release_c", "must not exceed cooling/overheat_c");
}

}  // namespace hbt::cosim::core
