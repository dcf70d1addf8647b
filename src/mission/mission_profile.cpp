#include "mission/mission_profile.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "common/errors.hpp"

namespace hbt::mission {
namespace {

// Time knots: state at each knot, constant acceleration up to the next knot.
struct Knot {
  double t, s, v;
  bool dwell_after;  // the interval to the next knot is a stop dwell (v = 0)
};

std::vector<Knot> timeKnots(const DistanceProfile& dp) {
  std::vector<Knot> k;
  k.reserve(dp.size() + 256);
  double t = 0.0;
  for (std::size_t i = 0; i < dp.size(); ++i) {
    const double v = dp.v_m_s[i];
    if (dp.dwell_s[i] > 0.0) {
      k.push_back({t, dp.s_m[i], v, true});
      t += dp.dwell_s[i];
    }
    k.push_back({t, dp.s_m[i], v, false});
    if (i + 1 < dp.size()) {
      const double vs = v + dp.v_m_s[i + 1];
      if (!(vs > 0.0))
        throw ModelDivergence("mission profile", "speed",
                              "zero speed on both ends of a step at s = " +
                                  std::to_string(dp.s_m[i]) + " m (vehicle cannot advance)");
      t += 2.0 * (dp.s_m[i + 1] - dp.s_m[i]) / vs;
    }
  }
  return k;
}

}  // namespace

MissionProfile MissionProfile::fromDistanceProfile(const DistanceProfile& dp,
                                                   const DrivingCycle& cycle, double dt_s) {
  if (!(dt_s > 0.0)) throw InputError(cycle.source, "dt_s", "sample time must be > 0");
  MissionProfile p;
  p.cycle_ = cycle;
  p.dt_ = dt_s;
  const std::vector<Knot> kn = timeKnots(dp);
  const double tEnd = kn.back().t;
  const auto nSamples = static_cast<std::size_t>(std::ceil(tEnd / dt_s - 1e-9)) + 1;
  p.samples_.resize(nSamples);
  std::size_t j = 0;
  for (std::size_t k = 0; k < nSamples; ++k) {
    const double t = double(k) * dt_s;
    while (j + 1 < kn.size() && kn[j + 1].t <= t) ++j;
    ProfileSample& o = p.samples_[k];
    o.t_s = t;
    if (j + 1 < kn.size()) {
      const double span = kn[j + 1].t - kn[j].t;
      const double a = span > 0.0 ? (kn[j + 1].v - kn[j].v) / span : 0.0;
      const double tau = t - kn[j].t;
      o.v_target_m_s = std::max(0.0, kn[j].v + a * tau);
      o.distance_m = std::min(kn[j].s + kn[j].v * tau + 0.5 * a * tau * tau, kn[j + 1].s);
      o.stop_flag = kn[j].dwell_after ? 1 : 0;
    } else {  // past the end: hold the final state (standing after the last stop)
      o.v_target_m_s = kn.back().v;
      o.distance_m = kn.back().s;
      o.stop_flag = 0;
    }
    o.grade_percent = cycle.gradeAt(o.distance_m);
    o.altitude_m = cycle.altitudeAt(o.distance_m);
  }
  for (std::size_t k = 0; k + 1 < nSamples; ++k)
    p.samples_[k].a_target_m_s2 =
        (p.samples_[k + 1].v_target_m_s - p.samples_[k].v_target_m_s) / dt_s;
  return p;
}

std::size_t MissionProfile::index(double t_s, double& frac) const {
  const double x = std::clamp(t_s / dt_, 0.0, double(samples_.size() - 1));
  std::size_t k = static_cast<std::size_t>(std::floor(x));
  if (k + 1 >= samples_.size()) k = samples_.size() >= 2 ? samples_.size() - 2 : 0;
  frac = samples_.size() >= 2 ? x - double(k) : 0.0;
  return k;
}

double MissionProfile::speedAt(double t_s) const {
  double f;
  const std::size_t k = index(t_s, f);
  if (samples_.size() < 2) return samples_.front().v_target_m_s;
  return samples_[k].v_target_m_s + f * (samples_[k + 1].v_target_m_s - samples_[k].v_target_m_s);
}

double MissionProfile::accelAt(double t_s) const {
  double f;
  const std::size_t k = index(t_s, f);
  return f >= 1.0 ? samples_[k + 1].a_target_m_s2 : samples_[k].a_target_m_s2;
}

double MissionProfile::distanceAt(double t_s) const {
  double f;
  const std::size_t k = index(t_s, f);
  if (samples_.size() < 2) return samples_.front().distance_m;
  return samples_[k].distance_m + f * (samples_[k + 1].distance_m - samples_[k].distance_m);
}

double MissionProfile::gradeAt(double t_s) const { return cycle_.gradeAt(distanceAt(t_s)); }

bool MissionProfile::standingAtStop(double t_s) const {
  double f;
  const std::size_t k = index(t_s, f);
  return (f >= 1.0 ? samples_[k + 1].stop_flag : samples_[k].stop_flag) != 0;
}

ProfileSummary MissionProfile::summary() const {
  ProfileSummary s;
  if (samples_.empty()) return s;
  s.duration_s = samples_.back().t_s;
  s.distance_m = samples_.back().distance_m - samples_.front().distance_m;
  s.stops_in_cycle = cycle_.stopCount();
  int prevFlag = 0;
  for (const auto& x : samples_) {
    if (x.stop_flag && !prevFlag) ++s.stops_served;
    if (x.stop_flag) s.standing_time_s += dt_;
    prevFlag = x.stop_flag;
    s.max_accel_m_s2 = std::max(s.max_accel_m_s2, x.a_target_m_s2);
    s.max_decel_m_s2 = std::min(s.max_decel_m_s2, x.a_target_m_s2);
    s.max_speed_m_s = std::max(s.max_speed_m_s, x.v_target_m_s);
  }
  return s;
}

void MissionProfile::writeCsv(const std::string& path) const {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw InputError(path, "(file)", "cannot open the profile file for writing");
  std::fprintf(f, "# mission profile from %s, dt = %.6g s (see src/mission/README.md)\n",
               cycle_.source.c_str(), dt_);
  std::fprintf(f, "t_s,v_target_m_s,a_target_m_s2,distance_m,grade_percent,altitude_m,stop_flag\n");
  for (const auto& x : samples_)
    std::fprintf(f, "%.10g,%.12g,%.12g,%.12g,%.10g,%.10g,%d\n", x.t_s, x.v_target_m_s,
                 x.a_target_m_s2, x.distance_m, x.grade_percent, x.altitude_m, x.stop_flag);
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) throw InputError(path, "(file)", "error while writing");
}

}  // namespace hbt::mission
