// Scaling to the 6.72 l / 210 kW engine, rated-point compressor duty from engine breathing,
// steady turbocharger matching (shaft power balance by bisection on speed), the YAML
// configuration, and look-up cost / no allocation.
#include <gtest/gtest.h>

#include "common/yaml_params.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>

#include "../common/alloc_counter.hpp"
#include "../common/input_errors.hpp"
#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/params.hpp"
#include "turbo_test_util.hpp"

using namespace hbt::turbo;
using hbt::turbo::test::dataPath;
using hbt::turbo::test::defaultTurbo;
using hbt::turbo::test::repoRoot;

namespace {

constexpr double kRpm = M_PI / 30.0;

double bisect(const std::function<double(double)>& f, double a, double b) {
  double fa = f(a);
  EXPECT_LT(fa * f(b), 0.0) << "no sign change in [" << a << ", " << b << "]";
  for (int i = 0; i < 100; ++i) {
    const double m = 0.5 * (a + b), fm = f(m);
    if ((fm < 0) == (fa < 0)) { a = m; fa = fm; } else { b = m; }
  }
  return 0.5 * (a + b);
}

// Rated operating point from engine breathing (engine data: SPEC §3; VECTO bus engine rated
// speed 2200 rpm; volumetric efficiency referred to intake-manifold state 0.90, assumed).
struct Rated { double m_air, m_fuel, p1, T1, pr, p2, T2, Tim, pim, N; };

Rated ratedPoint(double bsfc, double lambda) {
  const auto& t = defaultTurbo();
  Rated r{};
  r.m_fuel = 210e3 * bsfc * 1e-3 / 3.6e6;
  r.m_air = r.m_fuel * lambda * 14.5;
  r.p1 = 98000.0;
  r.T1 = 298.0;
  const double swept = 6.72e-3 * 2200.0 / 120.0 * 0.90;  // m³/s
  r.pr = 2.5;
  for (int it = 0; it < 40; ++it) {
    r.p2 = r.pr * r.p1;
    r.N = bisect([&](double n) {
      return t.compressor.massFlow(r.p1, r.T1, r.p2, n * kRpm) - r.m_air; }, 2e4, 2.5e5);
    r.T2 = t.compressor.outletTotalTemperature(r.p1, r.T1, r.p2, r.N * kRpm);
    r.Tim = t.intercooler.outletTemperature(r.T2, 298.0, r.m_air);
    r.pim = r.m_air * 287.0 * r.Tim / swept;
    r.pr = (r.pim + t.intercooler.pressureDrop(r.m_air, r.T2, r.p2)) / r.p1;
  }
  return r;
}


}  // namespace

TEST(Scaling, FactorsFromRatedAirFlowAndEfficiencyRidge) {
  const auto& s = defaultTurbo().scaling;
  const double fuel = 210e3 * 210.0 / 3.6e9, air = fuel * 1.6 * 14.5;
  EXPECT_NEAR(s.fuel_kg_s, fuel, 1e-12);
  EXPECT_NEAR(s.air_kg_s, air, 1e-12);
  // independent ridge: max-efficiency row of each speed line of the CSV, interpolated at the design Π
  const auto t = hbt::CsvTable::read(dataPath(
      "scania_di09_enginetoolbox/compressor_map_SAE_lowflow_extrapolated.csv"));
  std::map<double, std::pair<double, double>> best;  // speed -> (eta, row)
  for (std::size_t r = 0; r < t.rows(); ++r) {
    auto& b = best[t.column("speed")[r]];
    if (t.column("efficiency")[r] > b.first) b = {t.column("efficiency")[r], double(r)};
  }
  double pr0 = 0, m0 = 0, ridge = -1;
  for (const auto& [n, b] : best) {
    const double pr = t.column("pressure_ratio")[std::size_t(b.second)];
    const double m = t.column("mass_flow")[std::size_t(b.second)];
    const double d = TurboConfig{}.scaling.rated_pressure_ratio;
    if (pr0 > 0 && pr0 <= d && pr >= d) ridge = m0 + (m - m0) * (d - pr0) / (pr - pr0);
    pr0 = pr;
    m0 = m;
  }
  ASSERT_GT(ridge, 0.0);
  EXPECT_NEAR(s.ridge_flow_kg_s, ridge, 1e-12);
  EXPECT_NEAR(s.flow_factor, air / 0.98 / ridge, 1e-12);
  EXPECT_NEAR(s.speed_factor, 1.0 / std::sqrt(s.flow_factor), 1e-12);
  const auto& lines = defaultTurbo().compressor.map().lines();
  EXPECT_NEAR(lines.front().speed_rpm, 20344.3 * s.speed_factor, 1e-9);
  EXPECT_NEAR(lines.back().flow.back(), 0.483128 * s.flow_factor, 1e-12);
  std::cout << "[scaling] rated air " << s.air_kg_s << " kg/s, ridge flow " << ridge
            << " kg/s, flow factor " << s.flow_factor << ", speed factor " << s.speed_factor
            << ", diameter factor " << s.diameter_factor << "\n";
}

