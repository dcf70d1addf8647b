// Robustness: a bad configuration raises InputError naming the file and the key; a diverging
// state raises ModelDivergence naming the element; no NaN reaches the outputs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "common/errors.hpp"
#include "support.hpp"
#include "../common/input_errors.hpp"

using namespace hbt::engine_1d;
using namespace hbt::engine_1d::test;

namespace {
std::string readFile(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// A copy of the config folder's four 1D-engine files in /tmp/engine_1d_test_<name>/, with
/// `from` replaced by `to` in `file`; returns the path of the copy's engine_1d.yaml.
std::string writeVariant(const std::string& from, const std::string& to, const std::string& name,
                         const std::string& file = "engine_1d.yaml") {
  const std::string dir = "/tmp/engine_1d_test_" + name;
  std::filesystem::create_directories(dir);
  for (const char* f : {"engine_1d.yaml", "engine_1d_cylinder.yaml", "engine_1d_turbo.yaml", "engine_map.yaml"}) {
    std::string s = readFile(repoRoot() + "/config/" + f);
    if (file == f) {
      const auto pos = s.find(from);
      EXPECT_NE(pos, std::string::npos) << from;
      s.replace(pos, from.size(), to);
    }
    std::ofstream(dir + "/" + f) << s;
  }
  return dir + "/engine_1d.yaml";
}
}  // namespace

TEST(Engine1DErrors, OutOfRangeValueNamesFileAndKey) {
  const std::string f = writeVariant("plenum_m3: 4.0e-3", "plenum_m3: -1.0", "range");
  hbt::testing::expectInputError([&] { Engine1DParams::load(repoRoot(), f); }, f, "engine_1d/intake/plenum_m3");
}

TEST(Engine1DErrors, UnknownKeyAndBadSolverAreRejected) {
  const std::string f = writeVariant("  firing_order:", "  tvd_mesh_factr: 3\n  firing_order:", "typo");
  hbt::testing::expectInputError([&] { Engine1DParams::load(repoRoot(), f); }, f, "engine_1d/tvd_mesh_factr");
  const std::string g = writeVariant("solver: fsm", "solver: lax", "solver");
  hbt::testing::expectInputError([&] { Engine1DParams::load(repoRoot(), g); }, g, "engine_1d/solver");
  const std::string h = writeVariant("cd_normal: [0.72, 0.70, 0.67", "cd_normal: [0.70, 0.67", "cd");
  EXPECT_THROW(Engine1DParams::load(repoRoot(), h), hbt::InputError);
  // implicit one-cell pipes are solved with their implicit volume: without it, an error
  const std::string i = writeVariant("implicit_volumes: true", "implicit_volumes: false", "implicit");
  hbt::testing::expectInputError([&] { Engine1DParams::load(repoRoot(), i); }, i,
                                 "engine_1d/numerics/implicit_one_cell_pipes");
}

TEST(Engine1DErrors, CylinderCountFiringOrderAndBanksAreCheckedAtLoad) {
  struct Case {
    const char *from, *to, *name, *key, *says;
  };
  const char* fo = "firing_order: [1, 5, 3, 6, 2, 4]";
  const char* eb = "exhaust_bank: [1, 1, 1, 2, 2, 2]";
  const Case cases[] = {
      {"cylinders: 6", "cylinders: 13", "cyl_13", "engine_1d/cylinders", "range"},
      {"cylinders: 6", "cylinders: 0", "cyl_0", "engine_1d/cylinders", "range"},
      {"cylinders: 6", "cylinders: 6.5", "cyl_frac", "engine_1d/cylinders", "integer"},
      {"cylinders: 6", "cylinders: 5", "cyl_5", "engine_1d/firing_order", "permutation of 1..5"},
      {fo, "firing_order: [1, 5, 3, 6, 2]", "fo_short", "engine_1d/firing_order", "permutation"},
      {fo, "firing_order: [1, 5, 3, 6, 2, 2]", "fo_twice", "engine_1d/firing_order", "permutation"},
      {fo, "firing_order: [1, 5, 3, 6, 2, 4.5]", "fo_frac", "engine_1d/firing_order", "permutation"},
      {eb, "exhaust_bank: [1, 1, 1, 2, 2]", "eb_short", "engine_1d/exhaust_bank", "6 values, got 5"},
      {eb, "exhaust_bank: [1, 1, 1, 2, 2, 3]", "eb_3", "engine_1d/exhaust_bank", "range"},
      {eb, "exhaust_bank: [1, 1, 1.5, 2, 2, 2]", "eb_frac", "engine_1d/exhaust_bank", "cylinder 3"},
      {eb, "exhaust_bank: [1, 1, 1, 1, 1, 1]", "eb_unfed", "engine_1d/exhaust_bank", "entry 2 has no cylinder"},
  };
  for (const Case& c : cases) {
    const std::string f = writeVariant(c.from, c.to, c.name);
    SCOPED_TRACE(c.to);
    const std::string m = hbt::testing::expectInputError([&] { Engine1DParams::load(repoRoot(), f); }, f, c.key);
    EXPECT_NE(m.find(c.says), std::string::npos) << m;
  }
  // parameters filled in code are checked by the engine before it builds anything
  Engine1DParams p = defaultParams();
  p.engine.cylinders = 4;
  hbt::testing::expectInputError([&] { Engine1D e(p, repoRoot()); }, p.engine_source, "engine_1d/firing_order");
}

TEST(Engine1DErrors, SubFilesAreReadBesideTheEngineFile) {
  // a copy of the config folder (launch argument config:=DIR) uses its own cylinder file: a
  // broken value there is reported with the copy's path, never replaced by the package's file
  const std::string f = writeVariant("bore_m: 0.104", "bore_m: -0.104", "subfile", "engine_1d_cylinder.yaml");
  const std::string cyl = f.substr(0, f.find_last_of('/')) + "/engine_1d_cylinder.yaml";
  hbt::testing::expectInputError([&] { Engine1DParams::load(repoRoot(), f); }, cyl, "cylinder/geometry/bore_m");
  // and an intact copy loads to exactly the package's parameters
  const std::string g = writeVariant("bore_m: 0.104", "bore_m: 0.104", "subfile_same", "engine_1d_cylinder.yaml");
  EXPECT_EQ(Engine1DParams::load(repoRoot(), g).cylinder.geometry.bore_m, defaultParams().cylinder.geometry.bore_m);
}

TEST(Engine1DErrors, DivergenceNamesTheElement) {
  Engine1DParams p = defaultParams();
  Engine1D e(p, repoRoot());
  e.reset(1400.0 * kRpm, 500.0);
  run(e, 1400.0, 500.0, 0.2);
  // impose a non-physical back pressure: the downpipe empties backwards into the turbine outlet
  // until a cell or a volume goes non-physical, or the step collapses
  Engine1DInputs in;
  in.speed_rad_s = 1400.0 * kRpm;
  in.torque_request_Nm = 500.0;
  in.back_pressure_Pa = 1e9;
  try {
    for (int i = 0; i < 200; ++i) {
      const Engine1DOutputs& o = e.step(0.01, in);
      ASSERT_TRUE(std::isfinite(o.brake_torque_Nm));
    }
    FAIL() << "no ModelDivergence";
  } catch (const hbt::ModelDivergence& d) {
    const std::string w = d.what();
    std::printf("divergence: %s\n", w.c_str());
    const bool named = w.find("pipe ") != std::string::npos || w.find("volume ") != std::string::npos ||
                       w.find("cylinder ") != std::string::npos || w.find("turbine") != std::string::npos ||
                       w.find("downpipe") != std::string::npos || w.find("compressor") != std::string::npos ||
                       w.find("turbocharger") != std::string::npos;
    EXPECT_TRUE(named) << w;
  }
}

TEST(Engine1DErrors, NonFiniteInputIsRejected) {
  Engine1D e(defaultParams(), repoRoot());
  e.reset(1400.0 * kRpm, 300.0);
  Engine1DInputs in;
  in.speed_rad_s = std::nan("");
  in.torque_request_Nm = 300.0;
  EXPECT_THROW(e.step(0.01, in), hbt::ModelDivergence);
}
