// Vehicle dynamics against closed forms and conservation laws (no engine model: the crank
// torque is prescribed): coast-down vs the analytic solution of M dv/dt = -(F0 + c v²), exact
// stop and hold (Coulomb friction), momentum conservation of a shift impulse, and the energy
// balance over a drive with shifts, converter, stops and grades.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "common/units.hpp"
#include "vehicle/vehicle_model.hpp"

using namespace hbt;
using namespace hbt::vehicle;

namespace {

VehicleParams noRetarder() {
  VehicleParams p;
  p.driveline.retarder_loss_file = "";
  return p;
}

// Closed-form coast-down: M dv/dt = -(F0 + c v²), v(0) = v0.
struct CoastDown {
  double M, F0, c, v0;
  double v(double t) const {
    const double a = std::sqrt(F0 / c), b = std::sqrt(F0 * c) / M;
    return std::max(0.0, a * std::tan(std::atan(v0 / a) - t * b));
  }
  double stopTime() const { return M / std::sqrt(F0 * c) * std::atan(v0 * std::sqrt(c / F0)); }
};

CoastDown analytic(const VehicleParams& p, double v0, double T_amb) {
  const auto& c = p.chassis;
  const double m = c.curb_mass_kg + c.payload_kg, g = 9.81, r = c.tyre_radius_m;
  const double sf = c.front_axle_load_share, sr = 1.0 - sf;
  const double crr = sf * c.rrc_front * std::pow(sf * m * g / (c.tyres_front * c.tyre_fz_iso_N), -0.1) +
                     sr * c.rrc_rear * std::pow(sr * m * g / (c.tyres_rear * c.tyre_fz_iso_N), -0.1);
  const double rho = c.ambient_pressure_Pa / (c.air_R_J_kgK * T_amb);
  // ISO 28580 / UN R117 temperature correction F_r25 = F_rt (1 + K_t (t - 25 degC)), C3: 0.006
  const double F_r25 = crr * m * g, F_rt = F_r25 / (1.0 + 0.006 * (T_amb - 273.15 - 25.0));
  return {m + (c.tyres_front + c.tyres_rear) * c.wheel_inertia_kg_m2 / (r * r), F_rt,
          0.5 * rho * c.cda_m2, v0};
}

}  // namespace

TEST(VehicleDynamics, CoastDownMatchesAnalyticSolution) {
  const VehicleParams p = noRetarder();
  VehicleModel vm(p);
  const double v0 = units::kmhToMps(60.0), T_amb = 293.15, dt = 0.01;
  const CoastDown cd = analytic(p, v0, T_amb);
  vm.reset(v0, 0, p.driveline.idle_speed_rad_s);
  VehicleInputs in;
  in.neutral_request = true;
  in.driver_enabled = false;
  in.ambient_T_K = T_amb;
  double maxRelErr = 0.0, t = 0.0, tStop = -1.0;
  for (int k = 1; k <= 30000; ++k) {
    const auto& o = vm.step(dt, in);
    t = k * dt;
    ASSERT_GE(o.speed_m_s, 0.0);
    if (o.speed_m_s > 0.5) maxRelErr = std::max(maxRelErr, std::fabs(o.speed_m_s - cd.v(t)) / cd.v(t));
    if (tStop < 0.0 && o.speed_m_s == 0.0) tStop = t;
    if (tStop > 0.0) {
      ASSERT_EQ(o.speed_m_s, 0.0) << "bus must stay stopped";
    }
  }
  RecordProperty("coastdown_max_rel_error", std::to_string(maxRelErr));
  RecordProperty("coastdown_stop_time_s", std::to_string(tStop));
  std::printf("coast-down 60 km/h: max rel. speed error %.2e, stop %.2f s (analytic %.2f s)\n",
              maxRelErr, tStop, cd.stopTime());
  EXPECT_LT(maxRelErr, 1e-6);
  EXPECT_NEAR(tStop, cd.stopTime(), dt);
  EXPECT_NEAR(vm.outputs().energy.residual_J(), 0.0, 1e-6 * cd.M * v0 * v0);
}

