// Stops and standstill losses, vehicle coupled in lock-step with the map engine (10 ms
// exchange, engine torque one exchange late):
//  - a 5 s stop: once the target is at rest the driver brakes to standstill (no release, no
//    creep against the converter), the bus stands >= 4.5 s, at the profile's position;
//  - neutral at standstill: engine load = aux + the documented neutral spin loss only;
//  - 1C at standstill (neutral_at_stop off): load = aux + the converter's stall pump torque
//    MP(0) (ω_idle/ω_ref)² of the .vtcc, and no gearbox drag (turbine at rest);
//  - the 1C creep force at idle is what the pedal allocation treats as "zero accelerator".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/units.hpp"
#include "vehicle/tools/coupled_sim.hpp"
#include "stop_profile.hpp"

using namespace hbt;
using namespace hbt::vehicle;

namespace {

constexpr double kDt = 0.01;

// Target: one stop, standing kStop s (test/vehicle/stop_profile.hpp).
constexpr double kStop = 5.0;
struct StopProfile : test::StopProfile {
  StopProfile() : test::StopProfile(kStop) {}
};

}  // namespace

TEST(VehicleStops, FiveSecondStopIsServedWithoutCreep) {
  const VehicleParams p;
  CoupledSim sim(p, engine_map::MapEngineParams{});
  sim.reset(0.0, 0);
  const StopProfile prof;
  double standing = 0.0, v_at_zero = -1.0, t_standstill = -1.0, s_stop = 0.0, v_prev = 0.0;
  bool neutral = false;
  const double t_end = prof.t_go + 16.0;  // 30 km/h reached at t_go + 10.4 s
  for (int k = 0; k * kDt < t_end; ++k) {
    const double t1 = (k + 1) * kDt;
    VehicleInputs in;
    in.target_speed_m_s = prof.v(t1);
    in.target_accel_m_s2 = prof.a(t1);
    sim.step(kDt, in);
    const auto& o = sim.vehicle();
    if (t1 >= prof.t_zero - 1e-9 && t1 <= prof.t_go) {
      if (v_at_zero < 0.0) v_at_zero = o.speed_m_s;
      if (o.speed_m_s > 0.0) {  // still rolling after the target reached 0: braking, no creep
        ASSERT_EQ(o.accel_pedal, 0.0) << "t = " << t1;
        ASSERT_GT(o.brake_pedal, 0.0) << "t = " << t1;
        ASSERT_LE(o.speed_m_s, v_prev + 1e-12) << "speed must not rise, t = " << t1;
      } else {
        if (t_standstill < 0.0) {
          t_standstill = t1;
          s_stop = o.distance_m;
        }
      }
      if (t_standstill > 0.0) {
        ASSERT_EQ(o.speed_m_s, 0.0) << "no creep after standstill, t = " << t1;
      }
      if (o.gear == 0) neutral = true;
    }
    if (t1 > prof.t_zero && t1 <= prof.t_zero + kStop + 2.0 && o.speed_m_s == 0.0) standing += kDt;
    v_prev = o.speed_m_s;
  }
  const double s_ref = prof.s(prof.t_zero);
  std::printf("5 s stop: v at target 0 = %.3f km/h, standstill %.2f s later, stood %.2f s, "
              "position %.2f m (target %.2f m), neutral %d\n",
              units::mpsToKmh(v_at_zero), t_standstill - prof.t_zero, standing, s_stop, s_ref,
              neutral ? 1 : 0);
  ASSERT_GT(t_standstill, 0.0);
  // Braking at >= stop_decel (+ one exchange of delay for the brake to act).
  EXPECT_LE(t_standstill - prof.t_zero, v_at_zero / p.driver.stop_decel_m_s2 + 2 * kDt + 1e-9);
  EXPECT_GE(standing, 4.5);
  EXPECT_TRUE(neutral);
  EXPECT_NEAR(s_stop, s_ref, 0.5);  // distance-error PI: stops where the target stops
  EXPECT_NEAR(sim.vehicle().speed_m_s, prof.v30, units::kmhToMps(1.5));  // drove off again
}

