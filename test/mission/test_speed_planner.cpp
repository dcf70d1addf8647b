// Speed planner on synthetic cycles against closed-form kinematics (constant limits, no aero
// unless stated) and an independent RK4 integration for the power limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mission/mission_profile.hpp"
#include "mission/speed_planner.hpp"
#include "mission/vehicle_limits.hpp"

using namespace hbt::mission;

namespace {

constexpr double g = 9.81;
constexpr double kDs = 0.25;

RoadLoadParams noAeroNoPower() {
  RoadLoadParams p;
  p.cda_m2 = 0.0;
  p.max_wheel_power_W = 0.0;
  return p;
}
DriverRules rulesOff() {
  DriverRules r;
  r.lac_enabled = false;
  r.overspeed_enabled = false;
  return r;
}
double vAt(const DistanceProfile& dp, double s) {  // value at a grid point
  const auto it = std::lower_bound(dp.s_m.begin(), dp.s_m.end(), s - 1e-9);
  EXPECT_NEAR(*it, s, 1e-9) << "not a grid point";
  return dp.v_m_s[static_cast<std::size_t>(it - dp.s_m.begin())];
}
// Grid points s in [a, b] (a, b snapped inward to the grid).
template <class F>
void forGrid(const DistanceProfile& dp, double a, double b, F f) {
  for (std::size_t i = 0; i < dp.size(); ++i)
    if (dp.s_m[i] >= a && dp.s_m[i] <= b) f(dp.s_m[i], dp.v_m_s[i]);
}

}  // namespace

TEST(Planner, ConstantSpeedFlatCycleIsExact) {
  const DrivingCycle c = makeCycle("flat", {0, 1000}, {50, 50}, {0, 0}, {0, 0});
  const auto acc = AccelerationLimits::readVacc("config/data/vehicle/citybus_P1_hybrid_48V/Bus.vacc");
  const DistanceProfile dp = planSpeedOverDistance(c, acc, RoadLoad(RoadLoadParams{}), DriverRules{}, kDs);
  for (double v : dp.v_m_s) EXPECT_DOUBLE_EQ(v, 50 / 3.6);
  const MissionProfile mp = MissionProfile::fromDistanceProfile(dp, c, 0.1);
  const double v = 50 / 3.6;
  EXPECT_NEAR(mp.duration_s(), 1000 / v, 1e-9);  // 72 s, a multiple of dt
  for (const auto& x : mp.samples()) {
    EXPECT_NEAR(x.v_target_m_s, v, 1e-12);
    EXPECT_NEAR(x.a_target_m_s2, 0.0, 1e-9);
    EXPECT_NEAR(x.distance_m, v * x.t_s, 1e-9);  // t = s / v
    EXPECT_EQ(x.stop_flag, 0);
  }
}

TEST(Planner, BrakesAheadToMeetLowerTargetAtItsPoint) {
  const double d = 0.8, v1 = 40 / 3.6, v2 = 20 / 3.6;
  const DrivingCycle c = makeCycle("drop", {0, 500, 1000}, {40, 20, 20}, {0, 0, 0}, {0, 0, 0});
  const auto acc = AccelerationLimits::constant(1.0, -d);
  const DistanceProfile dp = planSpeedOverDistance(c, acc, RoadLoad(noAeroNoPower()), rulesOff(), kDs);
  const double sb = 500 - (v1 * v1 - v2 * v2) / (2 * d);  // braking starts here
  forGrid(dp, 0, sb - kDs, [&](double, double v) { EXPECT_NEAR(v, v1, 1e-9); });
  forGrid(dp, sb + kDs, 500, [&](double s, double v) {
    EXPECT_NEAR(v, std::sqrt(v2 * v2 + 2 * d * (500 - s)), 1e-9) << s;
  });
  EXPECT_NEAR(vAt(dp, 500), v2, 1e-12);
  forGrid(dp, 500, 1000, [&](double, double v) { EXPECT_NEAR(v, v2, 1e-9); });
  // Time-based: position vs the closed-form s(t).
  const MissionProfile mp = MissionProfile::fromDistanceProfile(dp, c, 0.1);
  const double t1 = sb / v1, t2 = t1 + (v1 - v2) / d, T = t2 + 500 / v2;
  EXPECT_GE(mp.duration_s(), T - 1e-6);
  EXPECT_LT(mp.duration_s(), T + 0.1);
  for (const auto& x : mp.samples()) {
    const double t = std::min(x.t_s, T);
    const double s = t < t1 ? v1 * t
                     : t < t2 ? sb + v1 * (t - t1) - 0.5 * d * (t - t1) * (t - t1)
                              : 500 + v2 * (t - t2);
    EXPECT_NEAR(x.distance_m, s, 2e-3) << x.t_s;
  }
}

