// VECTO engine file readers: the reference files parse to the expected SI values; every kind of
// bad input raises hbt::InputError naming the file and the column/key.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "engine_map/vecto_engine_files.hpp"
#include "../common/input_errors.hpp"

using namespace hbt;
using namespace hbt::engine_map;
using hbt::testing::expectInputError;
using hbt::testing::KeyMatch;

namespace {

const std::string kDir = "config/data/engine/generic_primary_bus_7.7l_200kW/";

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

const char* kVmapHeader = "engine speed [rpm],torque [Nm],fuel consumption [g/h]\n";
const char* kVfldHeader = "engine speed [rpm],full load torque [Nm],motoring torque [Nm]\n";

}  // namespace

TEST(VectoFiles, ReferenceFullLoadCurveInSI) {
  const auto c = readFullLoadCurve(kDir + "FullLoad.vfld");
  ASSERT_EQ(c.speed_rad_s.size(), 12u);
  EXPECT_NEAR(c.speed_rad_s.front(), 600.0 * 2.0 * M_PI / 60.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.full_load_Nm[3], 1092.03);
  EXPECT_DOUBLE_EQ(c.motoring_Nm.back(), -132.07);
}

TEST(VectoFiles, ReferenceFuelMapInSI) {
  const auto m = readFuelMap(kDir + "FCMap.vmap");
  ASSERT_EQ(m.fuel_kg_s.size(), 146u);
  // Row 2: 600 rpm, 0 Nm, 580.60 g/h.
  EXPECT_NEAR(m.speed_rad_s[1], 62.8318530718, 1e-9);
  EXPECT_DOUBLE_EQ(m.torque_Nm[1], 0.0);
  EXPECT_NEAR(m.fuel_kg_s[1], 580.60e-3 / 3600.0, 1e-15);
  EXPECT_DOUBLE_EQ(m.fuel_kg_s[0], 0.0);  // motoring row
}

TEST(VectoFiles, Pt1TableInSI) {
  const auto t = readPt1Table("config/data/vehicle/declaration_2015/PT1.csv");
  EXPECT_NEAR(t(units::rpmToRadps(1000.0)), 0.58, 1e-12);
  EXPECT_NEAR(t(units::rpmToRadps(900.0)), 0.525, 1e-12);
}

TEST(VectoFiles, MissingFileNamesFile) {
  expectInputError([] { readFuelMap("/nonexistent/FCMap.vmap"); }, "/nonexistent/FCMap.vmap", "file",
                   KeyMatch::kContains);
  expectInputError([] { readFullLoadCurve("/nonexistent/x.vfld"); }, "/nonexistent/x.vfld", "file",
                   KeyMatch::kContains);
}

TEST(VectoFiles, NanFuelNamesFileAndColumn) {
  const auto p = writeTemp("nan.vmap", std::string(kVmapHeader) + "600,0,580\n600,100,nan\n800,0,700\n");
  expectInputError([&] { readFuelMap(p); }, p, normaliseColumnName("fuel consumption"),
                   KeyMatch::kContains);
}

TEST(VectoFiles, MalformedCellNamesColumn) {
  const auto p = writeTemp("bad.vmap", std::string(kVmapHeader) + "600,0,580\n600,1O0,900\n800,0,700\n");
  expectInputError([&] { readFuelMap(p); }, p, "torque", KeyMatch::kContains);
}

TEST(VectoFiles, TruncatedRowNamesLine) {
  const auto p = writeTemp("trunc.vmap", std::string(kVmapHeader) + "600,0,580\n600,100\n800,0,700\n");
  expectInputError([&] { readFuelMap(p); }, p, "line 3", KeyMatch::kContains);
}

TEST(VectoFiles, MissingColumnNamesColumn) {
  const auto p = writeTemp("nocol.vmap", "engine speed [rpm],torque [Nm],fuel [g/h]\n600,0,1\n600,5,2\n700,0,3\n");
  expectInputError([&] { readFuelMap(p); }, p, "fuel consumption", KeyMatch::kContains);
}

TEST(VectoFiles, NegativeFuelAndDuplicatePointRejected) {
  const auto p1 = writeTemp("neg.vmap", std::string(kVmapHeader) + "600,0,580\n600,100,-1\n800,0,700\n");
  expectInputError([&] { readFuelMap(p1); }, p1, "fuel consumption", KeyMatch::kContains);
  const auto p2 = writeTemp("dup.vmap", std::string(kVmapHeader) + "600,0,580\n800,0,700\n600,0,590\n");
  expectInputError([&] { readFuelMap(p2); }, p2, "torque", KeyMatch::kContains);
}

TEST(VectoFiles, FullLoadCurveChecks) {
  const auto p1 = writeTemp("mot.vfld", std::string(kVfldHeader) + "600,500,-40\n800,700,10\n");
  expectInputError([&] { readFullLoadCurve(p1); }, p1, "motoring torque", KeyMatch::kContains);
  const auto p2 = writeTemp("order.vfld", std::string(kVfldHeader) + "800,500,-40\n600,700,-50\n");
  expectInputError([&] { readFullLoadCurve(p2); }, p2, "engine speed", KeyMatch::kContains);
  const auto p3 = writeTemp("nan.vfld", std::string(kVfldHeader) + "600,500,-40\n800,inf,-50\n");
  expectInputError([&] { readFullLoadCurve(p3); }, p3, normaliseColumnName("full load torque"),
                   KeyMatch::kContains);
  const auto p4 = writeTemp("trunc.vfld", std::string(kVfldHeader) + "600,500,-40\n800,700\n");
  expectInputError([&] { readFullLoadCurve(p4); }, p4, "line 3", KeyMatch::kContains);
}

TEST(VectoFiles, Pt1NegativeRejected) {
  const auto p = writeTemp("pt1.csv", "rpm,PT1\n400,0\n800,-0.1\n");
  expectInputError([&] { readPt1Table(p); }, p, "PT1", KeyMatch::kContains);
}
