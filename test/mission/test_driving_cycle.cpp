// Reader of VECTO .vdri cycles and .vacc limits, road load, parameter binding + mission.yaml.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/params.hpp"
#include "mission/driving_cycle.hpp"
#include "mission/mission_preprocessor.hpp"
#include "mission/vehicle_limits.hpp"
#include "../common/input_errors.hpp"

using namespace hbt::mission;
using hbt::testing::expectInputError;

namespace {

const std::string kUrban = "config/data/cycles/vecto/Urban.vdri";
const std::string kVacc = "config/data/vehicle/citybus_P1_hybrid_48V/Bus.vacc";

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

const std::string kHeader = "<s>,<v>,<grad>,<stop>\n";

}  // namespace

TEST(Vdri, UrbanMatchesFileFacts) {
  const DrivingCycle c = readVdri(kUrban);
  // Facts stated in config/data/cycles/README.txt, cross-checked with the raw CSV.
  const hbt::CsvTable raw = hbt::CsvTable::read(kUrban);
  EXPECT_EQ(c.size(), raw.rows());
  EXPECT_DOUBLE_EQ(c.endDistance_m(), 39551.0);
  EXPECT_EQ(c.stopCount(), 121u);
  EXPECT_NEAR(c.totalStopTime_s(), 2782.2, 1e-9);
  EXPECT_NEAR(c.target_speed_m_s[1], 23.7 / 3.6, 1e-12);
  // First row is a 12.6 s stop; the drive-off target is the next row's (23.7 km/h).
  EXPECT_TRUE(c.isStopPoint(0));
  EXPECT_NEAR(c.intervalTarget_m_s(0), 23.7 / 3.6, 1e-12);
  // Rows: (0, grad -7), (1, -6.9), (2, -7): left-sample gradient, altitude integrated by hand.
  EXPECT_DOUBLE_EQ(c.gradeAt(0.5), -7.0);
  EXPECT_DOUBLE_EQ(c.gradeAt(1.0), -6.9);
  EXPECT_NEAR(c.altitudeAt(1.0), -0.07, 1e-12);
  EXPECT_NEAR(c.altitudeAt(2.0), -0.07 - 0.069, 1e-12);
  EXPECT_NEAR(c.altitudeAt(1.5), -0.07 - 0.0345, 1e-12);
  // Altitude closes: sum of grad*ds over the raw file.
  const auto& s = raw.column("s");
  const auto& g = raw.column("grad");
  double z = 0.0;
  for (std::size_t k = 1; k < raw.rows(); ++k) z += (s[k] - s[k - 1]) * g[k - 1] / 100.0;
  EXPECT_NEAR(c.altitudeAt(39551.0), z, 1e-6);
}

TEST(Vdri, ConsecutiveStopsDriveOffWithNextPositiveTarget) {
  const DrivingCycle c = makeCycle("mem", {0, 100, 130, 400}, {30, 0, 0, 50}, {0, 0, 0, 0},
                                   {0, 20, 5, 0});
  EXPECT_NEAR(c.intervalTarget_m_s(1), 50 / 3.6, 1e-12);
  EXPECT_NEAR(c.intervalTarget_m_s(2), 50 / 3.6, 1e-12);
  EXPECT_NEAR(c.intervalTarget_m_s(0), 30 / 3.6, 1e-12);
  EXPECT_EQ(c.stopCount(), 2u);
  EXPECT_EQ(c.intervalIndex(99.9), 0u);
  EXPECT_EQ(c.intervalIndex(100.0), 1u);
  EXPECT_EQ(c.intervalIndex(1e6), 3u);
}

TEST(Vdri, MissingFile) {
  expectInputError([] { readVdri("config/data/cycles/vecto/NoSuch.vdri"); },
                   "config/data/cycles/vecto/NoSuch.vdri", "(file)");
}

TEST(Vdri, TruncatedRow) {
  const auto p = writeTemp("trunc.vdri", kHeader + "0,0,0,5\n10,30,0.5,0\n20,30\n");
  expectInputError([&] { readVdri(p); }, p, "line 4");
}

