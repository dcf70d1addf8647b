// Vehicle coupled in lock-step (Jacobi exchange every 10 ms, engine torque one exchange late)
// with the map-based engine: full-load acceleration (0-50 km/h time, shift points), start-stop
// manoeuvre (stop, idle, no reversal, gears back down, restart), energy balance of the whole
// chain, idle-governor stability with the exchange delay.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/units.hpp"
#include "vehicle/tools/coupled_sim.hpp"

using namespace hbt;
using namespace hbt::vehicle;
using units::radpsToRpm;

namespace {

constexpr double kDt = 0.01;

struct ShiftEvent {
  double t, kmh, rpm_before, rpm_after;
  GearState from, to;
  double t_sync;
};

// Target-speed generator: accelerate at a_acc up to v_max, then follow the schedule.
struct Profile {
  double v = 0.0;
  double step(double t, double& a_out, const std::vector<std::pair<double, double>>& phases) {
    // phases: (start time, commanded acceleration); v limited to [0, v_cap].
    double a = 0.0;
    for (const auto& ph : phases)
      if (t >= ph.first) a = ph.second;
    v = std::max(0.0, v + a * kDt);
    a_out = v > 0.0 ? a : 0.0;
    return v;
  }
};

}  // namespace

TEST(VehicleCoupled, FullLoadAccelerationFromStandstill) {
  CoupledSim sim(VehicleParams{}, engine_map::MapEngineParams{});
  sim.reset(0.0, 0);
  VehicleInputs in;
  in.driver_enabled = false;
  in.brake_pedal_cmd = 1.0;
  for (int k = 0; k < 100; ++k) sim.step(kDt, in);
  in.brake_pedal_cmd = 0.0;
  in.accel_pedal_cmd = 1.0;
  std::vector<ShiftEvent> ev;  // lock-up and gear changes (rpm_after: when the clutch has locked)
  GearState gs{sim.vehicle().mode, sim.vehicle().gear};
  double rpm_prev = radpsToRpm(sim.vehicle().engine_speed_rad_s), t50 = -1, t30 = -1, vprev = 0;
  const double t0 = sim.time();
  while (sim.time() - t0 < 40.0) {
    sim.step(kDt, in);
    const auto& o = sim.vehicle();
    const double t = sim.time() - t0, kmh = units::mpsToKmh(o.speed_m_s);
    ASSERT_GE(o.speed_m_s, vprev - 1e-9) << "speed must not drop under full load (t = " << t << ")";
    ASSERT_LT(o.speed_m_s - vprev, 0.03) << "no speed jump (t = " << t << ")";
    vprev = o.speed_m_s;
    const GearState now{o.mode, o.gear};
    const double rpm = radpsToRpm(o.engine_speed_rad_s);
    if (now != gs && gs.mode != DriveMode::Neutral) {
      if (gs.mode == DriveMode::Shifting) {
        ev.back().rpm_after = rpm;  // slip phase over
        ev.back().t_sync = t;
      } else {
        ev.push_back({t, kmh, rpm_prev, rpm, gs, now, t});
      }
    }
    gs = now;
    rpm_prev = rpm;
    if (t30 < 0 && kmh >= 30.0) t30 = t;
    if (t50 < 0 && kmh >= 50.0) t50 = t;
    ASSERT_LT(rpm_prev, 2500.0) << "engine overspeed";
  }
  std::printf("full-load acceleration: 0-30 km/h %.2f s, 0-50 km/h %.2f s\n", t30, t50);
  for (const auto& e : ev)
    std::printf("  t %6.2f s  %d%c -> %d%c  %5.0f -> %5.0f rpm at %5.1f km/h (locked after %.2f s)\n",
                e.t, e.from.gear, e.from.mode == DriveMode::Converter ? 'C' : 'L', e.to.gear,
                e.to.mode == DriveMode::Converter ? 'C' : 'L', e.rpm_before, e.rpm_after, e.kmh,
                e.t_sync - e.t);
  RecordProperty("t_0_50_kmh_s", std::to_string(t50));
  // Power-limited bound: t >= M v²/(2 P_max) = 7.5 s for 50 km/h; typical city buses 12-25 s.
  EXPECT_GT(t50, 10.0);
  EXPECT_LT(t50, 25.0);
  EXPECT_LT(t30, 0.6 * t50);
  ASSERT_GE(ev.size(), 5u);
  EXPECT_EQ(ev[0].to, (GearState{DriveMode::Locked, 1}));  // 1C -> 1L first
  int gear = 1;
  for (std::size_t i = 1; i < ev.size(); ++i) {
    EXPECT_EQ(ev[i].to.gear, gear + 1) << "upshifts only, one gear at a time";
    gear = ev[i].to.gear;
    EXPECT_GT(ev[i].rpm_before, 2100.0);   // full-load upshift near rated speed (2293 rpm)
    EXPECT_LT(ev[i].rpm_before, 2300.0);
    EXPECT_GT(ev[i].rpm_after, 1150.0);    // lands high on the torque plateau
    EXPECT_LT(ev[i].rpm_after, 1950.0);
    EXPECT_LT(ev[i].t_sync - ev[i].t, 0.65);
  }
  EXPECT_NEAR(sim.vehicle().energy.residual_J(), 0.0, 1e-6 * sim.vehicle().energy.engine_J);
}

