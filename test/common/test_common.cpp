// Tests of the shared helpers: CSV reader errors name file and key; Table1D interpolation is
// exact on linear data; PID anti-windup keeps the integral bounded under saturation; the angle
// conversions of common/units.hpp have the bits of the M_PI expressions they replaced; the tests'
// own InputError check (test/common/input_errors.hpp) fails on a wrong file or key or no error.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/pid.hpp"
#include "common/species.hpp"
#include "common/table1d.hpp"
#include "common/units.hpp"
#include "input_errors.hpp"

using hbt::testing::expectInputError;
using hbt::testing::KeyMatch;

namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

void throwsXYZ() { throw hbt::InputError("a.yaml", "x/y_z", "bad"); }
void returns() {}

}  // namespace

TEST(TestSupport, ExpectInputErrorChecksFileKeyAndThatItThrows) {
  EXPECT_EQ(expectInputError(throwsXYZ, "a.yaml", "x/y_z"), "a.yaml: key 'x/y_z': bad");
  EXPECT_EQ(expectInputError(throwsXYZ, "a.yaml", "y_", KeyMatch::kContains), "a.yaml: key 'x/y_z': bad");
  EXPECT_NONFATAL_FAILURE(expectInputError(throwsXYZ, "b.yaml", "x/y_z"), "b.yaml");
  EXPECT_NONFATAL_FAILURE(expectInputError(throwsXYZ, "a.yaml", "x/y"), "x/y");
  EXPECT_NONFATAL_FAILURE(expectInputError(throwsXYZ, "a.yaml", "q", KeyMatch::kContains), "does not contain");
  EXPECT_NONFATAL_FAILURE(expectInputError(returns, "a.yaml", "x/y_z"), "no InputError");
}

TEST(CsvTable, ReadsVectoHeaderAndComments) {
  const auto p = writeTemp("ok.csv", "# comment\n<s>,<v> [km/h],<grad>\n0,0,1.5\n10,20,-2\n");
  const auto t = hbt::CsvTable::read(p);
  EXPECT_EQ(t.rows(), 2u);
  EXPECT_DOUBLE_EQ(t.column("v")[1], 20.0);
  EXPECT_DOUBLE_EQ(t.column("<grad>")[1], -2.0);
}

TEST(CsvTable, MissingFileNamesFile) {
  const std::string msg = expectInputError([] { hbt::CsvTable::read("/nonexistent/cycle.vdri"); },
                                           "/nonexistent/cycle.vdri", "(file)");
  EXPECT_NE(msg.find("/nonexistent/cycle.vdri"), std::string::npos) << msg;
}

TEST(CsvTable, NanCellNamesColumnAndLine) {
  const auto p = writeTemp("nan.csv", "<s>,<v>\n0,1\n5,nan\n");
  const std::string msg = expectInputError([&] { hbt::CsvTable::read(p); }, p, "v");
  EXPECT_NE(msg.find("line 3"), std::string::npos) << msg;
}

TEST(CsvTable, TruncatedRowIsRejected) {
  const auto p = writeTemp("trunc.csv", "<s>,<v>,<grad>\n0,1,0\n5,2\n");
  EXPECT_THROW(hbt::CsvTable::read(p), hbt::InputError);
}

TEST(CsvTable, MissingColumnNamesKey) {
  const auto p = writeTemp("col.csv", "a,b\n1,2\n");
  const auto t = hbt::CsvTable::read(p);
  expectInputError([&] { t.column("stop"); }, p, "stop");
}

// The models' former local constants (M_PI / 180.0, 180.0 / M_PI): replaced by these, every
// product or quotient keeps its bits.
static_assert(hbt::units::kPi == M_PI);
static_assert(hbt::units::kRad_per_deg == M_PI / 180.0);
static_assert(hbt::units::kDeg_per_rad == 180.0 / M_PI);

TEST(Units, AngleConversionsHaveTheFormerBits) {
  using namespace hbt::units;
  // the rig's former `step_deg * M_PI / 180.0` (left to right) for the steps the rig and its
  // tests use: identical to step_deg * kRad_per_deg (not so for every double: 0.011, e.g.)
  for (double d : {0.05, 0.1, 0.2, 0.5, 1.0, 2.0}) EXPECT_EQ(degToRad(d), d * M_PI / 180.0) << d;
  for (double r : {1e-3, 0.25, 3.0}) EXPECT_EQ(radToDeg(r), r * (180.0 / M_PI)) << r;
  EXPECT_EQ(radToDeg(degToRad(90.0)), 90.0);
}

TEST(Species, GramsPerMoleAreTheDecimalValues) {
  using namespace hbt::species;
  // the map engine's gas path works in g/mol: gPerMol() must give the decimal g/mol doubles
  EXPECT_EQ(gPerMol(kO2_kg_mol), 31.999);
  EXPECT_EQ(gPerMol(kCO2_kg_mol), 44.010);
  EXPECT_EQ(gPerMol(kH2O_kg_mol), 18.015);
}

TEST(Table1D, ExactOnLinearDataAndClamped) {
  hbt::Table1D t({0.0, 1.0, 3.0}, {1.0, 3.0, 7.0});
  EXPECT_DOUBLE_EQ(t(0.5), 2.0);
  EXPECT_DOUBLE_EQ(t(2.0), 5.0);
  EXPECT_DOUBLE_EQ(t(-1.0), 1.0);
  EXPECT_DOUBLE_EQ(t(4.0), 7.0);
  EXPECT_DOUBLE_EQ(t.extrapolated(4.0), 9.0);
  EXPECT_THROW(hbt::Table1D({0.0, 0.0}, {1.0, 2.0}), hbt::InputError);
}

