// Properties of the e-machine step loop: no heap allocation, bitwise deterministic.
#include <gtest/gtest.h>

#include <cmath>

#include "../common/alloc_counter.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "emachine/emachine_model.hpp"

using hbt::testing::allocations;

namespace hbt::emachine {
namespace {

EMachineParams params() {
  EMachineParams p;
  ParamSet ps;
  p.declare(ps);
  applyParams(ps, readYamlParams("config/emachine.yaml"), {"cosim/"});
  return p;
}

EMachineInputs inputs(int k) {
  EMachineInputs in;
  in.crank_speed_rad_s = units::rpmToRadps(600.0 + 800.0 * (0.5 + 0.5 * std::sin(0.003 * k)));
  in.torque_request_Nm = 600.0 * std::sin(0.01 * k);
  in.dc_voltage_V = 46.0 + 3.0 * std::cos(0.002 * k);
  in.coolant_T_K = 330.0;
  return in;
}

TEST(EMachineStep, DoesNotAllocate) {
  const EMachineParams p = params();
  const long c0 = allocations();
  EMachineModel m(p, "config/emachine.yaml");
  EXPECT_GT(allocations(), c0);  // the counter works: construction allocates
  m.reset(300.0);
  for (int k = 0; k < 1000; ++k) m.step(0.01, inputs(k));
  const long before = allocations();
  for (int k = 1000; k < 20000; ++k) m.step(0.01, inputs(k));
  EXPECT_EQ(allocations(), before);
}

TEST(EMachineStep, IsDeterministic) {
  const EMachineParams p = params();
  EMachineModel a(p, "config/emachine.yaml"), b(p, "config/emachine.yaml");
  a.reset(280.0);
  b.reset(280.0);
  for (int k = 0; k < 20000; ++k) {
    a.step(0.01, inputs(k));
    b.step(0.01, inputs(k));
  }
  EXPECT_EQ(a.outputs().winding_T_K, b.outputs().winding_T_K);
  EXPECT_EQ(a.outputs().dc_J, b.outputs().dc_J);
  EXPECT_EQ(a.outputs().energy_residual_J, b.outputs().energy_residual_J);
}

}  // namespace
}  // namespace hbt::emachine
