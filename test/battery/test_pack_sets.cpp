// The pack sets (config/battery_pack/*.yaml, launch argument pack): read as the node reads them
// (battery.yaml, then the set replacing pack/ and housing/); the set changes nothing else; the
// power limits of a pack of Np strings are Np times one string's (same cells, same state), so the
// production_13s2p limits are 2/7 of the 13s7p's; its envelope (the numbers quoted in its file).
#include <gtest/gtest.h>

#include <cstdio>

#include "battery/battery_model.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::battery;
using hbt::battery::test::shippedParams;
using units::celsiusToK;

namespace {

constexpr const char* kProduction = "config/battery_pack/production_13s2p.yaml";

}  // namespace

TEST(PackSets, ProductionSetReplacesOnlyPackAndHousing) {
  const BatteryParams base = shippedParams(""), prod = shippedParams(kProduction);
  EXPECT_EQ(prod.pack.cells_in_series, 13);
  EXPECT_EQ(prod.pack.cells_in_parallel, 2);
  EXPECT_LT(prod.housing.area_m2, base.housing.area_m2);
  // Everything outside the set is battery.yaml's.
  EXPECT_EQ(prod.cell.table_file, base.cell.table_file);
  EXPECT_EQ(prod.cell.capacity_Ah, base.cell.capacity_Ah);
  EXPECT_EQ(prod.limits.soc_min, base.limits.soc_min);
  EXPECT_EQ(prod.enclosure.h_cells_fan_W_m2K, base.enclosure.h_cells_fan_W_m2K);
  EXPECT_EQ(prod.fan.rated_power_W, base.fan.rated_power_W);
  // A set file must hold every key of both groups: a missing one is named with the file.
  ParamSet set;
  BatteryParams q = base;
  q.declarePackSet(set);
  ParamSource src = readYamlParams(kProduction);
  ASSERT_EQ(src.values.erase("housing/mass_kg"), 1u);
  try {
    applyParams(set, src);
    requireKeys(set, src);
    ADD_FAILURE() << "a set without housing/mass_kg was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("housing/mass_kg"), std::string::npos) << e.what();
  }
}

TEST(PackSets, PowerLimitsScaleWithTheParallelStrings) {
  BatteryModel big(shippedParams(""), "config/battery.yaml"), small(shippedParams(kProduction), kProduction);
  std::printf("13s2p: %.0f Ah, %.2f kWh nominal (3.7 V), cell mass %.1f kg\n", 2 * 27.0, 26 * 27.0 * 3.7 / 1e3,
              26 * small.params().cell.mass_kg);
  for (double Tc : {25.0, 5.0, 0.0})
    for (double s : {0.25, 0.5, 0.75}) {
      big.reset(celsiusToK(Tc), s);
      small.reset(celsiusToK(Tc), s);
      const BatteryOutputs &b = big.outputs(), &o = small.outputs();
      std::printf("13s2p T %4.0f degC SOC %.2f: discharge %.2f kW, charge %.2f kW\n", Tc, s,
                  o.discharge_power_limit_W / 1e3, o.charge_power_limit_W / 1e3);
      EXPECT_NEAR(o.discharge_power_limit_W, 2.0 / 7.0 * b.discharge_power_limit_W, 1e-12 * b.discharge_power_limit_W);
      EXPECT_NEAR(o.charge_power_limit_W, 2.0 / 7.0 * b.charge_power_limit_W, 1e-12 * b.charge_power_limit_W);
      EXPECT_NEAR(o.ocv_V, b.ocv_V, 1e-12);
    }
  // The 24 V consumers' DC/DC load (1842 W) is covered at the bottom of the full-power window at 0 degC.
  small.reset(celsiusToK(0.0), 0.25);
  EXPECT_GT(small.outputs().discharge_power_limit_W, 1842.0 * 1.5);
  // Stop-start needs 15 kW to crank (config/ems.yaml min_discharge_power_W): this pack cannot.
  small.reset(celsiusToK(25.0), 0.75);
  EXPECT_LT(small.outputs().discharge_power_limit_W, 15e3);
}
