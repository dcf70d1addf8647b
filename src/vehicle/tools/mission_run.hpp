// Full mission in-process: the time-based mission profile (src/mission) followed by the bus
// (VehicleModel) coupled in lock-step with the map engine (CoupledSim: 10 ms exchange, engine
// torque one exchange late), set up exactly like the ROS vehicle participant
// (src/vehicle/node/vehicle_participant.cpp): profile built with this bus's mass, rotating mass,
// CdA and RRC; grade vs the bus's own distance; reset at the profile's first speed in neutral;
// each step gets the target speed / acceleration for t + dt.
//
// Stop service criterion (per stop of the profile, a run of stop_flag = 1 starting at t_0 and
// lasting D): mission::StopService (config/mission.yaml stop_service/: the bus below
// standstill_speed_m_s for >= served_fraction · D within [t_0, t_0 + D + window_after_s]).
// Position error of a stop: bus distance while standing in that window (first standstill
// instant) minus the profile's stop position (if it never stands: the distance at t_0 + D).
// Used by the vehicle_mission tool and the full-mission test.
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "mission/mission_preprocessor.hpp"
#include "vehicle/tools/coupled_sim.hpp"

namespace hbt::vehicle {

struct MissionStopResult {
  double t_start_s = 0.0, duration_s = 0.0, position_m = 0.0;  // from the profile
  double standing_s = 0.0;       // bus standing still within the stop's window
  double position_error_m = 0.0; // bus distance at the stop - profile stop position
  bool served = false;
};

struct MissionRunResult {
  double duration_s = 0.0, distance_m = 0.0, target_distance_m = 0.0;
  double speed_rmse_m_s = 0.0, max_speed_error_m_s = 0.0;
  std::vector<MissionStopResult> stops;
  std::size_t stops_served = 0;
  double max_stop_position_error_m = 0.0;  // max |position_error_m|
  double fuel_kg = 0.0, engine_positive_work_J = 0.0, engine_brake_work_J = 0.0;
  double wall_time_s = 0.0;
  VehicleEnergy energy;     // vehicle's cumulative energies at the end
  double idle_standing_s = 0.0;  // total time standing still (StopService::standstill_speed_m_s)
};

struct MissionRunOptions {
  double dt_s = 0.01;
  double ambient_T_K = 298.15;
  double t_end_s = -1.0;  // < 0: whole profile
  /// Optional observer after every step: (t, vehicle outputs, engine outputs, target speed).
  std::function<void(double, const VehicleOutputs&, const engine_map::MapEngineOutputs&, double)>
      on_step;
};

inline MissionRunResult runMission(const VehicleParams& vp, const engine_map::MapEngineParams& ep,
                                   mission::MissionParams mp, const MissionRunOptions& opt,
                                   const std::string& base_dir = "") {
  MissionRunResult res;
  CoupledSim sim(vp, ep, base_dir);
  const VehicleModel& vm = sim.vehicleModel();
  mp.vehicle.mass_kg = vp.totalMass_kg();
  mp.vehicle.rotating_mass_kg = vm.vehicleInertiaMass_kg() - vp.totalMass_kg();
  mp.vehicle.cda_m2 = vp.chassis.cda_m2;
  mp.vehicle.rrc = vm.roadLoad().rollingCoefficient();
  const mission::MissionProfile prof = mission::buildMissionProfile(mp);
  const mission::StopService& sv = mp.stop_service;
  const auto& cyc = prof.cycle();
  std::vector<double> grade(cyc.grade_percent.size());
  for (std::size_t i = 0; i < grade.size(); ++i) grade[i] = cyc.grade_percent[i] / 100.0;

  // Stops of the profile (runs of stop_flag = 1), as the participant's stops.csv.
  const auto& s = prof.samples();
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s[i].stop_flag || (i > 0 && s[i - 1].stop_flag)) continue;
    std::size_t j = i;
    while (j + 1 < s.size() && s[j + 1].stop_flag) ++j;
    MissionStopResult st;
    st.t_start_s = s[i].t_s;
    st.duration_s = s[j].t_s - s[i].t_s;
    st.position_m = s[i].distance_m;
    st.position_error_m = NAN;
    res.stops.push_back(st);
  }

  sim.setGradeProfile(cyc.distance_m, grade);
  sim.reset(prof.speedAt(0.0), 0, opt.ambient_T_K);
  const double T = opt.t_end_s > 0.0 ? std::min(opt.t_end_s, prof.duration_s()) : prof.duration_s();
  const long n = static_cast<long>(std::floor(T / opt.dt_s + 1e-9));
  double se2 = 0.0;
  std::size_t k_stop = 0;
  for (long k = 0; k < n; ++k) {
    const double t = k * opt.dt_s, t1 = t + opt.dt_s;
    VehicleInputs in;
    in.target_speed_m_s = prof.speedAt(t1);
    in.target_accel_m_s2 = prof.accelAt(t1);
    sim.step(opt.dt_s, in);
    const VehicleOutputs& o = sim.vehicle();
    if (opt.on_step) opt.on_step(t1, o, sim.engine(), prof.speedAt(t1));
    const double e = o.speed_m_s - prof.speedAt(t1);
    se2 += e * e;
    res.max_speed_error_m_s = std::max(res.max_speed_error_m_s, std::fabs(e));
    const bool still = o.speed_m_s < sv.standstill_speed_m_s;
    if (still) res.idle_standing_s += opt.dt_s;
    // Stop windows (non-overlapping in time in practice; check every window that holds t1).
    while (k_stop < res.stops.size() &&
           t1 > res.stops[k_stop].t_start_s + res.stops[k_stop].duration_s + sv.window_after_s)
      ++k_stop;
    for (std::size_t q = k_stop; q < res.stops.size() && res.stops[q].t_start_s < t1; ++q) {
      MissionStopResult& st = res.stops[q];
      const double w_end = st.t_start_s + st.duration_s + sv.window_after_s;
      if (t1 > w_end + 1e-9) continue;
      if (still) {
        st.standing_s += std::min(opt.dt_s, t1 - st.t_start_s);
        if (std::isnan(st.position_error_m)) st.position_error_m = o.distance_m - st.position_m;
      }
      if (std::fabs(t1 - (st.t_start_s + st.duration_s)) < 0.5 * opt.dt_s &&
          std::isnan(st.position_error_m) && !still) {
        st.position_error_m = o.distance_m - st.position_m;  // not standing at the stop's end
      }
    }
  }
  res.duration_s = n * opt.dt_s;
  res.speed_rmse_m_s = n > 0 ? std::sqrt(se2 / n) : 0.0;
  res.distance_m = sim.vehicle().distance_m;
  res.target_distance_m = prof.distanceAt(res.duration_s) - prof.distanceAt(0.0);
  for (auto& st : res.stops) {
    if (st.t_start_s + st.duration_s > res.duration_s) continue;
    st.served = st.standing_s >= sv.served_fraction * st.duration_s - 1e-9;
    if (st.served) ++res.stops_served;
    if (!std::isnan(st.position_error_m))
      res.max_stop_position_error_m = std::max(res.max_stop_position_error_m, std::fabs(st.position_error_m));
  }
  res.energy = sim.vehicle().energy;
  res.fuel_kg = sim.engine().fuel_mass_kg;
  res.engine_positive_work_J = sim.engine().positive_work_J;
  res.engine_brake_work_J = sim.engine().brake_work_J;
  return res;
}

}  // namespace hbt::vehicle
