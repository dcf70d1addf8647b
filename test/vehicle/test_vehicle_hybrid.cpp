// Vehicle inputs of the hybrid (P1 e-machine on the crank, EMS brake blending, stop-start)
// against independent references: the crank's spin-down and cranking in neutral (and the gas
// torque of a stopped 1D engine driving it) vs the analytic constant-torque solution, the friction brake set by the EMS, the stop-start debt of
// the crank-driven consumers repaid exactly, and the driveline energy balance with an e-machine.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "vehicle/vehicle_model.hpp"

using namespace hbt;
using namespace hbt::vehicle;

namespace {

// Neutral, no consumers, no spin loss: the crank is a free inertia J = J_E + J_GI.
VehicleParams freeCrank() {
  VehicleParams p;
  p.aux.steering_pump_W = p.aux.air_compressor_W = p.aux.alternator_W = p.aux.fan_default_W = 0.0;
  p.driveline.neutral_drag_torque_Nm = 0.0;
  return p;
}

}  // namespace

TEST(VehicleHybrid, StoppedEngineSpinsDownAsFrictionAndStaysAtRest) {
  // Engine off: its torque is friction -|T_e| sgn(ω) (T_e = -100 Nm), so from ω0 the crank
  // decelerates at 100/J and stops at t* = J ω0 / 100 -- and stays at 0, never reversing.
  const VehicleParams p = freeCrank();
  VehicleModel vm(p);
  const double w0 = p.driveline.idle_speed_rad_s, dt = 0.01;
  vm.reset(0.0, 0, w0);
  const double J = 2.0 * vm.kineticEnergy() / (w0 * w0);  // J_E + J_GI from the state
  VehicleInputs in;
  in.engine_on = false;
  in.engine_torque_Nm = -100.0;
  in.driver_enabled = false;
  in.brake_pedal_cmd = 1.0;
  double t_stop = -1.0;
  for (int k = 1; k <= 600; ++k) {
    const auto& o = vm.step(dt, in);
    ASSERT_GE(o.engine_speed_rad_s, 0.0);
    ASSERT_EQ(o.gear, 0);
    if (t_stop < 0.0 && o.engine_speed_rad_s < 1.0) t_stop = k * dt;  // friction ramp starts
    if (k * dt < J * w0 / 100.0 - 0.05) {
      ASSERT_NEAR(o.engine_speed_rad_s, w0 - 100.0 / J * k * dt, 0.02 * w0) << k;  // smoothSign edge
    }
  }
  EXPECT_NEAR(t_stop, J * (w0 - 1.0) / 100.0, 2.0 * dt);
  // below 1 rad/s the friction fades linearly (smoothSign): the last rad/s decays with J/100 s
  EXPECT_LT(vm.outputs().engine_speed_rad_s, 1e-6);
  // the friction dissipated the crank's kinetic energy: engine work = -½ J ω0², balance closes
  const auto& e = vm.outputs().energy;
  EXPECT_NEAR(e.engine_J + e.correction_J, -0.5 * J * w0 * w0, 1e-6 * J * w0 * w0);
  EXPECT_LT(std::fabs(e.residual_J()), 1e-9 * J * w0 * w0);
}

TEST(VehicleHybrid, CrankingByTheEmachineFollowsTheConstantTorqueSolution) {
  // Engine off with friction F, EM torque T: J dω/dt = T - F (ω > 0), ω(t) = (T - F) t / J.
  const VehicleParams p = freeCrank();
  VehicleModel vm(p);
  vm.reset(0.0, 0, 0.0);
  const double J = [&] { VehicleModel v2(p); v2.reset(0.0, 0, 1.0); return 2.0 * v2.kineticEnergy(); }();
  VehicleInputs in;
  in.engine_on = false;
  in.engine_torque_Nm = -80.0;
  in.em_torque_Nm = 300.0;
  in.driver_enabled = false;
  in.brake_pedal_cmd = 1.0;
  const double dt = 0.01;
  for (int k = 1; k <= 20; ++k) vm.step(dt, in);
  // smoothSign(ω) ramps the friction in over ω < 1 rad/s: bound its effect by J·1 rad/s
  EXPECT_NEAR(vm.outputs().engine_speed_rad_s, (300.0 - 80.0) * 0.2 / J, 1.0);
  EXPECT_GT(vm.outputs().engine_speed_rad_s, (300.0 - 80.0) * 0.2 / J - 1.0);
  const auto& e = vm.outputs().energy;
  EXPECT_GT(e.em_J, 0.0);
  EXPECT_LT(std::fabs(e.residual_J()), 1e-9 * e.em_J);
}