TEST(VehicleDynamics, HeldOnGradeByBrakeRollsBackWithout) {
  VehicleModel vm{VehicleParams{}};
  vm.reset(0.0, 0, VehicleParams{}.driveline.idle_speed_rad_s);
  VehicleInputs in;
  in.driver_enabled = false;
  in.neutral_request = true;
  in.road_grade = 0.08;
  in.brake_pedal_cmd = 0.3;  // 1.5 m/s² of brake > 0.78 m/s² of grade
  for (int k = 0; k < 1000; ++k) ASSERT_EQ(vm.step(0.01, in).speed_m_s, 0.0);
  in.brake_pedal_cmd = 0.0;
  for (int k = 0; k < 100; ++k) vm.step(0.01, in);
  EXPECT_LT(vm.outputs().speed_m_s, -0.5);  // g (sin α - C_rr cos α) ≈ 0.72 m/s² backwards
  EXPECT_NEAR(vm.outputs().accel_m_s2, -(9.81 * (0.08 - vm.roadLoad().rollingCoefficient()) / std::sqrt(1.0064)) *
                                           16660.0 / vm.vehicleInertiaMass_kg(), 0.02);
}

TEST(VehicleDynamics, ShiftImpulseConservesMomentum) {
  VehicleParams p = noRetarder();
  p.shift.shift_duration_s = 0.0;  // instantaneous gear change: a clutch impulse
  VehicleModel vm(p);
  const double w2 = units::rpmToRadps(2250.0), v = w2 / vm.ratio(2);
  vm.reset(v, 2, 0.0);
  VehicleInputs in;
  in.driver_enabled = false;
  in.accel_pedal_cmd = 1.0;
  const auto& o = vm.step(1e-7, in);  // upshift 2L -> 3L at the start of the step
  ASSERT_EQ(o.gear, 3);
  const double M = vm.vehicleInertiaMass_kg();
  const double J = p.driveline.engine_inertia_kg_m2 + p.driveline.tc_pump_inertia_kg_m2 +
                   p.driveline.gearbox_input_inertia_kg_m2;
  const double k3 = vm.ratio(3);
  const double v_expected = (M * v + J * w2 * k3) / (M + J * k3 * k3);
  EXPECT_NEAR(o.speed_m_s, v_expected, 1e-5);
  EXPECT_NEAR(o.engine_speed_rad_s, k3 * o.speed_m_s, 1e-9);
  const double ke0 = 0.5 * M * v * v + 0.5 * J * w2 * w2;
  const double ke1 = 0.5 * (M + J * k3 * k3) * v_expected * v_expected;
  EXPECT_NEAR(o.energy.shift_loss_J, ke0 - ke1, 1e-3 * (ke0 - ke1) + 1.0);
  EXPECT_GT(o.energy.shift_loss_J, 0.0);
}

