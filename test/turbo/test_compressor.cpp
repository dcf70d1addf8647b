// Compressor map and model: measured points reproduced exactly, validation errors name file and
// column, similarity-law extrapolation (continuity, the law itself, zero speed), monotonicity
// and no NaN over a wide sweep, outlet temperature against the isentropic formula.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "turbo/compressor.hpp"
#include "turbo_test_util.hpp"
#include "../common/input_errors.hpp"

using namespace hbt::turbo;
using hbt::turbo::test::dataPath;

namespace {

const std::string kScania = "scania_di09_enginetoolbox/compressor_map_SAE_lowflow_extrapolated.csv";
const std::string kSample = "turbotools_sample/SampleCMAP_compressor.csv";
const CompressorMapFormat kSampleFmt{"RPM", "WC", "PRC", "ETAC"};

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string p = ::testing::TempDir() + name;
  std::ofstream(p) << text;
  return p;
}

// Reading the map at `path` is an InputError naming it and `key`.
void expectBadMapFile(const std::string& path, const std::string& key) {
  hbt::testing::expectInputError([&] { CompressorMap::read(path); }, path, key);
}

const char* kHead = "speed [rpm],mass_flow [kg/s],pressure_ratio [-],efficiency [-]\n";

}  // namespace

TEST(CompressorMap, ReproducesMeasuredPointsExactly) {
  struct Case { std::string file; CompressorMapFormat fmt; };
  for (const auto& c : {Case{kScania, {}}, Case{kSample, kSampleFmt}}) {
    const auto map = CompressorMap::read(dataPath(c.file), c.fmt);
    const auto t = hbt::CsvTable::read(dataPath(c.file));
    const auto &n = t.column(c.fmt.col_speed), &m = t.column(c.fmt.col_flow),
               &pr = t.column(c.fmt.col_pr), &eta = t.column(c.fmt.col_eff);
    for (std::size_t r = 0; r < t.rows(); ++r) {
      const auto p = map.atPressureRatio(n[r], pr[r]);
      EXPECT_NEAR(p.flow_kg_s, m[r], 1e-12) << c.file << " row " << r;
      EXPECT_NEAR(p.eta, std::max(eta[r], 0.30), 1e-12) << c.file << " row " << r;
      EXPECT_EQ(p.region, CompressorMap::kInside);
    }
  }
}

TEST(CompressorMap, ScaledModelReproducesScaledPoints) {
  const auto raw = CompressorMap::read(dataPath(kScania));
  const double f = 0.8;
  CompressorMap sc = raw;
  sc.scale(f);
  const Compressor comp(sc, 100000.0, 298.0);
  const auto t = hbt::CsvTable::read(dataPath(kScania));
  for (std::size_t r = 0; r < t.rows(); r += 5) {
    const double w = t.column("speed")[r] / std::sqrt(f) * 2.0 * M_PI / 60.0;
    // inlet at 2 x p_ref, T = T_ref: physical flow = 2 x corrected flow
    const auto s = comp.evaluate(200000.0, 298.0, 200000.0 * t.column("pressure_ratio")[r], w);
    EXPECT_NEAR(s.mass_flow_kg_s, 2.0 * f * t.column("mass_flow")[r], 1e-11);
  }
}

