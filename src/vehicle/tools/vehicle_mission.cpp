// vehicle_mission: the full VECTO mission (default Urban) in-process — mission profile, bus and
// map engine in lock-step at the 10 ms exchange like the ROS nodes (tools/mission_run.hpp).
// Prints distance, speed RMSE, stops served (v = 0 for >= 90 % of the stop time within
// [t_0, t_0 + D + 2 s]), stop position errors, fuel [kg, L/100 km at the diesel density of
// common/units.hpp] and the vehicle's energy breakdown [kWh]. --stops lists every stop.
//
//   vehicle_mission [--dt 0.01] [--ambient_C 25] [--payload 1500] [--cycle <vdri>]
//                   [--t_end <s>] [--base <package root>] [--stops 1] [--trace <csv, 10 Hz>]
//                   [--gearbox typical|vecto_standard]  (gear loss set config/gearbox/<set>.yaml)
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/params.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "vehicle/tools/mission_run.hpp"

using namespace hbt;

namespace {

struct Args {
  vehicle::MissionRunOptions opt;
  double payload = 1500.0, ambient_C = 25.0;  // [kg], [degC]
  bool list_stops = false;
  std::string base, cycle, trace, gearbox = "typical";
};

bool parse(int argc, char** argv, Args& a) {
  if (const char* env = std::getenv("HBT_SOURCE_DIR")) a.base = env;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--dt")) a.opt.dt_s = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--ambient_C")) a.ambient_C = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--payload")) a.payload = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--cycle")) a.cycle = argv[i + 1];
    else if (!std::strcmp(argv[i], "--t_end")) a.opt.t_end_s = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--base")) a.base = argv[i + 1];
    else if (!std::strcmp(argv[i], "--stops")) a.list_stops = std::atoi(argv[i + 1]) != 0;
    else if (!std::strcmp(argv[i], "--trace")) a.trace = argv[i + 1];
    else if (!std::strcmp(argv[i], "--gearbox")) a.gearbox = argv[i + 1];
    else { std::fprintf(stderr, "unknown option %s\n", argv[i]); return false; }
  }
  return true;
}

// The 10 Hz trace CSV: opens the file and sets opt.on_step to write it.
FILE* openTrace(const std::string& trace, vehicle::MissionRunOptions& opt) {
  FILE* tf = std::fopen(trace.c_str(), "w");
  if (!tf) throw std::runtime_error("cannot write " + trace);
  std::fprintf(tf, "t_s,v_target_kmh,v_kmh,distance_m,gear,mode,engine_rpm,accel_pedal,"
                   "brake_pedal,engine_torque_Nm,fuel_g_s,hold\n");
  opt.on_step = [tf](double t, const vehicle::VehicleOutputs& o,
                     const engine_map::MapEngineOutputs& e, double vt) {
    const long k = std::lround(t * 100.0);
    if (k % 10) return;  // 10 Hz
    std::fprintf(tf, "%.2f,%.3f,%.3f,%.2f,%d,%d,%.1f,%.3f,%.3f,%.1f,%.3f,%d\n", t, 3.6 * vt,
                 3.6 * o.speed_m_s, o.distance_m, o.gear, static_cast<int>(o.mode),
                 hbt::units::radpsToRpm(o.engine_speed_rad_s), o.accel_pedal, o.brake_pedal,
                 e.brake_torque_Nm, 1000.0 * e.fuel_mass_flow_kg_s, o.stop_hold ? 1 : 0);
  };
  return tf;
}

