// MessageLayout and the unit a field's name states (src/fmi/message_layout.hpp), against the
// package's own message definitions (msg/*.msg, read here from the files):
// - every field whose comment states its unit in brackets ([W], [K], [rad/s], [kg/s], [Ah] ...)
//   gets that unit from its name suffix alone (dimension and factor): the two independent
//   statements of the unit agree for every message of the package;
// - the parse keeps the definition's order, skips the header, comments and constants, and stops
//   at the embedded definitions of nested types;
// - the conversions: Ah -> A s (3600), percent -> 1 (0.01), degC -> K (+273.15).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "fmi/message_layout.hpp"

namespace hbt::fmi {
namespace {

namespace fs = std::filesystem;

std::string readFile(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

/// The bracketed units of the comments, as the dimension and factor they denote (the ones the
/// messages use; others are skipped and counted).
std::optional<FieldUnit> bracketUnit(const std::string& b) {
  static const std::map<std::string, std::string> same = {
      {"W", "W"}, {"K", "K"}, {"J", "J"}, {"Nm", "N.m"}, {"rad/s", "rad/s"}, {"Pa", "Pa"}, {"kg/s", "kg/s"},
      {"s", "s"}, {"mol", "mol"}, {"A", "A"}, {"m^3/s", "m3/s"}, {"m/s", "m/s"}, {"V", "V"}, {"m", "m"},
      {"W/K", "W/K"}, {"rad", "rad"}, {"m/s^2", "m/s2"}, {"kg", "kg"}, {"-", "1"}};
  const auto it = same.find(b);
  if (it != same.end()) return unitNamed(it->second);
  FieldUnit u = *unitNamed("1");
  if (b == "Ah") {
    u = *unitNamed("A");
    u.si.dimension.exponent[2] = 1;
    u.factor = 3600.0;
    return u;
  }
  if (b == "%") return FieldUnit{u.si, 0.01};
  if (b == "ppm") return FieldUnit{u.si, 1e-6};
  return std::nullopt;
}

TEST(MessageLayout, EveryBracketedUnitOfThePackageAgreesWithTheNameSuffix) {
  const std::regex field_line(R"(^(float64|float32)\s+(\w+)\s*#[^\[]*\[([^\],]+)\])");
  int checked = 0;
  for (const auto& e : fs::directory_iterator(HBT_MSG_DIR)) {
    if (e.path().extension() != ".msg") continue;
    std::istringstream in(readFile(e.path()));
    std::string line;
    while (std::getline(in, line)) {
      std::smatch m;
      if (!std::regex_search(line, m, field_line)) continue;
      const auto want = bracketUnit(m[3]);
      if (!want) continue;  // e.g. [0, 1], [kg K]: not a unit this table names
      const FieldUnit got = unitOfName(m[2]);
      EXPECT_EQ(got.si.dimension, want->si.dimension)
          << e.path().filename() << " " << m[2] << ": [" << m[3] << "] is " << want->si.dimension.str() << ", the suffix says "
          << got.si.dimension.str();
      EXPECT_DOUBLE_EQ(got.factor, want->factor) << m[2];
      EXPECT_DOUBLE_EQ(got.offset, 0.0) << m[2];
      ++checked;
    }
  }
  EXPECT_GT(checked, 250);  // the package states units for most of its ~330 float64 fields
}

TEST(MessageLayout, ParsesFieldsInOrderWithoutHeaderCommentsConstantsOrNestedTypes) {
  const std::string def =
      "# leading comment\n"
      "std_msgs/Header header\n"
      "uint8 MODE_A=0   # a constant\n"
      "float64 power_w   # [W]\n"
      "\n"
      "bool fan_on\n"
      "int32 gear # engaged gear\n"
      "float64[] values\n"
      "string name\n"
      "================================================================================\n"
      "MSG: std_msgs/Header\n"
      "uint32 seq\ntime stamp\nstring frame_id\n";
  const MessageLayout l = MessageLayout::parse("pkg/Test", def);
  EXPECT_TRUE(l.hasHeader());
  ASSERT_EQ(l.fields().size(), 5u);
  const std::vector<std::pair<std::string, FieldKind>> want = {{"power_w", FieldKind::kFloat64},
                                                               {"fan_on", FieldKind::kBool},
                                                               {"gear", FieldKind::kInteger},
                                                               {"values", FieldKind::kFloat64Array},
                                                               {"name", FieldKind::kUnsupported}};
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(l.fields()[i].name, want[i].first);
    EXPECT_EQ(l.fields()[i].kind, want[i].second) << want[i].first;
  }
  EXPECT_EQ(*l.find("gear"), 2u);
  EXPECT_FALSE(l.find("seq"));  // a field of the nested header, not of the message
}

TEST(MessageLayout, ConversionsOfNonSiFieldUnits) {
  EXPECT_DOUBLE_EQ(unitOfName("charge_throughput_ah").toSi(2.0), 7200.0);   // 2 Ah = 7200 C
  EXPECT_DOUBLE_EQ(unitOfName("grade_percent").toSi(5.0), 0.05);
  EXPECT_DOUBLE_EQ(unitOfName("ambient_temperature_c").toSi(25.0), 298.15);
  EXPECT_DOUBLE_EQ(unitOfName("ambient_temperature_c").fromSi(273.15), 0.0);
  EXPECT_EQ(unitOfName("thermal_conductance_w_k").si.name, "W/K");  // longest suffix first
  EXPECT_EQ(unitOfName("soc").si.dimension.str(), "1");
  EXPECT_FALSE(unitNamed("degC"));  // only SI names
}

}  // namespace
}  // namespace hbt::fmi
