// Engine-out NOx map of the map engine (nox_map.hpp, config engine_map.yaml nox_map_file):
// the table's values at its grid points (read independently from the CSV), bilinear between
// them, clamped outside, zero in a fuel cut, and bad files rejected naming file and key.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "engine_map/map_engine.hpp"
#include "../common/input_errors.hpp"

using namespace hbt;
using namespace hbt::engine_map;

namespace {
constexpr double kRpm = units::kPi / 30.0;
const char* kMap = "config/data/engine/nox_map_1d.csv";

const MapEngine& engine() {
  static const MapEngine e{MapEngineParams{}};
  return e;
}

// EI [kg/kg] of the CSV at (rpm, load), from the raw file (exact grid match).
double rawEi(double rpm, double load) {
  const auto t = CsvTable::read(kMap);
  const auto& n = t.column("speed_rpm");
  const auto& l = t.column("load");
  const auto& ei = t.column("ei_nox_g_per_kg");
  for (std::size_t i = 0; i < t.rows(); ++i)
    if (std::fabs(n[i] - rpm) < 1e-6 && std::fabs(l[i] - load) < 1e-6) return ei[i] * 1e-3;
  ADD_FAILURE() << "no grid point " << rpm << " rpm load " << load;
  return NAN;
}

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string p = "/tmp/hbt_test_nox_map_" + name + ".csv";
  std::ofstream(p) << text;
  return p;
}
}  // namespace

TEST(MapEngineNoxMap, DefaultConfigNamesTheMapAndEveryGridPointIsReproduced) {
  EXPECT_EQ(MapEngineParams{}.nox_map_file, kMap);
  const auto& e = engine();
  const auto t = CsvTable::read(kMap);
  const auto& n = t.column("speed_rpm");
  const auto& l = t.column("load");
  const auto& ei = t.column("ei_nox_g_per_kg");
  ASSERT_GE(t.rows(), 4u);
  for (std::size_t i = 0; i < t.rows(); ++i) {
    const double w = n[i] * kRpm, T = l[i] * e.fullLoadTorque(w);
    EXPECT_NEAR(e.noxEmissionIndex(w, T), ei[i] * 1e-3, 1e-12 * ei[i]) << n[i] << " rpm load " << l[i];
  }
}

TEST(MapEngineNoxMap, StepGivesIndexTimesFuelBilinearClampedAndZeroInFuelCut) {
  MapEngine e{MapEngineParams{}};
  // A grid point in steady state: NOx flow = EI(grid) x the engine's own fuel flow.
  const double w = 1550.0 * kRpm, T = 0.55 * e.fullLoadTorque(w);
  e.reset(w, T);
  MapEngineInputs in{w, T, 298.15, units::kStandardAtmosphere_Pa, true};
  const MapEngineOutputs& o = e.step(0.01, in);
  ASSERT_NEAR(o.brake_torque_Nm, T, 1e-9);
  EXPECT_NEAR(o.gas.nox_mass_flow_kg_s, rawEi(1550.0, 0.55) * o.fuel_mass_flow_kg_s, 1e-15);
  EXPECT_GT(o.gas.nox_mass_flow_kg_s, 0.0);
  // Bilinear: the centre of a grid cell is the mean of its four corners.
  const double wc = 0.5 * (1550.0 + 1775.0) * kRpm;
  const double Tc = 0.5 * (0.55 + 0.595) * e.fullLoadTorque(wc);
  const double mean4 = 0.25 * (rawEi(1550.0, 0.55) + rawEi(1550.0, 0.595) + rawEi(1775.0, 0.55) +
                               rawEi(1775.0, 0.595));
  EXPECT_NEAR(e.noxEmissionIndex(wc, Tc), mean4, 1e-12);
  // Clamped outside: below the lowest speed / load and above the highest speed = edge values.
  EXPECT_NEAR(e.noxEmissionIndex(500.0 * kRpm, 0.55 * e.fullLoadTorque(500.0 * kRpm)), rawEi(650.0, 0.55), 1e-12);
  EXPECT_NEAR(e.noxEmissionIndex(1550.0 * kRpm, 0.02 * e.fullLoadTorque(w)), rawEi(1550.0, 0.1), 1e-12);
  EXPECT_NEAR(e.noxEmissionIndex(2600.0 * kRpm, 1.0 * e.fullLoadTorque(2600.0 * kRpm)), rawEi(2450.0, 1.0), 1e-12);
  // Motoring (fuel cut): no fuel, no NOx.
  in.torque_request_Nm = e.motoringTorque(w) - 10.0;
  const MapEngineOutputs& m = e.step(0.01, in);
  EXPECT_EQ(m.fuel_mass_flow_kg_s, 0.0);
  EXPECT_EQ(m.gas.nox_mass_flow_kg_s, 0.0);
}

TEST(MapEngineNoxMap, BadFileNamesFileAndKey) {
  auto expectBad = [](const std::string& path, const std::string& what) {
    SCOPED_TRACE(what);
    MapEngineParams p;
    p.nox_map_file = path;
    hbt::testing::expectInputError([&] { MapEngine e(p); }, path, "nox_map_file");
  };
  expectBad("/nonexistent/nox.csv", "missing file");
  expectBad(writeTemp("nocol", "speed_rpm,load,nox\n1000,0.5,1\n2000,0.5,1\n1000,1,1\n2000,1,1\n"),
            "missing column");
  expectBad(writeTemp("hole", "speed_rpm,load,ei_nox_g_per_kg\n1000,0.5,30\n2000,0.5,30\n1000,1,30\n"),
            "incomplete grid");
  expectBad(writeTemp("dup", "speed_rpm,load,ei_nox_g_per_kg\n1000,0.5,30\n2000,0.5,30\n1000,1,30\n"
                             "1000,1,30\n2000,1,30\n3000,1,30\n"),
            "duplicate point");
  expectBad(writeTemp("neg", "speed_rpm,load,ei_nox_g_per_kg\n1000,0.5,30\n2000,0.5,-1\n1000,1,30\n2000,1,30\n"),
            "negative index");
  expectBad(writeTemp("nan", "speed_rpm,load,ei_nox_g_per_kg\n1000,0.5,30\n2000,0.5,nan\n1000,1,30\n2000,1,30\n"),
            "NaN");
}