// Distance, speed tracking, stops, fuel and the vehicle's energies; with list_stops every stop.
void printResult(const vehicle::MissionRunResult& r, bool list_stops) {
  const double kWh = 1.0 / 3.6e6, km = r.distance_m / 1000.0;
  const double litres = units::dieselLitres(r.fuel_kg);
  std::printf("duration            %10.1f s\n", r.duration_s);
  std::printf("distance            %10.1f m  (profile %.1f m, %+.3f %%)\n", r.distance_m,
              r.target_distance_m, 100.0 * (r.distance_m / r.target_distance_m - 1.0));
  std::printf("speed RMSE          %10.3f km/h (max |error| %.2f km/h)\n", 3.6 * r.speed_rmse_m_s,
              3.6 * r.max_speed_error_m_s);
  std::size_t n_stops = 0;
  double min_frac = std::numeric_limits<double>::infinity();  // inf: no stop counted
  for (const auto& s : r.stops)
    if (s.t_start_s + s.duration_s <= r.duration_s) {
      ++n_stops;
      if (s.duration_s > 0) min_frac = std::min(min_frac, s.standing_s / s.duration_s);
    }
  std::printf("stops served        %6zu / %zu  (min standing / stop time %.3f)\n", r.stops_served,
              n_stops, min_frac);
  std::printf("max stop pos. error %10.1f m\n", r.max_stop_position_error_m);
  std::printf("time at standstill  %10.1f s\n", r.idle_standing_s);
  std::printf("fuel                %10.3f kg = %.2f L/100km (%.3f kg/L), %.1f g/km\n", r.fuel_kg,
              100.0 * litres / km, units::kDieselDensity_kg_m3 * units::kM3_per_litre,
              1000.0 * r.fuel_kg / km);
  std::printf("engine positive work %9.2f kWh (%.3f kWh/km), brake work %.2f kWh\n",
              r.engine_positive_work_J * kWh, r.engine_positive_work_J * kWh / km,
              r.engine_brake_work_J * kWh);
  const auto& e = r.energy;
  std::printf("vehicle energies [kWh]: engine %.2f  aux %.2f  gearbox drag %.2f  TC %.2f  "
              "gear load %.2f  retarder %.2f  axle %.2f  shift %.2f  rolling %.2f  aero %.2f  "
              "potential %.2f  brake %.2f  dE_kin %.3f  residual %.2e\n",
              e.engine_J * kWh, e.aux_J * kWh, e.gearbox_drag_J * kWh, e.tc_loss_J * kWh,
              e.gear_load_loss_J * kWh, e.retarder_J * kWh, e.axle_loss_J * kWh,
              e.shift_loss_J * kWh, e.rolling_J * kWh, e.aero_J * kWh, e.grade_J * kWh,
              e.brake_J * kWh, (e.kinetic_J - e.kinetic_initial_J) * kWh, e.residual_J() * kWh);
  if (list_stops) {
    std::printf("# stop t0[s] D[s] pos[m] standing[s] pos_err[m] served\n");
    for (std::size_t i = 0; i < r.stops.size(); ++i) {
      const auto& s = r.stops[i];
      std::printf("%3zu %9.1f %5.1f %9.1f %6.2f %8.2f %d\n", i, s.t_start_s, s.duration_s,
                  s.position_m, s.standing_s, s.position_error_m, s.served ? 1 : 0);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  Args a;
  if (!parse(argc, argv, a)) return 2;
  auto rel = [&](const std::string& f) {
    return a.base.empty() || f.empty() || f[0] == '/' ? f : a.base + "/" + f;
  };
  try {
    a.opt.ambient_T_K = a.ambient_C + 273.15;
    vehicle::VehicleParams vp;
    vp.chassis.payload_kg = a.payload;
    {  // gear loss set config/gearbox/<set>.yaml, as the launch argument gearbox:=<set>
      ParamSet gps;
      gps.setPrefix("gearbox/");
      vp.gearbox.declare(gps);
      applyParams(gps, readYamlParams(vehicle::gearLossSetFile(rel("config"), a.gearbox)));
    }
    mission::MissionParams mp;
    if (!a.cycle.empty()) mp.cycle_file = a.cycle;
    mp.cycle_file = rel(mp.cycle_file);
    mp.accel_limits_file = rel(mp.accel_limits_file);
    FILE* tf = a.trace.empty() ? nullptr : openTrace(a.trace, a.opt);
    const auto t0 = std::chrono::steady_clock::now();
    const vehicle::MissionRunResult r =
        vehicle::runMission(vp, engine_map::MapEngineParams{}, mp, a.opt, a.base);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (tf) std::fclose(tf);
    std::printf("mission %s, m = %.0f kg, ambient %.1f C, dt %.3f s, wall time %.1f s\n",
                mp.cycle_file.c_str(), vp.totalMass_kg(), a.ambient_C, a.opt.dt_s, wall);
    printResult(r, a.list_stops);
    return 0;
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "vehicle_mission: %s\n", ex.what());
    return 1;
  }
}
