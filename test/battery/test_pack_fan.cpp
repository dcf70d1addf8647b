// The pack's ventilation fans (src/battery/pack_fan.hpp) and its electric energy in the battery
// model: the thermostat's hysteresis; the fan's energy drawn through the terminals equals
// rated power x time on and closes the electrical balance terminal = external request + fan (the
// ledger's item); the model's energy balance with the fan heat; the fan lowers the cells' peak.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "battery/battery_model.hpp"
#include "battery/pack_fan.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"

using namespace hbt;
using namespace hbt::battery;
using units::celsiusToK;

namespace {

BatteryParams shipped() {
  BatteryParams p;
  ParamSet ps;
  p.declare(ps);
  applyParams(ps, readYamlParams("config/battery.yaml"), {"cosim/"});
  return p;
}

}  // namespace

TEST(PackFan, ThermostatSwitchesWithHysteresis) {
  PackFanParams fp;
  fp.rated_power_W = 6.0;
  fp.on_K = celsiusToK(35.0);
  fp.off_K = celsiusToK(30.0);
  PackFan fan(fp);
  fan.reset(celsiusToK(25.0));
  EXPECT_FALSE(fan.on());
  // Rising: stays off inside the band, on at the upper threshold.
  EXPECT_FALSE(fan.update(celsiusToK(32.0)));
  EXPECT_FALSE(fan.update(celsiusToK(34.999)));
  EXPECT_TRUE(fan.update(celsiusToK(35.0)));
  EXPECT_EQ(fan.power_W(), 6.0);
  // Falling: stays on inside the band, off at the lower threshold.
  EXPECT_TRUE(fan.update(celsiusToK(31.0)));
  EXPECT_TRUE(fan.update(celsiusToK(30.001)));
  EXPECT_FALSE(fan.update(celsiusToK(30.0)));
  EXPECT_EQ(fan.power_W(), 0.0);
  // A warm start above the upper threshold starts with the fan on.
  fan.reset(celsiusToK(40.0));
  EXPECT_TRUE(fan.on());
}

TEST(PackFan, FanEnergyIsDrawnThroughTheTerminalsAndClosesTheBalances) {
  // 13s7p pack in a well-cooled housing (~1 kW/K, cells follow the air within a minute) in air
  // swinging 25-41 degC with a 600 s period, 3000 s of +-12 kW (within the limits): the fan
  // cycles. Its energy = rated power x time on; the terminal energy = the external request's
  // energy + the fan's (the ledger: terminal + unmet = e-machine DC + DC/DC + fan); the model's
  // residual with the fan heat back in the enclosure closes.
  BatteryParams p = shipped();
  p.enclosure.h_cells_natural_W_m2K = p.enclosure.h_wall_inside_natural_W_m2K = 300.0;
  p.enclosure.h_cells_fan_W_m2K = p.enclosure.h_wall_inside_fan_W_m2K = 300.0;
  p.enclosure.h_outside_natural_W_m2K = 100.0;
  p.housing.area_m2 = 20.0;
  BatteryModel m(p, "config/battery.yaml");
  m.reset(celsiusToK(33.0));
  BatteryInputs in;
  const double h = 0.01;
  double external_J = 0.0, fan_test_J = 0.0, throughput = 0.0;
  int switches = 0;
  bool was_on = m.outputs().fan_on;
  for (int k = 0; k < 300000; ++k) {
    const double t = k * h;
    in.power_request_W = 12e3 * std::sin(2 * units::kPi * t / 41.0);
    in.air_speed_m_s = 6.0 + 5.0 * std::sin(t / 60.0);
    in.air_T_K = celsiusToK(33.0 + 8.0 * std::sin(2 * units::kPi * t / 600.0));
    m.step(h, in);
    const BatteryOutputs& o = m.outputs();
    ASSERT_FALSE(o.request_limited) << "t = " << t;
    external_J += in.power_request_W * h;
    fan_test_J += o.fan_power_W * h;
    throughput += std::abs(o.power_W) * h;
    switches += o.fan_on != was_on;
    was_on = o.fan_on;
  }
  const BatteryOutputs& o = m.outputs();
  std::printf("3000 s in 25-41 degC air: fan on %.0f s, %d switches, fan energy %.1f J, terminal %.6g J = external "
              "%.6g J + fan (diff %.2e J), residual %.2e J, cells %.2f degC, housing %.2f degC\n",
              o.fan_on_time_s, switches, o.fan_energy_J, o.terminal_energy_J, external_J,
              o.terminal_energy_J - external_J - o.fan_energy_J, o.energy_residual_J,
              units::kToCelsius(o.cell_T_K), units::kToCelsius(o.housing_T_K));
  EXPECT_GT(switches, 1);
  EXPECT_GT(o.fan_on_time_s, 0.0);
  EXPECT_NEAR(o.fan_energy_J, p.fan.rated_power_W * o.fan_on_time_s, 1e-9 * o.fan_energy_J);
  EXPECT_NEAR(o.fan_energy_J, fan_test_J, 1e-9 * o.fan_energy_J);
  EXPECT_NEAR(o.terminal_energy_J, external_J + o.fan_energy_J, 1e-9 * throughput);
  EXPECT_LT(std::abs(o.energy_residual_J), 1e-9 * throughput);
  const double therm = o.loss_energy_J + o.fan_energy_J - o.heat_to_air_J - o.ventilation_heat_J - o.stored_heat_change_J;
  EXPECT_LT(std::abs(therm), 1e-9 * throughput);
}

TEST(PackFan, FanLowersTheCellTemperature) {
  // The same hot duty with the fans and with fans that never switch on (threshold above the
  // run): the ventilation and the higher inner conductance keep the cells cooler, and heat leaves
  // with the ventilation air only when the fans run.
  BatteryParams p = shipped();
  BatteryParams nofan = p;
  nofan.fan.on_K = celsiusToK(76.0);
  nofan.fan.off_K = celsiusToK(75.0);
  BatteryModel a(p), b(nofan);
  a.reset(celsiusToK(25.0));
  b.reset(celsiusToK(25.0));
  BatteryInputs in;
  in.air_T_K = celsiusToK(25.0);
  in.air_speed_m_s = 5.0;
  for (int k = 0; k < 200000; ++k) {
    in.power_request_W = 15e3 * std::sin(2 * units::kPi * k * 0.01 / 30.0);
    a.step(0.01, in);
    b.step(0.01, in);
  }
  std::printf("2000 s of +-15 kW at 25 degC: cells %.2f degC with the fan (on %.0f s), %.2f degC without; "
              "housing %.2f / %.2f degC\n", units::kToCelsius(a.outputs().cell_T_K), a.outputs().fan_on_time_s,
              units::kToCelsius(b.outputs().cell_T_K), units::kToCelsius(a.outputs().housing_T_K),
              units::kToCelsius(b.outputs().housing_T_K));
  EXPECT_GT(a.outputs().fan_on_time_s, 0.0);
  EXPECT_EQ(b.outputs().fan_on_time_s, 0.0);
  EXPECT_LT(a.outputs().cell_T_K, b.outputs().cell_T_K);
  EXPECT_GT(a.outputs().ventilation_heat_J, 0.0);
  EXPECT_EQ(b.outputs().ventilation_heat_J, 0.0);
}
