// No heap allocation (operator new) inside Engine1D::step() once running (counting allocator).
#include <gtest/gtest.h>

#include "../common/alloc_counter.hpp"
#include "support.hpp"

using hbt::testing::allocations;

using namespace hbt::engine_1d;
using namespace hbt::engine_1d::test;

TEST(Engine1DAlloc, StepDoesNotAllocate) {
  Engine1D e(defaultParams(), repoRoot());
  e.reset(1400.0 * kRpm, 500.0);
  run(e, 1400.0, 500.0, 0.3);
  const long a0 = allocations();
  run(e, 1400.0, 800.0, 0.5);  // includes a torque change (controllers, smoke limiter)
  EXPECT_EQ(allocations() - a0, 0);
}
