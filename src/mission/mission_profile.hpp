// Time-based mission profile: the output of the pre-processor, sampled at a fixed dt.
//
// Built from a DistanceProfile (piecewise-constant acceleration over distance): step i lasts
//   dt_i = 2 ds_i / (v_i + v_{i+1})  [s]   (exact for constant acceleration),
// and at each stop point the vehicle stands for the stop time. The time axis is then sampled at
// t_k = k dt, k = 0..ceil(T/dt) (T = end of the last stop), with the exact kinematic state.
//
// Columns (CSV header exactly as below, one row per sample, SI units):
//   t_s            time since the start of the mission [s]
//   v_target_m_s   target vehicle speed at t_k [m/s]
//   a_target_m_s2  mean target acceleration over [t_k, t_k+1]: (v_{k+1} - v_k)/dt [m/s^2]
//                  (0 on the last row), so v_k = v_0 + sum_{j<k} a_j dt exactly
//   distance_m     exact position along the cycle at t_k [m] (cycle's <s> axis)
//   grade_percent  road gradient at distance_m [%] (left sample of the cycle)
//   altitude_m     altitude at distance_m [m] (integrated from the gradient, 0 at the start)
//   stop_flag      1 while the vehicle stands at a stop point for its stop time, else 0
// Interpolation helpers: speed linear in t (consistent with a_target), acceleration held over
// each sample interval, distance linear in t; grade and altitude are looked up from the cycle at
// the interpolated distance (or at any distance the caller supplies).
#pragma once
#include <string>
#include <vector>

#include "mission/driving_cycle.hpp"
#include "mission/speed_planner.hpp"

namespace hbt::mission {

struct ProfileSample {
  double t_s = 0.0;
  double v_target_m_s = 0.0;
  double a_target_m_s2 = 0.0;
  double distance_m = 0.0;
  double grade_percent = 0.0;
  double altitude_m = 0.0;
  int stop_flag = 0;
};

struct ProfileSummary {
  double duration_s = 0.0;          // time of the last sample [s]
  double distance_m = 0.0;          // distance covered (last - first distance_m) [m]
  std::size_t stops_in_cycle = 0;   // rows with v = 0 and stop > 0
  std::size_t stops_served = 0;     // standing periods (runs of stop_flag = 1) in the samples
  double standing_time_s = 0.0;     // total time with stop_flag = 1 [s]
  double max_accel_m_s2 = 0.0;      // largest a_target [m/s^2]
  double max_decel_m_s2 = 0.0;      // most negative a_target [m/s^2] (<= 0)
  double max_speed_m_s = 0.0;       // [m/s]
};

class MissionProfile {
 public:
  MissionProfile() = default;
  /// Samples `dp` (planned on `cycle`) at fixed dt_s > 0.
  static MissionProfile fromDistanceProfile(const DistanceProfile& dp, const DrivingCycle& cycle,
                                            double dt_s);

  const std::vector<ProfileSample>& samples() const { return samples_; }
  const DrivingCycle& cycle() const { return cycle_; }
  double dt_s() const { return dt_; }
  double duration_s() const { return samples_.empty() ? 0.0 : samples_.back().t_s; }

  double speedAt(double t_s) const;       // [m/s], linear between samples, clamped at the ends
  double accelAt(double t_s) const;       // [m/s^2], a_target of the sample interval holding t
  double distanceAt(double t_s) const;    // [m], linear between samples
  double gradeAt(double t_s) const;       // [%] at distanceAt(t)
  bool standingAtStop(double t_s) const;  // stop_flag of the sample interval holding t
  double gradeAtDistance(double s_m) const { return cycle_.gradeAt(s_m); }        // [%]
  double altitudeAtDistance(double s_m) const { return cycle_.altitudeAt(s_m); }  // [m]

  ProfileSummary summary() const;
  /// Writes the CSV described above. Throws InputError(path, "(file)", ...) if it cannot.
  void writeCsv(const std::string& path) const;

 private:
  std::size_t index(double t_s, double& frac) const;
  std::vector<ProfileSample> samples_;
  DrivingCycle cycle_;
  double dt_ = 0.1;
};

}  // namespace hbt::mission
