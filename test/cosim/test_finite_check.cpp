// The output guard of finite_check.hpp on the twin's own messages (no master needed): every
// floating-point field is reached, by name, in order, also inside arrays; finite messages pass.
#include <gtest/gtest.h>
#include <hybrid_bus_twin/BatteryState.h>
#include <hybrid_bus_twin/ProbeSignal.h>
#include <hybrid_bus_twin/StepCommand.h>
#include <hybrid_bus_twin/VehicleState.h>

#include <cmath>
#include <limits>

#include "cosim/finite_check.hpp"

using hbt::cosim::nonFiniteField;
using hbt::cosim::topLevelFieldNames;

TEST(FiniteCheck, FiniteMessagePasses) {
  hybrid_bus_twin::BatteryState m;
  m.soc = 0.5;
  m.terminal_voltage_v = 48.0;
  EXPECT_EQ(nonFiniteField(m), "");
}

TEST(FiniteCheck, EveryFloatFieldOfAMessageIsCheckedByName) {
  // set each top-level float64 of BatteryState to NaN in turn: the guard names that field
  const std::vector<std::string> names =
      topLevelFieldNames(ros::message_traits::Definition<hybrid_bus_twin::BatteryState>::value());
  ASSERT_GT(names.size(), 20u);
  EXPECT_EQ(names.front(), "header");
  int checked = 0;
  const auto set_nan = [](hybrid_bus_twin::BatteryState& m, const std::string& n) {
#define HBT_FIELD(f) if (n == #f) { m.f = std::numeric_limits<double>::quiet_NaN(); return true; }
    HBT_FIELD(terminal_voltage_v) HBT_FIELD(current_a) HBT_FIELD(soc) HBT_FIELD(cell_temperature_k)
    HBT_FIELD(loss_power_w) HBT_FIELD(energy_residual_j) HBT_FIELD(charge_current_limit_a)
#undef HBT_FIELD
    return false;
  };
  for (const auto& n : names) {
    hybrid_bus_twin::BatteryState m;
    if (!set_nan(m, n)) continue;
    EXPECT_EQ(nonFiniteField(m), n + ": nan");
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}

TEST(FiniteCheck, InfinityAndTheFirstBadFieldWins) {
  hybrid_bus_twin::VehicleState m;
  m.distance_m = std::numeric_limits<double>::quiet_NaN();
  m.speed_m_s = std::numeric_limits<double>::infinity();
  EXPECT_EQ(nonFiniteField(m), "speed_m_s: inf");  // the first in the message's order
}

TEST(FiniteCheck, ArraysNameTheElement) {
  hybrid_bus_twin::ProbeSignal m;
  m.values = {1.0, 2.0, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_EQ(nonFiniteField(m), "values[2]: nan");
}

TEST(FiniteCheck, IntegersStringsAndTimesAreNotFloats) {
  hybrid_bus_twin::StepCommand m;  // uint64, string, string[], uint32[]: nothing to check
  m.reason = "nan";
  m.topics = {"nan"};
  m.dt_s = 0.01;
  EXPECT_EQ(nonFiniteField(m), "");
  m.dt_s = -std::numeric_limits<double>::infinity();
  EXPECT_EQ(nonFiniteField(m), "dt_s: -inf");
}

TEST(FiniteCheck, DefinitionParsing) {
  const std::string def =
      "# comment line\n"
      "std_msgs/Header header\n"
      "uint8 GRANT=0   # a constant\n"
      "float64 speed_mps  # [m/s]\n"
      "float64[] temps_k\n"
      "\n"
      "================================================================================\n"
      "MSG: std_msgs/Header\n"
      "uint32 seq\n";
  EXPECT_EQ(topLevelFieldNames(def), (std::vector<std::string>{"header", "speed_mps", "temps_k"}));
}