TEST(Scaling, ScaledCompressorDeliversRatedAirFlow) {
  // across the stated uncertainty of BSFC (205–215 g/kWh) and λ (1.5–1.7)
  for (auto [bsfc, lambda] : {std::pair{205.0, 1.5}, std::pair{210.0, 1.6},
                              std::pair{215.0, 1.7}}) {
    const Rated r = ratedPoint(bsfc, lambda);
    const auto c = defaultTurbo().compressor.evaluate(r.p1, r.T1, r.p2, r.N * kRpm);
    std::cout << "[rated] bsfc " << bsfc << " lambda " << lambda << ": air " << r.m_air
              << " kg/s, PR " << r.pr << ", p_im " << r.pim << " Pa, T2 " << r.T2
              << " K, T_im " << r.Tim << " K, speed " << r.N << " rpm, eta " << c.eta
              << ", P_c " << c.power_W << " W\n";
    EXPECT_NEAR(c.mass_flow_kg_s, r.m_air, 1e-9);
    // engine-breathing estimate (η_v 0.90, 2200 rpm, no EGR): 2.2 (λ 1.5) … 2.7 (λ 1.7)
    EXPECT_GT(r.pr, 2.1);
    EXPECT_LT(r.pr, 3.2);
    if (lambda == 1.6) {
      EXPECT_GT(r.pr, 2.3);
      EXPECT_LT(r.pr, 2.8);
      // the scaling placed the rated flow on the efficiency ridge at the YAML design Π
      EXPECT_NEAR(r.pr, TurboConfig{}.scaling.rated_pressure_ratio, 0.1);
    }
    EXPECT_EQ(c.region, CompressorMap::kInside);
    EXPECT_GT(c.eta, 0.70);
    EXPECT_GT(r.N, 80e3);
    EXPECT_LT(r.N, 140e3);
  }
}

TEST(Matching, ShaftPowerBalanceAtRatedPoint) {
  const auto& t = defaultTurbo();
  const Rated r = ratedPoint(210.0, 1.6);
  const double T3 = 950.0, p4 = 105000.0, m_exh = r.m_air + r.m_fuel;
  const auto p3For = [&](double n, double wg) {
    return bisect([&](double p3) {
      return t.turbine.evaluate(p3, T3, p3, T3, p4, n * kRpm, wg).total_flow_kg_s - m_exh;
    }, 1.001 * p4, 8e5);
  };
  const auto residual = [&](double n, double wg) {
    const double p3 = p3For(n, wg);
    const auto ts = t.turbine.evaluate(p3, T3, p3, T3, p4, n * kRpm, wg);
    const auto cs = t.compressor.evaluate(r.p1, r.T1, r.p2, n * kRpm);
    TurboShaft sh(t.shaft.params(), n * kRpm);
    return sh.netPower(ts.power_W, cs.power_W);
  };
  // (a) wastegate closed: speed where the shaft is in balance
  const double N = bisect([&](double n) { return residual(n, 0.0); }, 3e4, 2.5e5);
  const double p3 = p3For(N, 0.0);
  const auto cs = t.compressor.evaluate(r.p1, r.T1, r.p2, N * kRpm);
  std::cout << "[match, wastegate closed] speed " << N << " rpm, p3 " << p3 << " Pa, p3/p2 "
            << p3 / r.p2 << ", compressor flow " << cs.mass_flow_kg_s << " kg/s (engine needs "
            << r.m_air << ")\n";
  EXPECT_GT(N, 80e3);
  EXPECT_LT(N, 140e3);
  EXPECT_GT(p3 / r.p2, 0.9);
  EXPECT_LT(p3 / r.p2, 1.4);
  EXPECT_GT(cs.mass_flow_kg_s, r.m_air);  // surplus: the boost must be limited by the wastegate
  EXPECT_LT(cs.mass_flow_kg_s, 1.6 * r.m_air);
  // (b) speed fixed by the engine's air demand: the wastegate opening that balances the shaft
  const double a = bisect([&](double wg) { return residual(r.N, wg); }, 0.0, 1.0);
  const double p3b = p3For(r.N, a);
  const auto ts = t.turbine.evaluate(p3b, T3, p3b, T3, p4, r.N * kRpm, a);
  std::cout << "[match, rated] speed " << r.N << " rpm, wastegate opening " << a << " (flow "
            << ts.wastegate_flow_kg_s << " kg/s), p3 " << p3b << " Pa, ER " << p3b / p4
            << ", eta_t " << ts.entry[0].eta << ", P_t " << ts.power_W << " W\n";
  EXPECT_GT(a, 0.0);
  EXPECT_LT(a, 1.0);
  EXPECT_GT(ts.entry[0].eta, 0.6);
}