TEST(Planner, StopServedExactlyAtItsPosition) {
  const double d = 0.8, a = 1.0, v = 10.0;
  const DrivingCycle c = makeCycle("stop", {0, 300, 1000}, {36, 0, 36}, {0, 0, 0}, {0, 10, 0});
  const auto acc = AccelerationLimits::constant(a, -d);
  const DistanceProfile dp = planSpeedOverDistance(c, acc, RoadLoad(noAeroNoPower()), rulesOff(), kDs);
  EXPECT_EQ(vAt(dp, 300), 0.0);
  EXPECT_NEAR(vAt(dp, 300 - v * v / (2 * d)), v, 1e-9);   // braking starts at 237.5 m
  EXPECT_NEAR(vAt(dp, 300 + v * v / (2 * a)), v, 1e-9);   // target regained at 350 m
  EXPECT_NEAR(vAt(dp, 325), std::sqrt(2 * a * 25), 1e-9);
  const MissionProfile mp = MissionProfile::fromDistanceProfile(dp, c, 0.1);
  const double tArr = 237.5 / v + v / d, tDep = tArr + 10.0;
  const double T = tDep + v / a + (1000 - 350) / v;  // 121.25 s
  EXPECT_GE(mp.duration_s(), T - 1e-6);
  EXPECT_LT(mp.duration_s(), T + 0.1);
  for (const auto& x : mp.samples()) {
    if (x.t_s > tArr + 1e-6 && x.t_s < tDep - 1e-6) {
      EXPECT_EQ(x.v_target_m_s, 0.0);
      EXPECT_EQ(x.distance_m, 300.0);
      EXPECT_EQ(x.stop_flag, 1);
    } else if (x.t_s < tArr - 1e-6 || x.t_s > tDep + 1e-6) {
      EXPECT_EQ(x.stop_flag, 0) << x.t_s;
    }
  }
  const ProfileSummary s = mp.summary();
  EXPECT_EQ(s.stops_in_cycle, 1u);
  EXPECT_EQ(s.stops_served, 1u);
  EXPECT_NEAR(s.standing_time_s, 10.0, 0.1 + 1e-9);
}

