// The EMS commands within the e-machine's live limits of the step it commands: in closed loop
// with the shipped e-machine model (config/emachine.yaml) under a full-load acceleration and a
// braking ramp, with a battery voltage that sags with the current, every request the EMS makes is
// delivered unclamped. The same loop with the limits the e-machine published for the previous
// step (no limit model) is clamped while the speed rises: the reference that the test can fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "emachine/emachine_model.hpp"
#include "ems/ems_model.hpp"

using namespace hbt;
using namespace hbt::ems;

namespace {

EmsParams emsParams() {
  EmsParams p;
  ParamSet ps;
  p.declare(ps);
  applyParams(ps, readYamlParams("config/ems.yaml"), {"cosim/"});
  p.validate("config/ems.yaml");
  return p;
}

emachine::EMachineParams machineParams() {
  emachine::EMachineParams p;
  ParamSet ps;
  p.declare(ps);
  applyParams(ps, readYamlParams("config/emachine.yaml"), {"cosim/"});
  return p;
}

// Willans line with a marginal cost of 4 J of fuel per J of crank work: boost always pays
// (s / η_m < 4 for the shipped equivalence factors), so the EMS asks for its upper bound.
class ExpensiveFuel : public FuelModel {
 public:
  double fuelRate_kg_s(double w, double T) const override {
    return T <= -100.0 ? 0.0 : (3000.0 + 4.0 * T * w) / units::kDieselLhv_J_kg;
  }
};

class Machine : public EmLimitModel {
 public:
  explicit Machine(const emachine::EMachineModel& m) : m_(m) {}
  void liveLimits(double w, double V, double Tw, double Tm, double& max_Nm, double& min_Nm) const override {
    const emachine::CrankLimits c = m_.limits(w, V, Tw, Tm);
    max_Nm = c.max_live;
    min_Nm = c.min_live;
  }
  double dcPower_W(double T, double w, double V, double Tw, double Tm) const override {
    return m_.dcPower(T, w, V, Tw, Tm);
  }

 private:
  const emachine::EMachineModel& m_;
};

struct LoopResult {
  int steps = 0, clamped = 0;
  double regen_J = 0.0, boost_J = 0.0;
  double max_pack_share = 0.0;  // max over steps of (e-machine DC power + DC/DC) / pack limit
};

// Crank speed ramps from w0 to w1 [rad/s] over T [s]; braking: the driver brakes at the wheels
// (regen), else full-load traction. Battery: OCV 50 V, R 10 mΩ (a 48 V pack of this class).
LoopResult closedLoop(bool with_limit_model, double w0, double w1, double T_s, bool braking,
                      double pack_limit_W = 60000.0, double dcdc_W = 0.0) {
  const double dt = 0.01, ocv = 50.0, R = 0.010;
  const EmsParams p = emsParams();
  ExpensiveFuel fuel;
  emachine::EMachineModel machine(machineParams(), "config/emachine.yaml");
  machine.reset(units::celsiusToK(25.0));
  const emachine::EMachineModel limits_of(machineParams(), "config/emachine.yaml");
  Machine lim(limits_of);
  EmsModel ems(p, fuel, with_limit_model ? &lim : nullptr);
  double V = ocv;  // terminal voltage of the last step
  LoopResult r;
  const int n = static_cast<int>(std::lround(T_s / dt));
  for (int k = 0; k < n; ++k) {
    const double w = w0 + (w1 - w0) * k / (n - 1);
    const auto& o = machine.outputs();
    EmsInputs in;
    in.crank_torque_demand_Nm = braking ? -200.0 : 1200.0;
    in.wheel_brake_demand_Nm = braking ? 20000.0 : 0.0;
    in.engine_speed_rad_s = w;
    in.crank_to_wheel_ratio = 20.0;
    in.engine_max_torque_Nm = 1100.0;
    in.engine_min_torque_Nm = -100.0;
    in.em_max_torque_Nm = o.limits.max_live;  // published: at the last step's speed and voltage
    in.em_min_torque_Nm = o.limits.min_live;
    in.em_winding_T_K = o.winding_T_K;
    in.em_magnet_T_K = o.magnet_T_K;
    in.dc_voltage_V = V;
    in.soc = 0.55;
    in.battery_T_K = 298.15;
    in.discharge_limit_W = pack_limit_W;
    in.charge_limit_W = pack_limit_W;
    in.dcdc_power_W = dcdc_W;
    const EmsDecision& d = ems.step(dt, in);
    emachine::EMachineInputs mi;
    mi.torque_request_Nm = d.em_torque_request_Nm;
    mi.crank_speed_rad_s = w;
    mi.dc_voltage_V = V;
    machine.step(dt, mi);
    const auto& m = machine.outputs();
    ++r.steps;
    if (std::fabs(m.torque_request_Nm - m.torque_Nm) > 1e-9 * (1.0 + std::fabs(m.torque_request_Nm))) ++r.clamped;
    if (m.torque_Nm > 0.0) r.boost_J += m.torque_Nm * w * dt;
    else r.regen_J -= m.torque_Nm * w * dt;
    // what the pack is asked: the e-machine's DC power and the DC/DC's draw (> 0 discharge)
    const double pack_W = m.dc_power_W + dcdc_W;
    r.max_pack_share = std::max(r.max_pack_share, (braking ? -pack_W : pack_W) / pack_limit_W);
    // the battery answers: V = OCV - R I with I = P / V
    const double P = pack_W;
    V = 0.5 * (ocv + std::sqrt(ocv * ocv - 4.0 * R * P));
  }
  return r;
}

}  // namespace