TEST(VehicleDynamics, EnergyBalanceWithPrescribedEngine) {
  // Ideal engine: delivers the request (clamped to [-100, 1100] Nm) one exchange late.
  VehicleModel vm{VehicleParams{}};
  const double idle = VehicleParams{}.driveline.idle_speed_rad_s;
  vm.reset(0.0, 0, idle);
  vm.setGradeProfile({0.0, 200.0, 400.0, 600.0, 2000.0}, {0.0, 0.03, 0.0, -0.02, -0.02});
  VehicleInputs in;
  double T = 0.0;
  double min_v = 0.0, max_shift = 0.0;
  const double dt = 0.01;
  double vt = 0.0;
  for (int k = 0; k < 12000; ++k) {
    const double t = k * dt;
    // 0-10 s wait, accelerate 0.8 m/s² to 45 km/h, cruise to 60 s, brake 1 m/s², stop.
    double a = 0.0;
    if (t >= 10.0 && vt < units::kmhToMps(45.0)) a = 0.8;
    if (t >= 60.0) a = vt > 0.0 ? -1.0 : 0.0;
    vt = std::max(0.0, std::min(units::kmhToMps(45.0), vt + a * dt));
    in.target_speed_m_s = vt;
    in.target_accel_m_s2 = a;
    in.engine_torque_Nm = T;
    in.engine_max_torque_Nm = 1100.0;
    in.engine_min_torque_Nm = -100.0;
    const auto& o = vm.step(dt, in);
    T = std::clamp(o.engine_torque_request_Nm, -100.0, 1100.0);
    min_v = std::min(min_v, o.speed_m_s);
    max_shift = std::max(max_shift, o.energy.shift_loss_J);
  }
  const auto& e = vm.outputs().energy;
  std::printf("prescribed-engine drive: engine %.3f MJ, residual %.3e J, distance %.0f m\n",
              e.engine_J / 1e6, e.residual_J(), vm.outputs().distance_m);
  EXPECT_GT(e.engine_J, 1e6);
  EXPECT_LT(std::fabs(e.residual_J()), 1e-6 * e.engine_J);
  for (double loss : {e.aux_J, e.gearbox_drag_J, e.tc_loss_J, e.gear_load_loss_J, e.retarder_J,
                      e.axle_loss_J, e.shift_loss_J, e.rolling_J, e.aero_J, e.brake_J})
    EXPECT_GE(loss, 0.0);
  EXPECT_NEAR(e.grade_J, 16660.0 * 9.81 * vm.outputs().altitude_m, 1e-6 * std::fabs(e.grade_J) + 1e-3);
  EXPECT_GE(min_v, 0.0);
  EXPECT_EQ(vm.outputs().speed_m_s, 0.0);
  EXPECT_GT(vm.outputs().distance_m, 600.0);
}

TEST(VehicleDynamics, AuxWorkSplitsExactlyOverConsumers) {
  // Neutral at a constant crank speed: the engine torque balances aux + neutral drag exactly,
  // so each consumer's work is its power times time (fan: +3 kW for 5 s, then windmilling
  // -1 kW for 5 s), and the consumers add up to the booked aux work. ATF and ambient at the oil's
  // reference temperature: the spin loss is the warm T_N (cold-oil factor exactly 1).
  const VehicleParams p;
  VehicleModel vm(p);
  const double w = p.driveline.idle_speed_rad_s, dt = 0.01, T_ref = p.driveline_oil.gearbox.reference_K;
  vm.reset(0.0, 0, w);
  vm.setOilTemperatures(T_ref, T_ref);
  VehicleInputs in;
  in.ambient_T_K = T_ref;
  in.neutral_request = true;
  in.driver_enabled = false;
  in.has_fan_power = true;
  const auto& a = p.aux;
  const double P_const = a.steering_pump_W + a.air_compressor_W + a.alternator_W;
  for (int k = 0; k < 1000; ++k) {
    in.fan_power_W = k < 500 ? 3000.0 : -1000.0;
    in.engine_torque_Nm = (P_const + in.fan_power_W) / w + p.driveline.neutral_drag_torque_Nm;
    vm.step(dt, in);
  }
  const auto& e = vm.outputs().energy;
  EXPECT_NEAR(vm.outputs().engine_speed_rad_s, w, 1e-9 * w);
  EXPECT_NEAR(e.fan_J, 3000.0 * 5.0 - 1000.0 * 5.0, 1e-6 * 1e4);
  EXPECT_NEAR(e.steering_J, a.steering_pump_W * 10.0, 1e-6 * a.steering_pump_W * 10.0);
  EXPECT_NEAR(e.pneumatic_J, a.air_compressor_W * 10.0, 1e-6 * a.air_compressor_W * 10.0);
  EXPECT_NEAR(e.electric_J, a.alternator_W * 10.0, 1e-6 * a.alternator_W * 10.0);
  EXPECT_NEAR(e.fan_J + e.steering_J + e.pneumatic_J + e.electric_J, e.aux_J, 1e-9 * e.aux_J);
}

