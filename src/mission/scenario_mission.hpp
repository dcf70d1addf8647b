// The mission of a scenario run, built once at start-up: the mission pre-processor's parameters
// from config/mission.yaml (every key checked, errors naming the file and the key), the scenario's
// driving cycle, and the road load of the bus that drives it, so that the target profile is
// planned within this bus's limits. Writes the time-based profile (profile.csv) and the stop
// list (stops.csv: distance [m], time of the stop in the profile [s], its standstill time [s])
// into the run's folder.
#pragma once
#include <string>

#include "mission/mission_preprocessor.hpp"
#include "mission/mission_profile.hpp"

namespace hbt::mission {

/// The bus's own road-load data, which override the vehicle/ keys of config/mission.yaml.
struct BusRoadLoad {
  double mass_kg = 0.0;           ///< curb + payload [kg]
  double rotating_mass_kg = 0.0;  ///< equivalent mass of the rotating parts at the wheel [kg]
  double cda_m2 = 0.0;            ///< drag coefficient x frontal area [m^2]
  double rrc = 0.0;               ///< rolling-resistance coefficient [-]
};

struct ScenarioMission {
  std::string mission_file;  ///< config/mission.yaml (MissionParams keys, all required)
  std::string cycle_file;    ///< the scenario's .vdri; empty: the file's cycle_file
  std::string package_dir;   ///< relative data paths (cycle, .vacc) are taken against it
  std::string out_dir;       ///< profile.csv and stops.csv go there; empty: not written
  BusRoadLoad bus;
};

/// Reads, plans and samples the mission. Throws InputError naming the file and the key.
MissionProfile buildScenarioMission(const ScenarioMission& s);

/// The stops of `profile` as CSV: distance_m, t_profile_s, stop_time_s (one row per stop).
void writeStops(const MissionProfile& profile, const std::string& path);

}  // namespace hbt::mission
