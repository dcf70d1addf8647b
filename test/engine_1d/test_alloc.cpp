// No heap allocation (operator new) inside Engine1D::step() once running (counting allocator).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "support.hpp"

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
static std::atomic<long> g_allocs{0};
void* operator new(std::size_t n) {
  ++g_allocs;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

using namespace hbt::engine_1d;
using namespace hbt::engine_1d::test;

TEST(Engine1DAlloc, StepDoesNotAllocate) {
  Engine1D e(defaultParams(), repoRoot());
  e.reset(1400.0 * kRpm, 500.0);
  run(e, 1400.0, 500.0, 0.3);
  const long a0 = g_allocs;
  run(e, 1400.0, 800.0, 0.5);  // includes a torque change (controllers, smoke limiter)
  EXPECT_EQ(g_allocs - a0, 0);
}
