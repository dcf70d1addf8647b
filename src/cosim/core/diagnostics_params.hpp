// Parameters of the participants' diagnostics (config/diagnostics.yaml, README "Diagnostics"):
// the status period and the thresholds of each participant's warnings. One file for every
// participant: each validates the whole file (a typo in any section is rejected wherever it is),
// then uses its own section. SI units except where the key names another (km/h, degC).
#pragma once
#include <string>

#include "common/params.hpp"

namespace hbt::cosim::core {

struct DiagnosticsParams {
  double period_s = 1.0;  ///< simulated time between two statuses of a participant [s]

  struct Vehicle {  // driver_not_tracking
    double speed_error_kmh = 3.0;          ///< |target - actual| above this ...
    double speed_error_release_kmh = 2.0;  ///< ... until it falls below this (hysteresis)
    double duration_s = 5.0;               ///< ... for this long, pedal not saturated
  } vehicle;
  struct Engine {  // boost_limited
    double duration_s = 3.0;   ///< limited for this long without a break
    double margin_nm = 50.0;   ///< map engine: request above the PT1 limit by more than this
  } engine;
  struct Aftertreatment {  // ats_below_light_off
    double light_off_grace_s = 300.0;  ///< SCR not lit off for this long without a break
  } aftertreatment;
  struct EMachine {  // emachine_derating
    double derating_factor_below = 1.0;  ///< live/peak torque limit below this
    double duration_s = 0.0;
  } emachine;
  struct Battery {  // battery_limited
    double duration_s = 0.0;  ///< request beyond the power limits for this long
  } battery;
  struct Cooling {  // coolant_overheat
    double overheat_c = 105.0;          ///< HT coolant above this ...
    double overheat_release_c = 102.0;  ///< ... until below this (hysteresis)
    double duration_s = 5.0;
  } cooling;

  /// Every key (names = config/diagnostics.yaml).
  void declare(ParamSet& ps);
  /// Cross-key checks (release levels below the thresholds). Throws InputError naming `file`.
  void validate(const std::string& file) const;
};

}  // namespace hbt::cosim::core
