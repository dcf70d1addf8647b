#include "mission/mission_preprocessor.hpp"

namespace hbt::mission {

void MissionParams::declare(ParamSet& ps) {
  ps.add("cycle_file", cycle_file, "distance-based VECTO cycle (.vdri), path from the repo root");
  ps.add("accel_limits_file", accel_limits_file,
         "VECTO .vacc driver acceleration/deceleration limits vs speed");
  ps.add("profile_csv_file", profile_csv_file, "time-based profile CSV output ('' = none)");
  ps.add("dt_s", dt_s, "s", 1e-3, 10.0, "sample time of the time-based profile");
  ps.add("ds_max_m", ds_max_m, "m", 1e-3, 10.0, "distance grid step of the speed planner");
  ps.add("vehicle/mass_kg", vehicle.mass_kg, "kg", 1000.0, 60000.0,
         "vehicle mass (curb + payload)");
  ps.add("vehicle/rotating_mass_kg", vehicle.rotating_mass_kg, "kg", 0.0, 5000.0,
         "equivalent mass of the wheels' inertia, sum(J)/r^2");
  ps.add("vehicle/rrc", vehicle.rrc, "-", 0.0, 0.05, "rolling-resistance coefficient");
  ps.add("vehicle/cda_m2", vehicle.cda_m2, "m^2", 0.0, 20.0, "drag coefficient x frontal area");
  ps.add("vehicle/air_density_kg_m3", vehicle.air_density_kg_m3, "kg/m^3", 0.5, 2.0,
         "air density");
  ps.add("vehicle/max_wheel_power_W", vehicle.max_wheel_power_W, "W", 0.0, 2e6,
         "maximum traction power at the wheels (0 = no power limit)");
  ps.add("driver/lac_enabled", driver.lac_enabled, "look-ahead coasting before speed drops");
  ps.add("driver/lac_min_speed_m_s", driver.lac_min_speed_m_s, "m/s", 0.0, 50.0,
         "look-ahead coasting disabled below this speed");
  ps.add("driver/lac_target_decel_m_s2", driver.lac_target_decel_m_s2, "m/s^2", 0.01, 5.0,
         "a_lookahead (positive) that sets the coasting start point");
  ps.add("driver/overspeed_enabled", driver.overspeed_enabled, "overspeed on downhill");
  ps.add("driver/overspeed_min_speed_m_s", driver.overspeed_min_speed_m_s, "m/s", 0.0, 50.0,
         "overspeed disabled below this target speed");
  ps.add("driver/overspeed_m_s", driver.overspeed_m_s, "m/s", 0.0, 10.0,
         "allowed speed above the target while rolling downhill");
  ps.add("stop_service/standstill_speed_m_s", stop_service.standstill_speed_m_s, "m/s", 0.0, 2.0,
         "a bus slower than this stands still (stop service, idle-at-stop fuel)");
  ps.add("stop_service/served_fraction", stop_service.served_fraction, "-", 0.1, 1.0,
         "share of a stop's duration the bus must stand still for the stop to be served");
  ps.add("stop_service/window_after_s", stop_service.window_after_s, "s", 0.0, 60.0,
         "the stop's window extends this long past its end (late arrival)");
}

MissionProfile buildMissionProfile(const DrivingCycle& cycle, const AccelerationLimits& limits,
                                   const MissionParams& p) {
  const DistanceProfile dp =
      planSpeedOverDistance(cycle, limits, RoadLoad(p.vehicle), p.driver, p.ds_max_m);
  return MissionProfile::fromDistanceProfile(dp, cycle, p.dt_s);
}

MissionProfile buildMissionProfile(const MissionParams& p) {
  const DrivingCycle cycle = readVdri(p.cycle_file);
  const AccelerationLimits limits = AccelerationLimits::readVacc(p.accel_limits_file);
  MissionProfile prof = buildMissionProfile(cycle, limits, p);
  if (!p.profile_csv_file.empty()) prof.writeCsv(p.profile_csv_file);
  return prof;
}

}  // namespace hbt::mission