TEST(Config, YamlFileLoadsAndMatchesBuiltInDefaults) {
  const std::string path = repoRoot() + "/config/engine_1d_turbo.yaml";
  TurboConfig cfg;
  cfg.source = path;
  hbt::ParamSet ps;
  cfg.declare(ps, "turbo/");
  hbt::applyParams(ps, hbt::readYamlParams(path));
  TurboConfig def;
  hbt::ParamSet pd;
  def.declare(pd, "turbo/");
  EXPECT_EQ(hbt::describeParams(ps), hbt::describeParams(pd));  // YAML documents the defaults
  const auto t = buildTurbocharger(cfg, repoRoot());
  EXPECT_NEAR(t.scaling.flow_factor, defaultTurbo().scaling.flow_factor, 1e-12);
  // misspelt key, out-of-range value, missing map file: errors name file and key
  auto src = hbt::readYamlParams(path);
  src.set("turbo/shaft/inertia_kgm2", 1e-4);
  hbt::testing::expectInputError([&] { hbt::applyParams(ps, src); }, path, "turbo/shaft/inertia_kgm2");
  src = hbt::readYamlParams(path);
  src.set("turbo/scaling/lambda", 0.5);
  hbt::testing::expectInputError([&] { hbt::applyParams(ps, src); }, path, "turbo/scaling/lambda");
  TurboConfig bad = cfg;
  bad.turbine_map_file = "nowhere/turbine.csv";
  const std::string msg = hbt::testing::expectInputError([&] { buildTurbocharger(bad, repoRoot()); },
                                                         dataPath("nowhere/turbine.csv"), "(file)");
  EXPECT_NE(msg.find("nowhere/turbine.csv"), std::string::npos) << msg;
  TurboConfig pr = cfg;
  pr.scaling.rated_pressure_ratio = 4.49;  // ridge ends at 4.484
  hbt::testing::expectInputError([&] { buildTurbocharger(pr, repoRoot()); }, path,
                                 "turbo/scaling/rated_pressure_ratio");
}

TEST(Performance, LookupsAreCheapAndDoNotAllocate) {
  const auto& t = defaultTurbo();
  const int n = 200000;
  double sink = 0.0;
  const long a0 = hbt::testing::allocations();
  auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) {
    const double f = (i % 1000) * 1e-3;
    sink += t.compressor.massFlow(98000.0, 298.0, 98000.0 * (0.8 + 2.4 * f), 12000.0 * f);
  }
  auto t1 = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) {
    const double f = (i % 1000) * 1e-3;
    sink += t.turbine.entry(i & 1).massFlow(1e5 * (0.9 + 3.0 * f), 900.0, 1.05e5, 12000.0 * f);
  }
  auto t2 = std::chrono::steady_clock::now();
  for (int i = 0; i < n; ++i) {
    const double f = (i % 1000) * 1e-3;
    sink += t.turbine.evaluate(1e5 * (0.9 + 3 * f), 900, 1e5 * (1 + 2 * f), 850, 1.05e5,
                               12000.0 * f, f).power_W;
  }
  auto t3 = std::chrono::steady_clock::now();
  EXPECT_EQ(hbt::testing::allocations(), a0);
  EXPECT_TRUE(std::isfinite(sink));
  const auto ns = [&](auto a, auto b) {
    return std::chrono::duration<double, std::nano>(b - a).count() / n; };
  std::cout << "[cost] compressor.massFlow " << ns(t0, t1) << " ns, turbine entry massFlow "
            << ns(t1, t2) << " ns, twin-entry evaluate " << ns(t2, t3) << " ns\n";
  EXPECT_LT(ns(t0, t1), 5000.0);  // loose: shared CI cores
  EXPECT_LT(ns(t1, t2), 5000.0);
}