TEST(CompressorMap, ValidationErrorsNameFileAndColumn) {
  expectBadMapFile(writeTemp("c_mono.csv", std::string(kHead) +
                                               "1000,0.1,1.2,0.7\n1000,0.2,1.3,0.7\n"
                                               "2000,0.2,1.5,0.7\n2000,0.3,1.4,0.7\n"),
                   "pressure_ratio");
  expectBadMapFile(writeTemp("c_eta.csv", std::string(kHead) +
                                              "1000,0.1,1.3,0.7\n1000,0.2,1.2,1.2\n"
                                              "2000,0.2,1.5,0.7\n2000,0.3,1.4,0.7\n"),
                   "efficiency");
  expectBadMapFile(writeTemp("c_neg.csv", std::string(kHead) +
                                              "1000,-0.1,1.3,0.7\n1000,0.2,1.2,0.7\n"
                                              "2000,0.2,1.5,0.7\n2000,0.3,1.4,0.7\n"),
                   "mass_flow");
  expectBadMapFile(writeTemp("c_split.csv", std::string(kHead) +
                                                "1000,0.1,1.3,0.7\n1000,0.2,1.2,0.7\n"
                                                "2000,0.2,1.5,0.7\n2000,0.3,1.4,0.7\n"
                                                "1000,0.3,1.1,0.7\n1000,0.4,1.05,0.7\n"),
                   "speed");
  expectBadMapFile(writeTemp("c_col.csv", "speed,flow,pressure_ratio,efficiency\n1,2,3,0.5\n"),
                   "mass_flow");
}

TEST(CompressorMap, SimilarityLawBelowLowestLine) {
  const auto map = CompressorMap::read(dataPath(kScania));
  const auto& l0 = map.lines().front();
  const double k = 0.4 / 1.4;
  for (double s : {0.75, 0.5, 0.1}) {
    for (std::size_t j = 0; j < l0.flow.size(); ++j) {
      // similar point: flow ∝ N, isentropic head ∝ N², same efficiency
      const double pr = std::pow(1.0 + (std::pow(l0.pr[j], k) - 1.0) * s * s, 1.0 / k);
      const auto p = map.atPressureRatio(s * l0.speed_rpm, pr);
      EXPECT_NEAR(p.flow_kg_s, s * l0.flow[j], 1e-9 * l0.flow[j]) << s << " " << j;
      EXPECT_NEAR(p.eta, std::max(l0.eta[j], 0.30), 1e-9);
      EXPECT_TRUE(p.region & CompressorMap::kBelowLines);
    }
  }
}

TEST(CompressorMap, ContinuousAtFirstAndLastMeasuredLines) {
  const auto map = CompressorMap::read(dataPath(kScania));
  for (const auto* l : {&map.lines().front(), &map.lines().back()}) {
    for (double pr = 0.8; pr < 1.3 * l->pr.front(); pr += 0.01) {
      const auto a = map.atPressureRatio(l->speed_rpm * (1.0 - 1e-7), pr);
      const auto b = map.atPressureRatio(l->speed_rpm * (1.0 + 1e-7), pr);
      EXPECT_NEAR(a.flow_kg_s, b.flow_kg_s, 2e-4) << l->speed_rpm << " " << pr;
      EXPECT_NEAR(a.eta, b.eta, 1e-5);
      EXPECT_NEAR(a.work, b.work, 1e-5);
    }
  }
}

TEST(CompressorMap, WideSweepNoNanAndMonotonic) {
  for (const auto& [file, fmt] : {std::pair{kScania, CompressorMapFormat{}},
                                 std::pair{kSample, kSampleFmt}}) {
    const auto map = CompressorMap::read(dataPath(file), fmt);
    const double nmax = map.lines().back().speed_rpm;
    const int NN = 160, NP = 400;
    std::vector<double> prev_n(NP + 1, -1.0);
    for (int i = 0; i <= NN; ++i) {
      const double n = 1.6 * nmax * i / NN;
      double prev_pr = 1e300;
      for (int j = 0; j <= NP; ++j) {
        const double pr = 0.2 + 5.8 * j / NP;
        const auto p = map.atPressureRatio(n, pr);
        ASSERT_TRUE(std::isfinite(p.flow_kg_s) && std::isfinite(p.eta) && std::isfinite(p.work))
            << file << " N=" << n << " PR=" << pr;
        ASSERT_GE(p.flow_kg_s, 0.0);
        ASSERT_GE(p.work, 0.0);
        ASSERT_GE(p.eta, 0.30 - 1e-15);
        ASSERT_LT(p.eta, 1.0);
        EXPECT_LE(p.flow_kg_s, prev_pr + 1e-12) << file << " not falling with PR, N=" << n
                                                << " PR=" << pr;
        EXPECT_GE(p.flow_kg_s, prev_n[j] - 1e-12) << file << " not rising with N, N=" << n
                                                  << " PR=" << pr;
        prev_pr = p.flow_kg_s;
        prev_n[j] = p.flow_kg_s;
      }
    }
  }
}