TEST(VehicleStops, NeutralAtStandstillLoadsEngineWithAuxAndSpinLossOnly) {
  const VehicleParams p;
  CoupledSim sim(p, engine_map::MapEngineParams{});
  sim.reset(0.0, 0);
  VehicleInputs in;  // target 0: the driver holds, neutral at stop
  for (int k = 0; k < 1000; ++k) sim.step(kDt, in);
  const VehicleEnergy e0 = sim.vehicle().energy;
  double T_sum = 0.0;
  const int n = 1000;
  for (int k = 0; k < n; ++k) {
    sim.step(kDt, in);
    T_sum += sim.engine().brake_torque_Nm;
  }
  const auto& o = sim.vehicle();
  ASSERT_EQ(o.gear, 0);
  ASSERT_EQ(o.speed_m_s, 0.0);
  const double w = p.driveline.idle_speed_rad_s;
  const double P_aux = p.aux.steering_pump_W + p.aux.air_compressor_W + p.aux.alternator_W +
                       p.aux.fan_default_W;
  // spin loss = T_N x the cold-oil factor of the ATF (at 20 degC ~1.5; the oil warms < 0.1 K here)
  const double T_spin = p.driveline.neutral_drag_torque_Nm * o.gearbox_drag_factor;
  EXPECT_GT(o.gearbox_drag_factor, 1.0);
  const double T_expected = P_aux / w + T_spin;
  std::printf("neutral idle: engine torque %.2f Nm (aux %.2f + spin %.2f = %.2f x %.3f cold oil), %.3f rpm\n",
              T_sum / n, P_aux / w, T_spin, p.driveline.neutral_drag_torque_Nm, o.gearbox_drag_factor,
              units::radpsToRpm(o.engine_speed_rad_s));
  EXPECT_NEAR(units::radpsToRpm(o.engine_speed_rad_s), 700.0, 0.5);
  EXPECT_NEAR(T_sum / n, T_expected, 0.5);
  const double T = n * kDt;
  EXPECT_NEAR(o.energy.gearbox_drag_J - e0.gearbox_drag_J, T_spin * w * T, 0.01 * T_spin * w * T);
  EXPECT_NEAR(o.energy.aux_J - e0.aux_J, P_aux * T, 0.01 * P_aux * T);
  EXPECT_EQ(o.energy.tc_loss_J - e0.tc_loss_J, 0.0);
  EXPECT_EQ(o.energy.gear_load_loss_J - e0.gear_load_loss_J, 0.0);
}

TEST(VehicleStops, StandingIn1CLoadsEngineWithStallPumpTorque) {
  VehicleParams p;
  p.shift.neutral_at_stop = false;  // stays in 1C: the converter stalls, the brake holds
  CoupledSim sim(p, engine_map::MapEngineParams{});
  sim.reset(0.0, 1);
  VehicleInputs in;
  for (int k = 0; k < 1000; ++k) sim.step(kDt, in);
  const VehicleEnergy e0 = sim.vehicle().energy;
  double T_sum = 0.0;
  const int n = 500;
  for (int k = 0; k < n; ++k) {
    sim.step(kDt, in);
    T_sum += sim.engine().brake_torque_Nm;
  }
  const auto& o = sim.vehicle();
  ASSERT_EQ(o.mode, DriveMode::Converter);
  ASSERT_EQ(o.speed_m_s, 0.0);
  const double w = p.driveline.idle_speed_rad_s, r = w / units::rpmToRadps(1000.0);
  const double T_pump = 367.68 * r * r;  // .vtcc MP1000(ν = 0) = 367.68 Nm, at 700 rpm
  const double P_aux = p.aux.steering_pump_W + p.aux.air_compressor_W + p.aux.alternator_W +
                       p.aux.fan_default_W;
  std::printf("1C stall at idle: engine torque %.2f Nm (aux %.2f + pump %.2f), creep force "
              "%.0f N held by the brake\n",
              T_sum / n, P_aux / w, T_pump, 1.80 * T_pump * sim.vehicleModel().ratio(1));
  EXPECT_NEAR(units::radpsToRpm(o.engine_speed_rad_s), 700.0, 1.0);
  EXPECT_NEAR(T_sum / n, P_aux / w + T_pump, 1.5);
  // Turbine at rest: no gearbox drag power, the stall power goes into converter heat.
  EXPECT_NEAR(o.energy.gearbox_drag_J - e0.gearbox_drag_J, 0.0, 1e-9);
  EXPECT_NEAR(o.energy.tc_loss_J - e0.tc_loss_J, T_pump * w * n * kDt, 0.01 * T_pump * w * n * kDt);
  // The brake holds against the creep force μ(0) T_p k_1 (1.80 x 180 Nm x 44.5 1/m = 14.4 kN).
  EXPECT_GE(o.brake_force_N, 1.80 * T_pump * sim.vehicleModel().ratio(1));
}