TEST(VehicleDynamics, AuxTorqueBelowIdleNeverExceedsItsIdleTorque) {
  // Engine off in neutral, no drag: the crank spins down from idle under the aux set alone.
  // The deceleration J dω/dt is the aux torque; at every speed below idle it stays at or below
  // the idle torque P_aux/ω_idle (belt loads are sized at idle: a crank or a run-up never meets
  // more).
  VehicleParams p;
  p.driveline.neutral_drag_torque_Nm = 0.0;
  VehicleModel vm(p);
  const double w_idle = p.driveline.idle_speed_rad_s, dt = 0.001;
  vm.reset(0.0, 0, w_idle);
  VehicleInputs in;
  in.neutral_request = true;
  in.driver_enabled = false;
  in.engine_on = false;
  vm.step(dt, in);
  const double P_aux = vm.outputs().aux_power_W;
  ASSERT_GT(P_aux, 0.0);
  const auto& d = p.driveline;
  const double J = d.engine_inertia_kg_m2 + d.tc_pump_inertia_kg_m2 + d.gearbox_input_inertia_kg_m2;
  double w_prev = vm.outputs().engine_speed_rad_s, worst_ratio = 0.0;
  for (int k = 0; k < 20000 && w_prev > 0.05 * w_idle; ++k) {
    vm.step(dt, in);
    const double w = vm.outputs().engine_speed_rad_s;
    worst_ratio = std::max(worst_ratio, J * (w_prev - w) / dt / (P_aux / w_idle));
    w_prev = w;
  }
  EXPECT_LT(w_prev, 0.5 * w_idle);  // it did spin down through the crank speeds
  EXPECT_GT(worst_ratio, 0.9);      // near idle the full idle torque acts
  EXPECT_LE(worst_ratio, 1.0 + 1e-6);
}

TEST(VehicleDynamics, ShiftSlipPhaseIsSmoothAndDissipative) {
  VehicleParams p = noRetarder();
  VehicleModel vm(p);
  const double w2 = units::rpmToRadps(2250.0);
  vm.reset(w2 / vm.ratio(2), 2, 0.0);
  VehicleInputs in;
  in.driver_enabled = false;
  in.accel_pedal_cmd = 1.0;
  in.engine_torque_Nm = 800.0;  // constant crank torque during the shift
  double vprev = vm.outputs().speed_m_s, tSync = -1.0, maxJump = 0.0;
  for (int k = 1; k <= 150; ++k) {
    const auto& o = vm.step(0.01, in);
    maxJump = std::max(maxJump, std::fabs(o.speed_m_s - vprev));
    vprev = o.speed_m_s;
    if (k == 1) {
      EXPECT_EQ(o.mode, DriveMode::Shifting);
      EXPECT_EQ(o.gear, 3);
    }
    if (tSync < 0.0 && o.mode == DriveMode::Locked) tSync = k * 0.01;
  }
  const auto& o = vm.outputs();
  // Synchronised within the nominal 0.6 s (the vehicle accelerates meanwhile), then rigid.
  EXPECT_GT(tSync, 0.3);
  EXPECT_LE(tSync, 0.61);
  EXPECT_NEAR(o.engine_speed_rad_s, vm.ratio(3) * o.speed_m_s, 1e-9);
  // No speed jump: at most ~ (800 Nm + inertia torque) k_3 / M * dt per step.
  EXPECT_LT(maxJump, 0.03);
  // Clutch heat ≈ ∫T_c s dt > 0; total balance closes.
  EXPECT_GT(o.energy.shift_loss_J, 0.0);
  EXPECT_NEAR(o.energy.residual_J(), 0.0, 1e-6 * o.energy.engine_J);
}