TEST(CompressorMap, ZeroSpeedActsAsOrificeAndSurgeSideClosesToZero) {
  const auto map = CompressorMap::read(dataPath(kScania));
  // stationary wheel: no flow against a pressure rise, orifice law m ∝ √(1 − Π) for a drop
  EXPECT_EQ(map.atPressureRatio(0.0, 1.05).flow_kg_s, 0.0);
  const double pistar = std::pow(2.0 / 2.4, 1.4 / 0.4);
  const double K = 0.5 * 0.483128 / std::sqrt(1.0 - pistar);  // 0.5 × max map flow
  for (double pr : {0.99, 0.9, 0.7}) {
    const auto p = map.atPressureRatio(0.0, pr);
    EXPECT_NEAR(p.flow_kg_s, K * std::sqrt(1.0 - pr), 1e-12);
    EXPECT_EQ(p.work, 0.0);  // isenthalpic throttle
  }
  EXPECT_NEAR(map.atPressureRatio(0.0, 0.1).flow_kg_s, 0.5 * 0.483128, 1e-12);  // choked
  // left of surge on the 61 krpm line: linear in head to zero at 1.1 × surge head
  const double k = 0.4 / 1.4, hs = std::pow(1.751, k) - 1.0;
  const double pr_mid = std::pow(1.0 + 1.05 * hs, 1.0 / k);
  EXPECT_NEAR(map.atPressureRatio(61032.8, pr_mid).flow_kg_s, 0.5 * 0.088854, 1e-9);
  const double pr_shut = std::pow(1.0 + 1.1 * hs, 1.0 / k);
  EXPECT_EQ(map.atPressureRatio(61032.8, pr_shut * 1.0001).flow_kg_s, 0.0);
}

TEST(Compressor, OutletTemperatureMatchesIsentropicFormula) {
  const auto& comp = hbt::turbo::test::defaultTurbo().compressor;
  const double k = 0.4 / 1.4, cp = 1.4 * 287.0 / 0.4;
  int checked = 0;
  for (double krpm = 60; krpm <= 130; krpm += 10) {
    for (double pr = 1.3; pr <= 3.4; pr += 0.1) {
      const double T1 = 310.0, p1 = 97000.0;
      const auto s = comp.evaluate(p1, T1, pr * p1, krpm * 1000 * 2 * M_PI / 60);
      if (s.region != CompressorMap::kInside) continue;
      ++checked;
      const double T2 = T1 * (1.0 + (std::pow(pr, k) - 1.0) / s.eta);
      EXPECT_NEAR(s.outlet_total_temperature_K, T2, 1e-9);
      EXPECT_NEAR(comp.outletTotalTemperature(p1, T1, pr * p1, krpm * 1000 * 2 * M_PI / 60),
                  T2, 1e-9);
      EXPECT_NEAR(s.power_W, s.mass_flow_kg_s * cp * (T2 - T1), 1e-6);
    }
  }
  EXPECT_GT(checked, 40);
  // at a measured point with the file's own efficiency: 91.5 krpm map line, Π = 2.822, η = 0.765
  CompressorMap raw = CompressorMap::read(dataPath(kScania));
  const Compressor c1(raw, 100000.0, 298.0);
  const auto s = c1.evaluate(100000.0, 298.0, 282200.0, 91549.2 * 2 * M_PI / 60);
  EXPECT_NEAR(s.outlet_total_temperature_K, 298.0 * (1 + (std::pow(2.822, k) - 1) / 0.765010),
              1e-6);
  EXPECT_NEAR(s.mass_flow_kg_s, 0.339605, 1e-9);
}