TEST(VehicleHybrid, StoppedEngineGasTorqueDrivesTheCrankFromRest) {
  // Engine off with a driving torque T_e > 0 (the gas of an expanding cylinder of the 1D engine
  // at rest): it acts as it is, J dω/dt = T_e from ω = 0 (no friction ramp), ω(t) = T_e t / J.
  const VehicleParams p = freeCrank();
  VehicleModel vm(p);
  vm.reset(0.0, 0, 0.0);
  const double J = [&] { VehicleModel v2(p); v2.reset(0.0, 0, 1.0); return 2.0 * v2.kineticEnergy(); }();
  VehicleInputs in;
  in.engine_on = false;
  in.engine_torque_Nm = 40.0;
  in.driver_enabled = false;
  in.brake_pedal_cmd = 1.0;
  for (int k = 1; k <= 20; ++k) vm.step(0.01, in);
  EXPECT_NEAR(vm.outputs().engine_speed_rad_s, 40.0 * 0.2 / J, 1e-9 * 40.0 * 0.2 / J);
  const auto& e = vm.outputs().energy;
  EXPECT_NEAR(e.engine_J, 0.5 * J * std::pow(40.0 * 0.2 / J, 2), 1e-6 * e.engine_J);
  EXPECT_LT(std::fabs(e.residual_J()), 1e-9 * e.engine_J);
}

TEST(VehicleHybrid, EmsBrakeOverridesTheDriversFrictionBrake) {
  // Rolling at 30 km/h in neutral with the EMS's friction brake F: dv/dt = -(F + F_roll + F_aero)/M.
  VehicleParams p = freeCrank();
  VehicleModel vm(p);
  const double v0 = 30.0 / 3.6;
  vm.reset(v0, 0, p.driveline.idle_speed_rad_s);
  VehicleInputs in;
  in.neutral_request = true;
  in.driver_enabled = false;
  in.brake_pedal_cmd = 1.0;            // the driver's full brake ...
  in.brake_override = true;
  in.friction_brake_force_N = 5000.0;  // ... replaced by the EMS's 5 kN (regen took the rest)
  in.engine_torque_Nm = 0.0;
  vm.step(0.01, in);
  EXPECT_EQ(vm.outputs().applied_brake_force_N, 5000.0);
  const double e_brake = vm.outputs().energy.brake_J;
  EXPECT_NEAR(e_brake, 5000.0 * v0 * 0.01, 0.01 * 5000.0 * v0 * 0.01);
}

TEST(VehicleHybrid, StopStartDebtOfCrankDrivenConsumersIsRepaidExactly) {
  // Steering pump + compressor stand with the engine and are owed; after the restart they run
  // at up to twice their power until repaid: over stop + run their work equals nominal power x
  // total time (what a bus with the engine running would have drawn).
  VehicleParams p;
  p.aux.fan_default_W = 0.0;
  p.aux.alternator_W = 0.0;
  p.driveline.neutral_drag_torque_Nm = 0.0;
  VehicleModel vm(p);
  const double w = p.driveline.idle_speed_rad_s, dt = 0.01;
  const double P_def = p.aux.steering_pump_W + p.aux.air_compressor_W;
  vm.reset(0.0, 0, 0.0);  // engine at rest
  VehicleInputs in;
  in.neutral_request = true;
  in.driver_enabled = false;
  in.engine_on = false;
  for (int k = 0; k < 1000; ++k) vm.step(dt, in);  // 10 s stopped
  const double owed = vm.outputs().energy.aux_deferred_J;
  EXPECT_NEAR(owed, P_def * 10.0, 1e-9 * P_def * 10.0);
  EXPECT_EQ(vm.outputs().energy.steering_J + vm.outputs().energy.pneumatic_J, 0.0);
  // restart and run 30 s at idle (the engine supplies what the crank absorbs, P control)
  in.engine_on = true;
  for (int k = 0; k < 3000; ++k) {
    const auto& o = vm.outputs();
    const double wc = std::max(o.engine_speed_rad_s, w);
    in.engine_torque_Nm = o.aux_power_W * o.engine_speed_rad_s / (wc * wc) + 20.0 * (w - o.engine_speed_rad_s);
    vm.step(dt, in);
  }
  const auto& e = vm.outputs().energy;
  EXPECT_NEAR(vm.outputs().engine_speed_rad_s, w, 0.01 * w);
  EXPECT_EQ(e.aux_deferred_J, 0.0);
  // the spin-up (below ω_idle the consumers' torque falls with the speed; the payback then lasts a
  // little longer, which the 30 s cover): total = 40 s of nominal power
  EXPECT_NEAR(e.steering_J + e.pneumatic_J, P_def * 40.0, 0.01 * P_def * 40.0);
  EXPECT_NEAR(e.steering_J + e.pneumatic_J, e.aux_J, 1e-9 * e.aux_J);
  EXPECT_LT(std::fabs(e.residual_J()), 1e-9 * std::fabs(e.engine_J));
}