TEST(Pid, ConvergesOnFirstOrderPlantAndAntiWindup) {
  // Plant dy/dt = (u - y)/tau; PI must bring y to the set point; saturation must not wind up.
  hbt::Pid pid({2.0, 4.0, 0.0, -1.0, 1.0});
  double y = 0.0;
  const double dt = 0.01, tau = 0.5, r = 0.5;
  for (int k = 0; k < 2000; ++k) {
    const double u = pid.update(r - y, dt);
    y += dt * (u - y) / tau;
  }
  EXPECT_NEAR(y, r, 1e-6);
  hbt::Pid sat({1.0, 1.0, 0.0, -1.0, 1.0});
  for (int k = 0; k < 10000; ++k) sat.update(10.0, dt);  // unreachable set point
  EXPECT_LT(sat.integral(), 1.0);
}

#include "common/params.hpp"

TEST(Params, AppliesValuesAndNamesBadKeys) {
  double mass_kg = 15160.0;
  std::string cycle = "Urban";
  hbt::ParamSet ps;
  ps.add("mass_kg", mass_kg, "kg", 1000.0, 60000.0, "curb mass");
  ps.add("cycle", cycle, "mission");
  hbt::ParamSource src;
  src.file = "config/vehicle.yaml";
  src.set("mass_kg", 16000.0);
  hbt::applyParams(ps, src);
  EXPECT_DOUBLE_EQ(mass_kg, 16000.0);

  src.set("mass_kg", -5.0);  // negative mass
  expectInputError([&] { hbt::applyParams(ps, src); }, "config/vehicle.yaml", "mass_kg");
  src.set("mass_kg", std::nan(""));
  EXPECT_THROW(hbt::applyParams(ps, src), hbt::InputError);
  src.set("mass_kg", 16000.0);
  src.set("mas_kg", 1.0);  // typo -> unknown key
  expectInputError([&] { hbt::applyParams(ps, src); }, "config/vehicle.yaml", "mas_kg");
  EXPECT_NO_THROW(hbt::applyParams(ps, src, {"mas_"}));
}

TEST(Params, CaptureRecordsResolvedValuesAndTheirSource) {
  double mass_kg = 15160.0, cd = 0.6;
  std::vector<double> gears{3.4, 1.9};
  bool retarder = true;
  hbt::ParamSet ps;
  ps.add("mass_kg", mass_kg, "kg", 1000.0, 60000.0, "curb mass");
  ps.add("cd", cd, "-", 0.1, 2.0, "drag coefficient");
  ps.add("gears", gears, "-", 0.1, 10.0, "ratios");
  ps.add("retarder", retarder, "retarder fitted");
  hbt::ParamSource src;
  src.file = "config/vehicle.yaml";
  src.set("mass_kg", 16000.5);
  src.set("gears", std::vector<double>{3.36, 1.91, 1.42});
  hbt::applyParams(ps, src);  // no capture alive: nothing recorded anywhere
  hbt::ParamCapture outer;
  {
    hbt::ParamCapture inner;  // the innermost capture receives
    hbt::applyParams(ps, src);
    ASSERT_EQ(inner.params().size(), 4u);
    const auto& p = inner.params();
    EXPECT_EQ(p[0].file, "config/vehicle.yaml");
    EXPECT_EQ(p[0].key, "mass_kg");
    EXPECT_EQ(p[0].value, "16000.5");
    EXPECT_EQ(p[0].unit, "kg");
    EXPECT_TRUE(p[0].from_file);
    EXPECT_EQ(p[1].key, "cd");
    EXPECT_EQ(std::stod(p[1].value), 0.6);  // %.17g: the default, exactly
    EXPECT_FALSE(p[1].from_file);
    EXPECT_EQ(p[2].value, "[3.3599999999999999, 1.9099999999999999, 1.4199999999999999]");
    EXPECT_TRUE(p[2].from_file);
    EXPECT_EQ(p[3].value, "true");
    EXPECT_FALSE(p[3].from_file);
  }
  EXPECT_TRUE(outer.params().empty());
  hbt::applyParams(ps, src);  // the inner capture ended: back to the outer one
  EXPECT_EQ(outer.params().size(), 4u);
  src.set("mas_kg", 1.0);  // a rejected configuration records nothing
  EXPECT_THROW(hbt::applyParams(ps, src), hbt::InputError);
  EXPECT_EQ(outer.params().size(), 4u);
}

#include "common/yaml_params.hpp"

TEST(YamlParams, FlattensNestedKeysAndNamesBadInput) {
  const auto src = hbt::parseYamlParams(
      "# comment\nvehicle:\n  mass_kg: 15160  # curb\n  name: bus\n  on: true\n"
      "ratios: [3.364, 1.909,\n   1.421]\n",
      "x.yaml");
  EXPECT_DOUBLE_EQ(std::get<double>(src.values.at("vehicle/mass_kg")), 15160.0);
  EXPECT_EQ(std::get<std::string>(src.values.at("vehicle/name")), "bus");
  EXPECT_TRUE(std::get<bool>(src.values.at("vehicle/on")));
  EXPECT_EQ(std::get<std::vector<double>>(src.values.at("ratios")).size(), 3u);
  expectInputError([] { hbt::parseYamlParams("ratios: [1, x]\n", "bad.yaml"); }, "bad.yaml", "ratios");
  EXPECT_THROW(hbt::parseYamlParams("a: [1, 2\n", "syntax.yaml"), hbt::InputError);
  EXPECT_THROW(hbt::readYamlParams("/nonexistent.yaml"), hbt::InputError);
}