TEST(EmsLiveLimits, AccelerationBoostIsNeverClampedWithTheLimitModel) {
  // 50 -> 230 rad/s in 3 s: across the e-machine's corner into its constant-power range
  const LoopResult with = closedLoop(true, 50.0, 230.0, 3.0, false);
  const LoopResult without = closedLoop(false, 50.0, 230.0, 3.0, false);
  std::printf("boost: with %d/%d clamped %.0f J; without %d clamped %.0f J\n", with.clamped, with.steps,
              with.boost_J, without.clamped, without.boost_J);
  EXPECT_EQ(with.clamped, 0);
  EXPECT_GT(with.boost_J, 0.0);
  // the published limits are one step old: clamped while the speed rises past the corner
  EXPECT_GT(without.clamped, with.steps / 10) << "the reference loop should show the old clamp";
  // nothing given away: the same boost energy within the clamp's share
  EXPECT_NEAR(with.boost_J, without.boost_J, 0.01 * without.boost_J);
}

TEST(EmsLiveLimits, RegenerationIsNeverClampedAndLosesNothing) {
  // braking 230 -> 60 rad/s in 4 s with the voltage rising as the battery charges
  const LoopResult with = closedLoop(true, 230.0, 60.0, 4.0, true);
  const LoopResult without = closedLoop(false, 230.0, 60.0, 4.0, true);
  std::printf("regen: with %d/%d clamped %.0f J; without %d clamped %.0f J\n", with.clamped, with.steps,
              with.regen_J, without.clamped, without.regen_J);
  EXPECT_EQ(with.clamped, 0);
  EXPECT_GT(with.regen_J, 0.0);
  // the regenerated energy is the e-machine's limit either way (≤ 1 % lost to the prediction)
  EXPECT_GE(with.regen_J, 0.99 * without.regen_J);
}

TEST(EmsLiveLimits, ThePackIsNeverAskedBeyondItsLimitsWithTheDcDcLoad) {
  // A cold pack (10 kW each way) with the 1.84 kW DC/DC load of the hybrid's 24 V net: boost and
  // regeneration bounded by the pack exactly, by the e-machine's own loss model.
  const double limit = 10000.0, dcdc = 1842.0;
  const LoopResult boost = closedLoop(true, 80.0, 200.0, 3.0, false, limit, dcdc);
  const LoopResult regen = closedLoop(true, 200.0, 80.0, 3.0, true, limit, dcdc);
  std::printf("pack share: boost max %.6f, regen max %.6f\n", boost.max_pack_share, regen.max_pack_share);
  const double margin = emsParams().battery.limit_margin;  // kept free for the limit's drift
  EXPECT_LE(boost.max_pack_share, 1.0 - margin + 1e-9);
  EXPECT_LE(regen.max_pack_share, 1.0 - margin + 1e-9);
  EXPECT_EQ(boost.clamped, 0);
  EXPECT_EQ(regen.clamped, 0);
  // and bounded by it, by nothing cruder: the pack's limit less the margin is reached within 0.1 %
  EXPECT_GT(boost.max_pack_share, 1.0 - margin - 0.001);
  EXPECT_GT(regen.max_pack_share, 1.0 - margin - 0.001);
}
