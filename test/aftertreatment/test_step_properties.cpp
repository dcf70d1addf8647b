// Properties of the step loop: no heap allocation, bitwise deterministic.
#include <gtest/gtest.h>

#include <cmath>

#include "../common/alloc_counter.hpp"
#include "aftertreatment/aftertreatment.hpp"
#include "support.hpp"

using hbt::testing::allocations;

namespace hbt::aftertreatment {
namespace {

AtsInputs inputs(int k) {
  AtsInputs in;
  const double load = 0.5 + 0.5 * std::sin(0.01 * k);
  in.exhaust_mass_flow_kg_s = 0.05 + 0.15 * load;
  in.exhaust_T_K = 500.0 + 200.0 * load;
  in.nox_mass_flow_kg_s = 1e-4 * load;
  in.co_mass_flow_kg_s = 1e-5;
  in.ambient_T_K = 283.15;
  in.vehicle_speed_m_s = 10.0 * load;
  return in;
}

TEST(AftertreatmentStep, DoesNotAllocate) {
  const AtsParams p = test::loadParams();
  const long c0 = allocations();
  Aftertreatment ats(p);
  EXPECT_GT(allocations(), c0);  // the counter works: construction allocates
  ats.reset(283.15);
  for (int k = 0; k < 2000; ++k) ats.step(0.1, inputs(k));  // warm: dosing and SCR active
  ASSERT_GT(ats.nitrogen().nh3_dosed_mol, 0.0);
  const long before = allocations();
  for (int k = 2000; k < 3000; ++k) ats.step(0.1, inputs(k));
  EXPECT_EQ(allocations(), before);
}

TEST(AftertreatmentStep, IsDeterministic) {
  const AtsParams p = test::loadParams();
  Aftertreatment a(p), b(p);
  a.reset(283.15);
  b.reset(283.15);
  for (int k = 0; k < 3000; ++k) {
    a.step(0.1, inputs(k));
    b.step(0.1, inputs(k));
  }
  EXPECT_EQ(a.outputs().tailpipe_nox_kg, b.outputs().tailpipe_nox_kg);
  EXPECT_EQ(a.outputs().back_pressure_Pa, b.outputs().back_pressure_Pa);
  EXPECT_EQ(a.energy().can_loss_J, b.energy().can_loss_J);
  for (int i = 0; i < a.brick(kSCR).slices(); ++i) EXPECT_EQ(a.scr().coverage(i), b.scr().coverage(i));
}

}  // namespace
}  // namespace hbt::aftertreatment