TEST(Vdri, NaNCell) {
  const auto p = writeTemp("nan.vdri", kHeader + "0,0,0,5\n10,nan,0.5,0\n20,30,0,0\n");
  const std::string msg = expectInputError([&] { readVdri(p); }, p, "v");
  EXPECT_NE(msg.find("line 3"), std::string::npos) << msg;
}

TEST(Vdri, NegativeSpeedNamesColumnAndLine) {
  const auto p = writeTemp("neg.vdri", "# comment line\n" + kHeader +
                                           "0,0,0,5\n10,30,0.5,0\n20,-3,0,0\n30,0,0,1\n");
  const std::string msg = expectInputError([&] { readVdri(p); }, p, "v");
  EXPECT_NE(msg.find("line 5"), std::string::npos) << msg;  // file line, comment counted
}

TEST(Vdri, NegativeStopTime) {
  const auto p = writeTemp("negstop.vdri", kHeader + "0,0,0,-5\n10,30,0.5,0\n");
  expectInputError([&] { readVdri(p); }, p, "stop");
}

TEST(Vdri, DistanceMustIncrease) {
  const auto p = writeTemp("dist.vdri", kHeader + "0,0,0,5\n10,30,0,0\n10,20,0,0\n30,0,0,1\n");
  const std::string msg = expectInputError([&] { readVdri(p); }, p, "s");
  EXPECT_NE(msg.find("line 4"), std::string::npos) << msg;
  const auto q = writeTemp("dist2.vdri", kHeader + "0,0,0,5\n10,30,0,0\n5,20,0,0\n");
  expectInputError([&] { readVdri(q); }, q, "s");
}

TEST(Vdri, InsaneGradeAndStopWithSpeed) {
  const auto p = writeTemp("grad.vdri", kHeader + "0,0,0,5\n10,30,45,0\n20,0,0,1\n");
  expectInputError([&] { readVdri(p); }, p, "grad");
  const auto q = writeTemp("stopv.vdri", kHeader + "0,0,0,5\n10,30,0,4\n20,0,0,1\n");
  expectInputError([&] { readVdri(q); }, q, "stop");
}

TEST(Vdri, MissingColumnAndTooShort) {
  const auto p = writeTemp("nocol.vdri", "<s>,<v>,<grad>\n0,0,0\n10,30,0\n");
  expectInputError([&] { readVdri(p); }, p, "stop");
  const auto q = writeTemp("short.vdri", kHeader + "0,0,0,5\n");
  expectInputError([&] { readVdri(q); }, q, "s");
}

TEST(Vacc, BusTableInterpolation) {
  const AccelerationLimits a = AccelerationLimits::readVacc(kVacc);
  // Rows of Bus.vacc: (0, .88, -.94) (10, 1, -.94) (20, 1, -.88) (30, .97, -.81)
  // (50, .63, -.66) (58, .50, -.52) ... (120, .39, -.50); km/h -> m/s.
  EXPECT_NEAR(a.maxAccel_m_s2(0.0), 0.88, 1e-12);
  EXPECT_NEAR(a.maxAccel_m_s2(5.0 / 3.6), 0.94, 1e-12);
  EXPECT_NEAR(a.maxAccel_m_s2(25.0 / 3.6), 0.985, 1e-12);
  EXPECT_NEAR(a.maxDecel_m_s2(55.0 / 3.6), -0.66 + 5.0 / 8.0 * 0.14, 1e-12);
  EXPECT_NEAR(a.maxDecel_m_s2(200.0 / 3.6), -0.50, 1e-12);  // constant beyond the table
}

TEST(Vacc, RejectsWrongSigns) {
  const auto p = writeTemp("bad.vacc", "v [km/h],acc [m/s2],dec [m/s2]\n0,1,-1\n50,1,0.5\n");
  expectInputError([&] { AccelerationLimits::readVacc(p); }, p, "dec");
  const auto q = writeTemp("bad2.vacc", "v [km/h],acc [m/s2],dec [m/s2]\n0,1,-1\n50,-1,-1\n");
  expectInputError([&] { AccelerationLimits::readVacc(q); }, q, "acc");
}

