// Properties of the step loop: no heap allocation, bitwise deterministic.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "aftertreatment/aftertreatment.hpp"
#include "support.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// Counting replacement of the global allocation functions (this test binary only).
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

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
  const long c0 = g_allocations.load();
  Aftertreatment ats(p);
  EXPECT_GT(g_allocations.load(), c0);  // the counter works: construction allocates
  ats.reset(283.15);
  for (int k = 0; k < 2000; ++k) ats.step(0.1, inputs(k));  // warm: dosing and SCR active
  ASSERT_GT(ats.nitrogen().nh3_dosed_mol, 0.0);
  const long before = g_allocations.load();
  for (int k = 2000; k < 3000; ++k) ats.step(0.1, inputs(k));
  EXPECT_EQ(g_allocations.load(), before);
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