TEST(Planner, LookAheadCoastingThenBraking) {
  const double d = 0.8, aLA = 0.5, v1 = 70 / 3.6, v2 = 30 / 3.6;
  const DrivingCycle c = makeCycle("lac", {0, 2000, 3000}, {70, 30, 30}, {0, 0, 0}, {0, 0, 0});
  const auto acc = AccelerationLimits::constant(1.0, -d);
  const RoadLoadParams rp = noAeroNoPower();
  DriverRules r = rulesOff();
  r.lac_enabled = true;
  r.lac_min_speed_m_s = 50 / 3.6;
  r.lac_target_decel_m_s2 = aLA;
  const DistanceProfile dp = planSpeedOverDistance(c, acc, RoadLoad(rp), r, kDs);
  const double ac = rp.mass_kg * g * rp.rrc / (rp.mass_kg + rp.rotating_mass_kg);  // coasting decel
  const double sc = 2000 - (v1 * v1 - v2 * v2) / (2 * aLA);                        // VECTO start point
  const double sm = (v2 * v2 + 2 * d * 2000 - v1 * v1 - 2 * ac * sc) / (2 * d - 2 * ac);  // meets braking
  auto C = [&](double s) { return std::sqrt(v1 * v1 - 2 * ac * (s - sc)); };
  auto B = [&](double s) { return std::sqrt(v2 * v2 + 2 * d * (2000 - s)); };
  ASSERT_LT(sc, sm);
  forGrid(dp, 0, sc - kDs, [&](double, double v) { EXPECT_NEAR(v, v1, 1e-9); });
  forGrid(dp, sc + kDs, sm - kDs, [&](double s, double v) { EXPECT_NEAR(v, C(s), 2e-3) << s; });
  forGrid(dp, sm + kDs, 2000, [&](double s, double v) { EXPECT_NEAR(v, B(s), 1e-9) << s; });
  EXPECT_NEAR(vAt(dp, 2000), v2, 1e-12);
  // Below the LAC minimum speed only the braking phase remains.
  r.lac_min_speed_m_s = 80 / 3.6;
  const DistanceProfile db = planSpeedOverDistance(c, acc, RoadLoad(rp), r, kDs);
  const double sb = 2000 - (v1 * v1 - v2 * v2) / (2 * d);
  forGrid(db, 0, sb - kDs, [&](double, double v) { EXPECT_NEAR(v, v1, 1e-9); });
  forGrid(db, sb + kDs, 2000, [&](double s, double v) { EXPECT_NEAR(v, B(s), 1e-9); });
}

TEST(Planner, OverspeedOnDownhillOnlyAboveMinSpeed) {
  const DrivingCycle c60 = makeCycle("os", {0, 500, 1500, 3000}, {60, 60, 60, 60},
                                     {0, -6, 0, 0}, {0, 0, 0, 0});
  const auto acc = AccelerationLimits::constant(1.0, -0.8);
  const RoadLoadParams rp = noAeroNoPower();
  DriverRules r = rulesOff();
  r.overspeed_enabled = true;
  r.overspeed_min_speed_m_s = 50 / 3.6;
  r.overspeed_m_s = 5 / 3.6;
  const DistanceProfile dp = planSpeedOverDistance(c60, acc, RoadLoad(rp), r, kDs);
  const double me = rp.mass_kg + rp.rotating_mass_kg, al = std::atan(-0.06);
  const double aDown = -rp.mass_kg * g * (rp.rrc * std::cos(al) + std::sin(al)) / me;  // > 0
  const double aFlat = rp.mass_kg * g * rp.rrc / me;
  const double v0 = 60 / 3.6, vmax = 65 / 3.6;
  const double sReach = 500 + (vmax * vmax - v0 * v0) / (2 * aDown);
  const double sBack = 1500 + (vmax * vmax - v0 * v0) / (2 * aFlat);
  ASSERT_GT(aDown, 0.0);
  ASSERT_LT(sBack, 3000.0);
  forGrid(dp, 0, 500, [&](double, double v) { EXPECT_NEAR(v, v0, 1e-9); });
  forGrid(dp, 500, sReach - kDs, [&](double s, double v) {
    EXPECT_NEAR(v, std::sqrt(v0 * v0 + 2 * aDown * (s - 500)), 1e-9) << s;
  });
  forGrid(dp, sReach + kDs, 1500, [&](double, double v) { EXPECT_NEAR(v, vmax, 1e-9); });
  forGrid(dp, 1500, sBack - kDs, [&](double s, double v) {
    EXPECT_NEAR(v, std::sqrt(vmax * vmax - 2 * aFlat * (s - 1500)), 1e-9) << s;
  });
  forGrid(dp, sBack + kDs, 3000, [&](double, double v) { EXPECT_NEAR(v, v0, 1e-9); });
  // Target 40 km/h < 50 km/h minimum: no overspeed; overspeed disabled: none either.
  const DrivingCycle c40 = makeCycle("os40", {0, 500, 1500, 3000}, {40, 40, 40, 40},
                                     {0, -6, 0, 0}, {0, 0, 0, 0});
  const DistanceProfile d40 = planSpeedOverDistance(c40, acc, RoadLoad(rp), r, kDs);
  EXPECT_NEAR(*std::max_element(d40.v_m_s.begin(), d40.v_m_s.end()), 40 / 3.6, 1e-12);
  r.overspeed_enabled = false;
  const DistanceProfile dOff = planSpeedOverDistance(c60, acc, RoadLoad(rp), r, kDs);
  EXPECT_NEAR(*std::max_element(dOff.v_m_s.begin(), dOff.v_m_s.end()), v0, 1e-12);
}