TEST(RoadLoad, HandCalculation) {
  RoadLoadParams p;  // defaults: 16660 kg, 349 kg, RRC 0.006, CdA 4.25, rho 1.188
  const RoadLoad r(p);
  const double flat = 16660 * 9.81 * 0.006 + 0.5 * 1.188 * 4.25 * 100.0;
  EXPECT_NEAR(r.resistance_N(10.0, 0.0), flat, 1e-9);
  const double a = std::atan(0.05);
  EXPECT_NEAR(r.resistance_N(0.0, 5.0), 16660 * 9.81 * (0.006 * std::cos(a) + std::sin(a)), 1e-9);
  EXPECT_NEAR(r.coastingAccel_m_s2(10.0, 0.0), -flat / 17009.0, 1e-12);
  EXPECT_GT(r.coastingAccel_m_s2(5.0, -5.0), 0.0);  // steep downhill accelerates the bus
  EXPECT_NEAR(r.powerLimitedAccel_m_s2(10.0, 0.0), (16000.0 - flat) / 17009.0, 1e-12);
  p.max_wheel_power_W = 0.0;
  EXPECT_TRUE(std::isinf(RoadLoad(p).powerLimitedAccel_m_s2(10.0, 0.0)));
}

TEST(Params, DeclareApplyAndRejectUnknown) {
  MissionParams m;
  hbt::ParamSet ps;
  m.declare(ps);
  hbt::ParamSource src;
  src.file = "test.yaml";
  src.set("dt_s", 0.05);
  src.set("vehicle/mass_kg", 18000.0);
  src.set("driver/lac_enabled", false);
  hbt::applyParams(ps, src);
  EXPECT_DOUBLE_EQ(m.dt_s, 0.05);
  EXPECT_DOUBLE_EQ(m.vehicle.mass_kg, 18000.0);
  EXPECT_FALSE(m.driver.lac_enabled);
  src.set("vehicle/mass_kgg", 1.0);
  expectInputError([&] { hbt::applyParams(ps, src); }, "test.yaml", "vehicle/mass_kgg");
  hbt::ParamSource bad;
  bad.file = "b.yaml";
  bad.set("dt_s", -1.0);
  expectInputError([&] { hbt::applyParams(ps, bad); }, "b.yaml", "dt_s");
}

// config/mission.yaml must hold exactly the declared keys (2-level YAML "group:\n  key: value").
TEST(Params, MissionYamlKeysMatchDeclare) {
  std::ifstream in("config/mission.yaml");
  ASSERT_TRUE(in) << "config/mission.yaml missing";
  hbt::ParamSource src;
  src.file = "config/mission.yaml";
  std::string line, group;
  while (std::getline(in, line)) {
    const auto hash = line.find('#');
    std::string body = line.substr(0, hash);
    while (!body.empty() && (body.back() == ' ' || body.back() == '\r')) body.pop_back();
    if (body.find_first_not_of(' ') == std::string::npos) continue;
    const bool indented = body[0] == ' ';
    const auto colon = body.find(':');
    ASSERT_NE(colon, std::string::npos) << line;
    std::string key = body.substr(body.find_first_not_of(' '), colon - body.find_first_not_of(' '));
    std::string val = body.substr(colon + 1);
    val.erase(0, val.find_first_not_of(' '));
    if (!indented) group.clear();
    if (val.empty()) { group = key; continue; }
    const std::string full = indented ? group + "/" + key : key;
    if (val == "true" || val == "false") src.set(full, val == "true");
    else if (val.front() == '"') src.set(full, val.substr(1, val.size() - 2));
    else src.set(full, std::stod(val));
  }
  MissionParams m;
  hbt::ParamSet ps;
  m.declare(ps);
  EXPECT_NO_THROW(hbt::applyParams(ps, src));               // no unknown key, all in range
  EXPECT_EQ(src.values.size(), ps.entries().size());        // every declared key documented
  const MissionParams d;
  EXPECT_EQ(m.cycle_file, d.cycle_file);                    // YAML restates the defaults
  EXPECT_DOUBLE_EQ(m.vehicle.mass_kg, d.vehicle.mass_kg);
  EXPECT_DOUBLE_EQ(m.driver.overspeed_m_s, d.driver.overspeed_m_s);
}
