#include "mission/speed_planner.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace hbt::mission {
namespace {

constexpr double kEps_m_s = 1e-9;

struct Grid {
  std::vector<double> s, vt, vmax, grade, dwell;
  std::vector<char> stop;
};

double sqrtPos(double x) { return std::sqrt(std::max(0.0, x)); }

// Grid points, target, clamp speed and grade per point (grade/target of the step starting there).
Grid buildGrid(const DrivingCycle& c, const DriverRules& r, double ds_max) {
  Grid g;
  const std::size_t n = c.size();
  auto osAllowed = [&](double vt) {
    return r.overspeed_enabled && vt >= r.overspeed_min_speed_m_s - kEps_m_s;
  };
  for (std::size_t k = 0; k < n; ++k) {
    const double vt = c.intervalTarget_m_s(k);
    if (k + 1 < n && vt <= 0.0)
      throw InputError(c.source, "v", "rows " + std::to_string(k + 1) + "-" +
                                          std::to_string(k + 2) +
                                          ": zero target speed after a stop point (the vehicle "
                                          "could never reach the next row)");
    const bool stop = c.isStopPoint(k);
    const double prevVt = k > 0 ? c.intervalTarget_m_s(k - 1) : vt;
    const double vmaxHere = stop ? 0.0 : (vt < prevVt ? vt : vt + (osAllowed(vt) ? r.overspeed_m_s : 0.0));
    const std::size_t m =
        k + 1 < n ? std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(
                                                 (c.distance_m[k + 1] - c.distance_m[k]) / ds_max - 1e-9)))
                  : 1;
    const double step = k + 1 < n ? (c.distance_m[k + 1] - c.distance_m[k]) / double(m) : 0.0;
    for (std::size_t j = 0; j < m; ++j) {
      g.s.push_back(j == 0 ? c.distance_m[k] : c.distance_m[k] + double(j) * step);
      g.vt.push_back(vt);
      g.vmax.push_back(j == 0 ? vmaxHere : vt + (osAllowed(vt) ? r.overspeed_m_s : 0.0));
      g.grade.push_back(c.grade_percent[k]);
      g.stop.push_back(j == 0 && stop ? 1 : 0);
      g.dwell.push_back(j == 0 && stop ? c.stop_time_s[k] : 0.0);
    }
    if (k + 1 == n) break;
  }
  return g;
}

// Conservative limits over a step of length ds starting at speed v (the table is evaluated at
// both ends of the step and the tighter value is taken).
struct StepLimits {
  const AccelerationLimits& acc;
  const RoadLoad& road;
  double accel(double v, double ds, double grade) const {
    const double a0 = std::min(acc.maxAccel_m_s2(v), road.powerLimitedAccel_m_s2(v, grade));
    const double v1 = sqrtPos(v * v + 2.0 * std::max(a0, 0.0) * ds);
    return std::min({a0, acc.maxAccel_m_s2(v1), road.powerLimitedAccel_m_s2(v1, grade)});
  }
  double accelNoPower(double v, double ds) const {
    const double a0 = acc.maxAccel_m_s2(v);
    return std::min(a0, acc.maxAccel_m_s2(sqrtPos(v * v + 2.0 * a0 * ds)));
  }
  // Deceleration limit (< 0) for a step that ends at v_end (backward) or starts at v (forward).
  double decel(double v, double ds, bool backward) const {
    const double d0 = acc.maxDecel_m_s2(v);
    const double v1 = sqrtPos(v * v + (backward ? -2.0 : 2.0) * d0 * ds);
    return std::max(d0, acc.maxDecel_m_s2(v1));
  }
};

void forwardPass(const Grid& g, const StepLimits& lim, const RoadLoad& road, const DriverRules& r,
                 std::vector<double>& v) {
  const std::size_t n = g.s.size();
  v.assign(n, 0.0);
  v[0] = g.stop[0] ? 0.0 : g.vt[0];  // at rest at a stop, else "flying start" at the target
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double ds = g.s[i + 1] - g.s[i], vt = g.vt[i], vi = v[i];
    const bool os = r.overspeed_enabled && vt >= r.overspeed_min_speed_m_s - kEps_m_s;
    const double ac = road.coastingAccel_m_s2(vi, g.grade[i]);
    double vn;
    if (os && vi >= vt - kEps_m_s && ac > 0.0) {  // downhill: roll freely up to vt + overspeed
      const double a = std::min(ac, lim.accelNoPower(vi, ds));
      vn = std::min(sqrtPos(vi * vi + 2.0 * a * ds), vt + r.overspeed_m_s);
    } else if (vi > vt + kEps_m_s) {  // above target: coast back down to it
      const double a = std::max(std::min(ac, 0.0), lim.decel(vi, ds, false));
      vn = std::max(sqrtPos(vi * vi + 2.0 * a * ds), vt);
    } else {  // accelerate to / cruise at the target
      const double reach = (vt * vt - vi * vi) / (2.0 * ds);
      double a = std::min(reach, lim.accel(vi, ds, g.grade[i]));
      a = std::max(a, lim.decel(vi, ds, false));
      vn = sqrtPos(vi * vi + 2.0 * a * ds);
    }
    v[i + 1] = std::min(vn, g.vmax[i + 1]);
  }
}

