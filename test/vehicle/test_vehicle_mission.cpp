// Full VECTO Urban mission in-process (tools/mission_run.hpp): mission profile, bus and map
// engine in lock-step at the 10 ms exchange exactly as the ROS nodes run it, 25 °C.
// Acceptance: every stop served (v = 0 for >= 90 % of the stop time within
// [t_0, t_0 + D + 2 s]), speed RMSE <= 1.5 km/h, distance within ±0.5 % of 39,551 m, stops
// within 5 m of their positions, energy balance closed. Runs ~10-20 s.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "common/units.hpp"
#include "vehicle/tools/mission_run.hpp"

using namespace hbt;
using namespace hbt::vehicle;

TEST(VehicleMission, UrbanStopsRmseDistance) {
  MissionRunOptions opt;
  opt.ambient_T_K = 298.15;
  const MissionRunResult r =
      runMission(VehicleParams{}, engine_map::MapEngineParams{}, mission::MissionParams{}, opt);
  std::size_t n_stops = 0;
  for (const auto& s : r.stops)
    if (s.t_start_s + s.duration_s <= r.duration_s) ++n_stops;
  const double km = r.distance_m / 1000.0;
  std::printf("Urban: %.1f m, RMSE %.3f km/h, stops %zu/%zu, max stop position error %.2f m, "
              "fuel %.3f kg = %.2f L/100km\n",
              r.distance_m, 3.6 * r.speed_rmse_m_s, r.stops_served, n_stops,
              r.max_stop_position_error_m, r.fuel_kg, 100.0 * units::dieselLitres(r.fuel_kg) / km);
  EXPECT_EQ(n_stops, 121u);  // the cycle's stops (incl. the start and the final 2 s stop)
  EXPECT_EQ(r.stops_served, n_stops);
  for (const auto& s : r.stops) {
    if (s.t_start_s + s.duration_s > r.duration_s) continue;
    EXPECT_TRUE(s.served) << "stop at " << s.position_m << " m, t " << s.t_start_s << " s: stood "
                          << s.standing_s << " of " << s.duration_s << " s";
  }
  EXPECT_LE(3.6 * r.speed_rmse_m_s, 1.5);
  EXPECT_NEAR(r.distance_m, 39551.0, 0.005 * 39551.0);
  EXPECT_LT(r.max_stop_position_error_m, 5.0);
  EXPECT_LT(std::fabs(r.energy.residual_J()), 1e-6 * r.energy.engine_J);
  EXPECT_NEAR(r.engine_brake_work_J, r.energy.engine_J, 0.01 * r.energy.engine_J);
}