TEST(VehicleCoupled, StartStopManoeuvreAndEnergyBalance) {
  CoupledSim sim(VehicleParams{}, engine_map::MapEngineParams{});
  sim.reset(0.0, 0);
  const double v30 = units::kmhToMps(30.0);
  Profile prof;
  // 0-5 s stand, accelerate 0.8 m/s² to 30 km/h, cruise, brake 0.8 m/s² at 40 s, stand
  // until 80 s, restart to 30 km/h, cruise to the end (110 s).
  double minSpeed = 0.0, cruiseErr = 0.0, minIdle = 1e9, maxIdle = 0.0;
  bool stopped = false, neutralAtStop = false;
  int maxGear = 0;
  for (int k = 0; k < 11000; ++k) {
    const double t = k * kDt;
    double a = 0.0;
    if (t >= 5.0 && t < 40.0) a = prof.v < v30 ? 0.8 : 0.0;
    if (t >= 40.0 && t < 80.0) a = -0.8;
    if (t >= 80.0) a = prof.v < v30 ? 0.8 : 0.0;
    prof.v = std::clamp(prof.v + a * kDt, 0.0, v30);
    VehicleInputs in;
    in.target_speed_m_s = prof.v;
    in.target_accel_m_s2 = (prof.v > 0.0 && prof.v < v30) ? a : 0.0;
    sim.step(kDt, in);
    const auto& o = sim.vehicle();
    minSpeed = std::min(minSpeed, o.speed_m_s);
    maxGear = std::max(maxGear, o.gear);
    if (t > 25.0 && t < 40.0) cruiseErr = std::max(cruiseErr, std::fabs(o.speed_m_s - v30));
    if (t > 65.0 && t < 80.0) {  // standing: bus stopped, engine idling
      stopped = o.speed_m_s == 0.0;
      neutralAtStop = o.gear == 0;
      minIdle = std::min(minIdle, radpsToRpm(o.engine_speed_rad_s));
      maxIdle = std::max(maxIdle, radpsToRpm(o.engine_speed_rad_s));
      ASSERT_EQ(o.speed_m_s, 0.0) << "t = " << t;
    }
  }
  const auto& o = sim.vehicle();
  std::printf("start-stop: max gear %d, cruise error %.3f km/h, idle %.1f-%.1f rpm, final %.1f km/h\n",
              maxGear, units::mpsToKmh(cruiseErr), minIdle, maxIdle, units::mpsToKmh(o.speed_m_s));
  EXPECT_GE(minSpeed, 0.0);
  EXPECT_TRUE(stopped);
  EXPECT_TRUE(neutralAtStop);
  EXPECT_GE(maxGear, 3);
  EXPECT_LT(units::mpsToKmh(cruiseErr), 1.0);
  EXPECT_GT(minIdle, 680.0);
  EXPECT_LT(maxIdle, 720.0);
  EXPECT_NEAR(o.speed_m_s, v30, units::kmhToMps(1.0));  // restarted

  // Energy: vehicle-side balance (brake work = driveline losses + aux + road + brake + ΔE).
  const auto& e = o.energy;
  const auto& eng = sim.engine();
  std::printf("energy [kJ]: engine %.1f (engine model %.1f), aux %.1f, gearbox drag %.1f, TC %.1f, "
              "gear %.1f, retarder %.1f, axle %.1f, shift %.1f, roll %.1f, aero %.1f, brake %.1f, "
              "dEkin %.1f, residual %.2e J; fuel %.1f g = %.1f kJ\n",
              e.engine_J / 1e3, eng.brake_work_J / 1e3, e.aux_J / 1e3, e.gearbox_drag_J / 1e3,
              e.tc_loss_J / 1e3, e.gear_load_loss_J / 1e3, e.retarder_J / 1e3, e.axle_loss_J / 1e3,
              e.shift_loss_J / 1e3, e.rolling_J / 1e3, e.aero_J / 1e3, e.brake_J / 1e3,
              (e.kinetic_J - e.kinetic_initial_J) / 1e3, e.residual_J(), eng.fuel_mass_kg * 1e3,
              eng.fuel_energy_J / 1e3);
  EXPECT_LT(std::fabs(e.residual_J()), 1e-3 * 0.01 * e.engine_J);
  // The engine's own brake work (its speed input lags one exchange) agrees within 1 %.
  EXPECT_NEAR(eng.brake_work_J, e.engine_J, 0.01 * e.engine_J);
  // Fuel energy = engine losses + brake work, with a plausible mean efficiency.
  const double eff = eng.brake_work_J / eng.fuel_energy_J;
  EXPECT_GT(eff, 0.15);
  EXPECT_LT(eff, 0.42);
}

TEST(VehicleCoupled, IdleIsStableWithExchangeDelay) {
  CoupledSim sim(VehicleParams{}, engine_map::MapEngineParams{});
  sim.reset(0.0, 0);
  VehicleInputs in;  // target 0: the driver holds, neutral at stop
  std::vector<double> rpm;
  for (int k = 0; k < 3000; ++k) {
    // A load step at 10 s: fan switched on (+6 kW) by the cooling node.
    in.has_fan_power = true;
    in.fan_power_W = k * kDt < 10.0 ? 800.0 : 6800.0;
    sim.step(kDt, in);
    rpm.push_back(radpsToRpm(sim.vehicle().engine_speed_rad_s));
  }
  double dip = 1e9, lo = 1e9, hi = 0.0;
  for (std::size_t i = 1000; i < 1500; ++i) dip = std::min(dip, rpm[i]);
  for (std::size_t i = 2000; i < 3000; ++i) { lo = std::min(lo, rpm[i]); hi = std::max(hi, rpm[i]); }
  std::printf("idle: dip %.1f rpm after a 6 kW step, last 10 s %.2f-%.2f rpm\n", dip, lo, hi);
  EXPECT_GT(dip, 620.0);
  EXPECT_NEAR(lo, 700.0, 2.0);
  EXPECT_NEAR(hi, 700.0, 2.0);
}