void backwardPass(const Grid& g, const StepLimits& lim, std::vector<double>& v) {
  for (std::size_t i = v.size() - 1; i-- > 0;) {
    const double ds = g.s[i + 1] - g.s[i], v1 = v[i + 1];
    const double d = lim.decel(v1, ds, true);
    v[i] = std::min(v[i], sqrtPos(v1 * v1 - 2.0 * d * ds));
  }
}

void lookAheadCoasting(const Grid& g, const StepLimits& lim, const RoadLoad& road,
                       const DriverRules& r, const std::vector<double>& vf, std::vector<double>& v) {
  const std::size_t n = v.size();
  std::size_t prevEnd = 0, i = 1;
  while (i < n) {
    if (!(v[i] < vf[i] - kEps_m_s)) { ++i; continue; }
    const std::size_t ib = i;  // first point lowered by the braking pass
    while (i < n && v[i] < vf[i] - kEps_m_s) ++i;
    const std::size_t jend = std::min(i, n - 1);  // the point whose lower speed is the goal
    const double vhi = v[ib - 1], vlo = v[jend];
    // Coasting curve: a = clamp(a_coast, max(-a_lookahead, a_min), a_max). Its deceleration
    // never exceeds a_lookahead, so it stays above the a_lookahead line through (s_lo, v_lo)
    // and is bound to meet the braking curve at or before s_lo (no stall before a stop).
    if (r.lac_enabled && vhi >= r.lac_min_speed_m_s - kEps_m_s && vhi > vlo) {
      const double sc = g.s[jend] - (vhi * vhi - vlo * vlo) / (2.0 * r.lac_target_decel_m_s2);
      std::size_t ic = static_cast<std::size_t>(
          std::lower_bound(g.s.begin(), g.s.end(), sc) - g.s.begin());
      ic = std::max(ic, prevEnd);
      // Start on or above the a_lookahead line (after a previous event the vehicle may still
      // be accelerating below it): v^2 >= v_lo^2 + 2 a_lookahead (s_lo - s).
      auto line2 = [&](std::size_t j) {
        return vlo * vlo + 2.0 * r.lac_target_decel_m_s2 * (g.s[jend] - g.s[j]);
      };
      while (ic + 1 < ib && v[ic] * v[ic] < line2(ic)) ++ic;
      if (ic + 1 < ib) {
        double c = v[ic];
        for (std::size_t j = ic; j < jend; ++j) {
          const double ds = g.s[j + 1] - g.s[j];
          double a = road.coastingAccel_m_s2(c, g.grade[j]);
          const double aLow = std::max(-r.lac_target_decel_m_s2, lim.decel(c, ds, false));
          a = std::clamp(a, aLow, std::max(aLow, lim.accelNoPower(c, ds)));
          const double cn = sqrtPos(c * c + 2.0 * a * ds);
          if (cn >= v[j + 1]) break;  // coasting curve met the braking curve
          v[j + 1] = cn;
          c = cn;
        }
      }
    }
    prevEnd = jend;
    i = jend + 1;
  }
}

}  // namespace

double DistanceProfile::stepAccel_m_s2(std::size_t i) const {
  return (v_m_s[i + 1] * v_m_s[i + 1] - v_m_s[i] * v_m_s[i]) / (2.0 * (s_m[i + 1] - s_m[i]));
}

DistanceProfile planSpeedOverDistance(const DrivingCycle& cycle, const AccelerationLimits& acc,
                                      const RoadLoad& road, const DriverRules& rules,
                                      double ds_max_m) {
  if (!(ds_max_m > 0.0)) throw InputError(cycle.source, "ds_max_m", "grid step must be > 0");
  const Grid g = buildGrid(cycle, rules, ds_max_m);
  const StepLimits lim{acc, road};
  std::vector<double> vf, v;
  forwardPass(g, lim, road, rules, vf);
  v = vf;
  backwardPass(g, lim, v);
  lookAheadCoasting(g, lim, road, rules, vf, v);
  DistanceProfile p;
  p.s_m = g.s;
  p.v_m_s = std::move(v);
  p.dwell_s = g.dwell;
  p.stop_point = g.stop;
  return p;
}

}  // namespace hbt::mission
