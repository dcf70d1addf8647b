// Distance-domain speed planner: VECTO-like driver on a distance-based cycle.
//
// Grid: every cycle sample s_k is a grid point; each interval is split into equal steps
// ds <= ds_max. On each step the acceleration is constant, a = (v_{i+1}^2 - v_i^2) / (2 ds),
// so the profile is exact piecewise-constant-acceleration kinematics.
//
// Rules, applied in this order (v_t = interval target speed, see DrivingCycle):
// 1. Forward pass (drive-off / cruise / downhill overspeed). Start at rest (or at the first
//    row's target if it is not a stop = "flying start"). On each step:
//    - v < v_t: accelerate, a = min(a_reach, a_max(v), a_power(v, grade)), a_reach bringing v
//      exactly to v_t; a_max from Bus.vacc, a_power from the wheel-power limit (RoadLoad).
//    - v >= v_t and overspeed allowed (enabled, v_t >= overspeed_min_speed) and the vehicle
//      accelerates while coasting (a_coast > 0, downhill): roll freely,
//      a = min(a_coast, a_max(v)), capped at v_t + overspeed (the brakes then hold it).
//    - v > v_t otherwise (after the downhill): coast back down, a = max(a_coast, a_min(v)),
//      never below v_t.
//    - cruise at v_t (on a climb the power limit may force a slow-down, bounded by a_min).
//    At stop points v = 0; where the target drops, v is clamped to the new target at its point.
// 2. Backward pass (look-ahead braking): v_i = min(v_i, sqrt(v_{i+1}^2 + 2 |a_min(v)| ds)),
//    i.e. the driver brakes at the deceleration limit so that every lower target is met
//    exactly at the point where it applies and the vehicle is at rest exactly at each stop.
// 3. Look-ahead coasting (VECTO "Look-Ahead Coasting", engineering-manual rule): for each
//    braking event from v_hi (speed where braking starts) down to v_lo at s_lo, if
//    v_hi >= lac_min_speed the deceleration start point is
//        s_c = s_lo - (v_hi^2 - v_lo^2) / (2 a_lookahead)       (a_lookahead > 0, 0.5 m/s^2)
//    From s_c the vehicle coasts, a = clamp(a_coast, max(-a_lookahead, a_min), a_max), until
//    the coasting curve meets the braking curve of rule 2, then brakes. On a climb where rolling
//    out would decelerate harder than a_lookahead the driver keeps some traction so that the
//    deceleration is a_lookahead: the curve then stays above the straight a_lookahead line
//    (in v^2 over s) through (s_lo, v_lo) and always meets the braking curve by s_lo.
//    Coasting never starts before the end of the previous braking event nor below that line
//    (it starts at the first point after s_c where v^2 >= v_lo^2 + 2 a_lookahead (s_lo - s));
//    where coasting would
//    speed the vehicle up (downhill) it ends at once (the rule-1/2 profile is kept).
// All accelerations stay within [a_min(v), a_max(v)] of the .vacc table. The result only uses
// vehicle-level data (mass, road load, wheel-power cap, driver limits): it is the same for
// every powertrain variant.
#pragma once
#include <cstddef>
#include <vector>

#include "mission/driving_cycle.hpp"
#include "mission/vehicle_limits.hpp"

namespace hbt::mission {

struct DriverRules {
  bool lac_enabled = true;                   // look-ahead coasting on/off
  double lac_min_speed_m_s = 50.0 / 3.6;     // [m/s] below it LAC is disabled (VECTO 50 km/h)
  double lac_target_decel_m_s2 = 0.5;        // [m/s^2] a_lookahead, VECTO default -0.5 m/s^2
  bool overspeed_enabled = true;             // downhill overspeed on/off
  double overspeed_min_speed_m_s = 50.0 / 3.6;  // [m/s] VECTO declaration 50 km/h
  double overspeed_m_s = 5.0 / 3.6;          // [m/s] allowed overspeed above target (5 km/h)
};

/// Speed over the distance grid. Point i: s_m[i], v_m_s[i]; on [s_i, s_{i+1}] the
/// acceleration is constant. dwell_s[i] > 0 only at stop points (time standing there).
struct DistanceProfile {
  std::vector<double> s_m;
  std::vector<double> v_m_s;
  std::vector<double> dwell_s;
  std::vector<char> stop_point;  // 1 where the cycle has a stop row (v = 0 forced)
  std::size_t size() const { return s_m.size(); }
  /// Constant acceleration on step i (between points i and i+1) [m/s^2].
  double stepAccel_m_s2(std::size_t i) const;
};

/// Plans the speed over distance with rules 1-3. ds_max_m > 0 is the grid step [m].
DistanceProfile planSpeedOverDistance(const DrivingCycle& cycle, const AccelerationLimits& acc,
                                      const RoadLoad& road, const DriverRules& rules,
                                      double ds_max_m);

}  // namespace hbt::mission
