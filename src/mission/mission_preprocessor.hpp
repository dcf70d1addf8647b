// Mission pre-processor: distance-based VECTO cycle -> time-based target profile.
//
//   MissionParams p;                       // defaults below; or p.declare(ps) + applyParams
//   MissionProfile prof = buildMissionProfile(p);   // reads cycle + .vacc, plans, samples,
//                                                   // writes p.profile_csv_file if not empty
// Pipeline: readVdri -> planSpeedOverDistance (driver rules, see speed_planner.hpp)
//           -> MissionProfile::fromDistanceProfile (fixed dt, see mission_profile.hpp).
// Relative file paths are used as given (the nodes and tests run from the repository root).
#pragma once
#include <string>

#include "common/params.hpp"
#include "mission/mission_profile.hpp"
#include "mission/speed_planner.hpp"
#include "mission/vehicle_limits.hpp"

namespace hbt::mission {

/// When a stop of the mission counts as served: the one definition used by the ROS report
/// (twin_tools.report.postprocess and .ledger read it from the run's resolved_config/vehicle.csv)
/// and by the in-process mission runner (src/vehicle/tools/mission_run.hpp).
/// A stop (profile window [t_0, t_0 + D]) is served when the bus stands still (speed below
/// standstill_speed_m_s) for at least served_fraction · D within [t_0, t_0 + D + window_after_s].
struct StopService {
  double standstill_speed_m_s = 0.5 / 3.6;  // [m/s] 0.5 km/h: "stands still"
  double served_fraction = 0.9;             // [-] of the stop's duration D
  double window_after_s = 2.0;              // [s] the bus may arrive up to this late
};

struct MissionParams {
  std::string cycle_file = "config/data/cycles/vecto/Urban.vdri";  // distance-based cycle
  std::string accel_limits_file =
      "config/data/vehicle/citybus_P1_hybrid_48V/Bus.vacc";  // driver a_max/a_min vs speed
  std::string profile_csv_file;  // profile CSV written here if not empty
  double dt_s = 0.1;             // [s] output sample time
  double ds_max_m = 0.25;        // [m] distance grid step of the planner
  RoadLoadParams vehicle;        // keys vehicle/...
  DriverRules driver;            // keys driver/...
  StopService stop_service;      // keys stop_service/...

  /// Keys: cycle_file, accel_limits_file, profile_csv_file, dt_s, ds_max_m,
  /// vehicle/{mass_kg, rotating_mass_kg, rrc, cda_m2, air_density_kg_m3, max_wheel_power_W},
  /// driver/{lac_enabled, lac_min_speed_m_s, lac_target_decel_m_s2, overspeed_enabled,
  ///         overspeed_min_speed_m_s, overspeed_m_s},
  /// stop_service/{standstill_speed_m_s, served_fraction, window_after_s}. All optional
  /// (defaults above).
  void declare(ParamSet& ps);
};

/// Plans and samples `cycle` with the given limits (no file I/O).
MissionProfile buildMissionProfile(const DrivingCycle& cycle, const AccelerationLimits& limits,
                                   const MissionParams& p);
/// Reads p.cycle_file and p.accel_limits_file, builds the profile, writes p.profile_csv_file
/// if it is not empty. Throws InputError on any bad input.
MissionProfile buildMissionProfile(const MissionParams& p);

}  // namespace hbt::mission
