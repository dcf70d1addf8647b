// The ventilation fans' operating point (src/battery/pack_ventilation.hpp) against independent
// references: the fan line meets the system curve (textbook quadratic formula, a different form
// from the model's), its limit cases (free air; purely linear or purely quadratic resistance),
// the ideal-gas density and m_dot c_p written out by hand, and the shipped packs' values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "battery/battery_model.hpp"
#include "battery/pack_ventilation.hpp"
#include "common/units.hpp"
#include "support.hpp"
#include "common/yaml_params.hpp"

using namespace hbt;
using namespace hbt::battery;
using hbt::battery::test::shippedParams;
using units::celsiusToK;

namespace {

PackVentilationParams example() {
  PackVentilationParams v;
  v.fan_free_flow_m3_s = 0.03;
  v.fan_max_pressure_Pa = 40.0;
  v.fan_count = 2;
  v.linear_resistance_Pa_s_m3 = 400.0;
  v.quadratic_resistance_Pa_s2_m6 = 6000.0;
  return v;
}

}  // namespace

TEST(PackVentilation, OperatingPointIsTheHandSolvedQuadratic) {
  // 40 (1 - V/0.06) = 400 V + 6000 V^2  ->  6000 V^2 + (400 + 666.67) V - 40 = 0,
  // V = (-b + sqrt(b^2 + 4 a c))/(2 a) with a = 6000, b = 1066.67, c = 40.
  const PackVentilation vent(example());
  const double a = 6000.0, b = 400.0 + 40.0 / 0.06, c = 40.0;
  const double V = (-b + std::sqrt(b * b + 4 * a * c)) / (2 * a);
  std::printf("example: V = %.6f m^3/s (hand %.6f), dp = %.4f Pa\n", vent.flow_m3_s(), V, vent.pressure_Pa());
  EXPECT_NEAR(vent.flow_m3_s(), V, 1e-14);
  // At the operating point the fans' pressure rise equals the system's drop.
  const double dp_sys = 400.0 * V + 6000.0 * V * V;
  EXPECT_NEAR(vent.pressure_Pa(), dp_sys, 1e-12);
  EXPECT_GT(V, 0.0);
  EXPECT_LT(V, 0.06);  // below the two fans' free-air flow
}

TEST(PackVentilation, LimitCases) {
  // No resistance: the fans' free-air flow n V_free at zero pressure.
  PackVentilationParams v = example();
  v.linear_resistance_Pa_s_m3 = 0.0;
  v.quadratic_resistance_Pa_s2_m6 = 0.0;
  EXPECT_NEAR(PackVentilation(v).flow_m3_s(), 0.06, 1e-15);
  EXPECT_NEAR(PackVentilation(v).pressure_Pa(), 0.0, 1e-12);
  // Linear resistance only: two straight lines, V = p_max/(R + p_max/(n V_free)).
  v.linear_resistance_Pa_s_m3 = 400.0;
  EXPECT_NEAR(PackVentilation(v).flow_m3_s(), 40.0 / (400.0 + 40.0 / 0.06), 1e-15);
  // One fan against a pure K: V^2 K = p_max (1 - V/V0) checked by substitution.
  v.fan_count = 1;
  v.linear_resistance_Pa_s_m3 = 0.0;
  v.quadratic_resistance_Pa_s2_m6 = 2e4;
  const PackVentilation one(v);
  const double V = one.flow_m3_s();
  EXPECT_NEAR(2e4 * V * V, 40.0 * (1.0 - V / 0.03), 1e-12);
  // Two fans in parallel move more air through the same system, less than twice as much.
  v.fan_count = 2;
  const double V2 = PackVentilation(v).flow_m3_s();
  EXPECT_GT(V2, V);
  EXPECT_LT(V2, 2.0 * V);
}

TEST(PackVentilation, DensityAndConductanceByHand) {
  const PackVentilation vent(example());
  // Ideal gas: rho = 101325/(287.05 T): 1.2922 kg/m^3 at 0 degC, 1.1272 at 40 degC.
  EXPECT_NEAR(vent.density_kg_m3(273.15), 101325.0 / (287.05 * 273.15), 1e-14);
  EXPECT_NEAR(vent.density_kg_m3(273.15), 1.2922, 1e-4);
  const double T = celsiusToK(40.0);
  EXPECT_NEAR(vent.conductance_W_K(true, T), 101325.0 / (287.05 * T) * vent.flow_m3_s() * 1007.0, 1e-12);
  EXPECT_EQ(vent.conductance_W_K(false, T), 0.0);
}

TEST(PackVentilation, ShippedPacks) {
  // The shipped fans, filter, gaps and losses: the operating point lies on both curves, the flow
  // is a fraction of the fans' free-air flow, and m_dot c_p is tens of W/K.
  for (const char* f : {"", "config/battery_pack/production_13s2p.yaml"}) {
    const BatteryParams bp = shippedParams(f);
    const BatteryModel m(bp, "config/battery.yaml");
    const PackVentilation& vent = m.thermal().ventilation();
    const auto& v = bp.ventilation;
    const double V = vent.flow_m3_s();
    const double R = v.filter_resistance_Pa_s_m3 + bp.housing.cell_gap_resistance_Pa_s_m3;
    const double dp_sys = R * V + v.minor_loss_Pa_s2_m6 * V * V;
    const double dp_fan = v.fan_max_pressure_Pa * (1.0 - V / (v.fan_count * v.fan_free_flow_m3_s));
    std::printf("%s: V = %.5f m^3/s (%.0f %% of free air), dp = %.2f Pa (filter %.2f, gaps %.2f, minor %.2f); "
                "m_dot c_p %.2f W/K at 0 degC, %.2f W/K at 40 degC\n", *f ? f : "13s7p (battery.yaml)", V,
                100.0 * V / (v.fan_count * v.fan_free_flow_m3_s), dp_fan, v.filter_resistance_Pa_s_m3 * V,
                bp.housing.cell_gap_resistance_Pa_s_m3 * V, v.minor_loss_Pa_s2_m6 * V * V,
                vent.conductance_W_K(true, celsiusToK(0.0)), vent.conductance_W_K(true, celsiusToK(40.0)));
    EXPECT_NEAR(dp_fan, dp_sys, 1e-12);
    EXPECT_NEAR(vent.pressure_Pa(), dp_sys, 1e-12);
    EXPECT_GT(vent.conductance_W_K(true, celsiusToK(40.0)), 10.0);
    EXPECT_LT(vent.conductance_W_K(true, celsiusToK(40.0)), 100.0);
  }
}
