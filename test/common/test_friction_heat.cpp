// The split of an engine's heat between its metal and its oil (common/friction_heat.hpp), the
// piece the 1D engine applies to its Chen-Flynn friction work and wall heat: conservation
// (oil + metal = wall + friction for any split) and the two limits (f_o = 0: all in the metal,
// f_o = 1: the whole friction in the oil).
#include <gtest/gtest.h>

#include "common/friction_heat.hpp"

using hbt::splitEngineHeat;

TEST(FrictionHeat, AllFrictionEndsInOilOrMetal) {
  for (double wall : {0.0, 1.5e3, 42.0e3})
    for (double fric : {0.0, 2.4e3, 31.0e3})
      for (double f : {0.0, 0.25, 0.5, 1.0}) {
        const auto s = splitEngineHeat(wall, fric, f);
        EXPECT_NEAR(s.metal_W + s.oil_W, wall + fric, 1e-12 * (wall + fric));
        EXPECT_DOUBLE_EQ(s.oil_W, f * fric);
      }
  const auto none = splitEngineHeat(5e3, 8e3, 0.0);
  EXPECT_DOUBLE_EQ(none.oil_W, 0.0);
  EXPECT_DOUBLE_EQ(none.metal_W, 13e3);
  const auto all = splitEngineHeat(5e3, 8e3, 1.0);
  EXPECT_DOUBLE_EQ(all.oil_W, 8e3);
  EXPECT_DOUBLE_EQ(all.metal_W, 5e3);
}
