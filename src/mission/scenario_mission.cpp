#include "mission/scenario_mission.hpp"

#include <fstream>

#include "common/errors.hpp"
#include "common/yaml_params.hpp"

namespace hbt::mission {
namespace {

std::string underPackage(const std::string& package_dir, const std::string& path) {
  return path.empty() || path[0] == '/' ? path : package_dir + "/" + path;
}

}  // namespace

MissionProfile buildScenarioMission(const ScenarioMission& s) {
  MissionParams mp;
  ParamSet ps;
  mp.declare(ps);
  applyParamFile(ps, s.mission_file);
  if (!s.cycle_file.empty()) mp.cycle_file = s.cycle_file;
  mp.cycle_file = underPackage(s.package_dir, mp.cycle_file);
  mp.accel_limits_file = underPackage(s.package_dir, mp.accel_limits_file);
  mp.vehicle.mass_kg = s.bus.mass_kg;
  mp.vehicle.rotating_mass_kg = s.bus.rotating_mass_kg;
  mp.vehicle.cda_m2 = s.bus.cda_m2;
  mp.vehicle.rrc = s.bus.rrc;
  mp.profile_csv_file = s.out_dir.empty() ? "" : s.out_dir + "/profile.csv";
  MissionProfile profile = buildMissionProfile(mp);
  if (!s.out_dir.empty()) writeStops(profile, s.out_dir + "/stops.csv");
  return profile;
}

void writeStops(const MissionProfile& profile, const std::string& path) {
  std::ofstream f(path);
  if (!f) throw InputError(path, "(file)", "cannot write the stop list");
  f << "distance_m,t_profile_s,stop_time_s\n";
  const auto& s = profile.samples();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s[i].stop_flag || (i > 0 && s[i - 1].stop_flag)) continue;
    std::size_t j = i;
    while (j + 1 < s.size() && s[j + 1].stop_flag) ++j;
    f << s[i].distance_m << "," << s[i].t_s << "," << (s[j].t_s - s[i].t_s) << "\n";
  }
}

}  // namespace hbt::mission