TEST(Planner, WheelPowerLimitMatchesRk4Reference) {
  RoadLoadParams rp;  // default mass, RRC, CdA
  rp.max_wheel_power_W = 100e3;
  const RoadLoad road(rp);
  const DrivingCycle c = makeCycle("pow", {0, 2000}, {0, 80}, {0, 0}, {1, 0});
  const auto acc = AccelerationLimits::constant(5.0, -0.8);
  const DistanceProfile dp = planSpeedOverDistance(c, acc, road, rulesOff(), kDs);
  const double me = rp.mass_kg + rp.rotating_mass_kg;
  for (std::size_t i = 0; i + 1 < dp.size(); ++i) {  // wheel power never above the cap
    const double a = dp.stepAccel_m_s2(i);
    for (double v : {dp.v_m_s[i], dp.v_m_s[i + 1]}) {
      const double F = rp.mass_kg * g * rp.rrc + 0.5 * rp.air_density_kg_m3 * rp.cda_m2 * v * v;
      EXPECT_LE((me * a + F) * v, rp.max_wheel_power_W * (1 + 1e-9)) << dp.s_m[i];
    }
  }
  // Independent reference: RK4 in time of dv/dt = min(5, (P/v - F(v))/m_e), ds/dt = v.
  auto f = [&](double v) {
    const double F = rp.mass_kg * g * rp.rrc + 0.5 * rp.air_density_kg_m3 * rp.cda_m2 * v * v;
    return std::min(5.0, (rp.max_wheel_power_W / std::max(v, 1e-6) - F) / me);
  };
  double t = 0, v = 0, s = 0;
  const double h = 1e-3;
  for (double probe : {100.0, 300.0, 800.0}) {
    while (s < probe) {
      const double k1 = f(v), k2 = f(v + 0.5 * h * k1), k3 = f(v + 0.5 * h * k2), k4 = f(v + h * k3);
      const double vn = v + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      s += 0.5 * h * (v + vn);
      v = vn;
      t += h;
    }
    EXPECT_NEAR(vAt(dp, probe), v, 0.005 * v) << probe;
  }
}

TEST(Planner, BusVaccLimitsHoldOnEveryStep) {
  const DrivingCycle c = makeCycle("vacc", {0, 10, 600, 610, 1200}, {0, 60, 0, 45, 0},
                                   {0, 2, -3, 1, 0}, {2, 0, 5, 0, 1});
  const auto acc = AccelerationLimits::readVacc("config/data/vehicle/citybus_P1_hybrid_48V/Bus.vacc");
  const DistanceProfile dp = planSpeedOverDistance(c, acc, RoadLoad(RoadLoadParams{}), DriverRules{}, kDs);
  EXPECT_EQ(vAt(dp, 600), 0.0);
  EXPECT_EQ(vAt(dp, 1200), 0.0);
  for (std::size_t i = 0; i + 1 < dp.size(); ++i) {
    const double a = dp.stepAccel_m_s2(i), va = dp.v_m_s[i], vb = dp.v_m_s[i + 1];
    EXPECT_LE(a, std::min(acc.maxAccel_m_s2(va), acc.maxAccel_m_s2(vb)) + 1e-12) << dp.s_m[i];
    EXPECT_GE(a, std::max(acc.maxDecel_m_s2(va), acc.maxDecel_m_s2(vb)) - 1e-12) << dp.s_m[i];
  }
}
