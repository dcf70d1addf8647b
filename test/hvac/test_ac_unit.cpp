// A/C unit (src/hvac/ac_unit.hpp): shaft power = heat / COP, COP = Carnot fraction of the
// reversed Carnot cycle at the ambient, capacity and compressor limits.
#include <gtest/gtest.h>

#include "hvac/ac_unit.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::hvac;

TEST(AcUnit, ShaftPowerIsHeatOverCop) {
  const HvacParams p = test::yamlParams();
  AcUnit ac(p.ac);
  for (double T_a : {288.15, 298.15, 308.15, 313.15}) {
    const AcOperation op = ac.operate(9000.0, T_a, true);
    EXPECT_EQ(op.cooling_W, 9000.0);
    EXPECT_NEAR(op.shaft_W * op.cop, op.cooling_W, 1e-9);
    EXPECT_NEAR(op.electric_W, 1200.0 * 0.5, 1e-9);  // fans at half load
  }
  EXPECT_NEAR(ac.cop(313.15), 0.35 * 278.15 / (313.15 + 15.0 - 278.15), 1e-12);  // 1.95 at 40 degC
  EXPECT_NEAR(ac.cop(298.15), 0.35 * 278.15 / 35.0, 1e-12);                      // 2.78 at 25 degC
  EXPECT_GT(ac.cop(298.15), ac.cop(313.15));  // hotter ambient, lower COP
  EXPECT_EQ(ac.cop(250.0), 6.0);              // capped where the lift vanishes
}

TEST(AcUnit, CapacityAndCompressorLimits) {
  const HvacParams p = test::yamlParams();
  AcUnit ac(p.ac);
  const AcOperation full = ac.operate(50000.0, 313.15, true);
  EXPECT_EQ(full.cooling_W, 18000.0);
  EXPECT_NEAR(full.electric_W, 1200.0, 1e-12);
  const AcOperation stopped = ac.operate(9000.0, 313.15, false);  // engine stopped: no compressor
  EXPECT_EQ(stopped.cooling_W, 0.0);
  EXPECT_EQ(stopped.shaft_W, 0.0);
  EXPECT_EQ(stopped.electric_W, 0.0);
}
