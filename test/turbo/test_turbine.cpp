// Turbine map and twin-entry turbine: measured points exact, validation errors, nozzle-law
// extrapolation (choke saturation, zero flow at ER = 1), efficiency shape outside the map,
// continuity, monotonicity and no NaN over a wide sweep, twin-entry split and wastegate orifice.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "turbo/turbine.hpp"
#include "turbo_test_util.hpp"
#include "../common/input_errors.hpp"

using namespace hbt::turbo;
using hbt::turbo::test::dataPath;

namespace {

const std::string kFile = "scania_di09_enginetoolbox/turbine_map_SAE.csv";
const double kGamma = 1.33;

// Own implementation of the isentropic-nozzle flow function (reference for the tests).
double psiRef(double er) {
  const double g = kGamma, pc = std::pow(2.0 / (g + 1.0), g / (g - 1.0));
  const double pi = std::max(1.0 / er, pc);
  return std::sqrt(2.0 * g / (g - 1.0) * (std::pow(pi, 2.0 / g) - std::pow(pi, (g + 1.0) / g)));
}

TurbineMap rawMap() { return TurbineMap::read(dataPath(kFile)); }

// A map file `name` of the rows `body` is an InputError naming the file and `key`.
void expectBadMapFile(const std::string& name, const std::string& body, const std::string& key) {
  const std::string p = ::testing::TempDir() + name;
  std::ofstream(p) << "reduced_speed,reduced_mass_flow_parameter,expansion_ratio,efficiency\n"
                   << body;
  hbt::testing::expectInputError([&] { TurbineMap::read(p); }, p, key);
}

}  // namespace

TEST(TurbineMap, ReproducesMeasuredPointsExactly) {
  const auto map = rawMap();
  const auto t = hbt::CsvTable::read(dataPath(kFile));
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const auto p = map.at(t.column("reduced_speed")[r], t.column("expansion_ratio")[r]);
    EXPECT_NEAR(p.mfp, t.column("reduced_mass_flow_parameter")[r], 1e-15) << "row " << r;
    EXPECT_NEAR(p.eta, t.column("efficiency")[r], 1e-15) << "row " << r;
    EXPECT_EQ(p.region, TurbineMap::kInside);
  }
}

TEST(TurbineMap, ValidationErrorsNameFileAndColumn) {
  expectBadMapFile("t_eta.csv", "1000,0.03,1.5,0.7\n1000,0.04,2,1.5\n2000,0.03,1.5,0.7\n"
                                "2000,0.04,2,0.7\n", "efficiency");
  expectBadMapFile("t_mfp.csv", "1000,0.03,1.5,0.7\n1000,0.02,2,0.7\n2000,0.03,1.5,0.7\n"
                                "2000,0.04,2,0.7\n", "reduced_mass_flow_parameter");
  expectBadMapFile("t_er.csv", "1000,0.03,0.9,0.7\n1000,0.04,2,0.7\n2000,0.03,1.5,0.7\n"
                               "2000,0.04,2,0.7\n", "expansion_ratio");
}

TEST(TurbineMap, NozzleLawChokesAtHighExpansionRatio) {
  const auto map = rawMap();
  for (const auto& l : map.lines()) {
    const double last = l.mfp.back();
    // ER_last = 3.5 is beyond the critical ratio (1.85 for γ = 1.33): saturated, constant
    for (double er : {4.0, 6.0, 10.0, 40.0})
      EXPECT_NEAR(map.at(l.speed, er).mfp, last, 1e-15) << l.speed << " " << er;
    EXPECT_TRUE(map.at(l.speed, 10.0).region & TurbineMap::kErAbove);
    // below the first point: nozzle law through the first point, zero at ER = 1
    for (double er : {1.02, 1.1, 1.25, 1.39})
      EXPECT_NEAR(map.at(l.speed, er).mfp, l.mfp.front() * psiRef(er) / psiRef(l.er.front()),
                  1e-12);
    EXPECT_EQ(map.at(l.speed, 1.0).mfp, 0.0);
    EXPECT_EQ(map.at(l.speed, 0.8).mfp, 0.0);
  }
  // choked effective area of the lowest-speed line is a plausible turbine throat (1 entry pair)
  const double psi_star = psiRef(10.0);
  const double A = map.lines().front().mfp.back() * std::sqrt(287.0) / (1000.0 * psi_star);
  EXPECT_GT(A, 5e-4);
  EXPECT_LT(A, 2e-3);
}

TEST(TurbineMap, EfficiencyParabolaAndLowSpeedShape) {
  const auto map = rawMap();
  EXPECT_GT(map.etaMaxFit(), 0.65);
  EXPECT_LT(map.etaMaxFit(), 0.85);
  // ν_opt lies inside the measured range of blade-speed parameters
  double nu_lo = 1e300, nu_hi = 0;
  for (const auto& l : map.lines())
    for (double er : l.er) {
      nu_lo = std::min(nu_lo, map.bladeSpeedParameter(l.speed, er));
      nu_hi = std::max(nu_hi, map.bladeSpeedParameter(l.speed, er));
    }
  EXPECT_GT(map.nuOpt(), nu_lo);
  EXPECT_LT(map.nuOpt(), nu_hi);
  // stalled turbine does no work; below the lowest line η follows the parabola 2x − x² (x < 1)
  const auto& l0 = map.lines().front();
  for (double er : {1.4, 2.0, 3.5}) {
    EXPECT_EQ(map.at(0.0, er).eta, 0.0);
    const double x0 = map.bladeSpeedParameter(l0.speed, er) / map.nuOpt();
    ASSERT_LT(x0, 1.0);
    const double e0 = map.at(l0.speed, er).eta;
    for (double s : {0.8, 0.5, 0.2}) {
      const double x = s * x0;
      EXPECT_NEAR(map.at(s * l0.speed, er).eta, e0 * (2 * x - x * x) / (2 * x0 - x0 * x0), 1e-12);
    }
  }
}

TEST(TurbineMap, ContinuousAtMeasuredBoundaries) {
  const auto map = rawMap();
  const double e = 1e-8;
  for (const auto* l : {&map.lines().front(), &map.lines().back()})
    for (double er = 1.05; er < 8.0; er += 0.05) {
      const auto a = map.at(l->speed * (1 - e), er), b = map.at(l->speed * (1 + e), er);
      EXPECT_NEAR(a.mfp, b.mfp, 1e-6);
      EXPECT_NEAR(a.eta, b.eta, 1e-5) << l->speed << " " << er;
    }
  for (double n = 500; n < 6000; n += 100)
    for (double er : {1.4, 3.5}) {
      const auto a = map.at(n, er * (1 - e)), b = map.at(n, er * (1 + e));
      EXPECT_NEAR(a.mfp, b.mfp, 1e-6);
      EXPECT_NEAR(a.eta, b.eta, 1e-5) << n << " " << er;
    }
}

TEST(TurbineMap, WideSweepNoNanAndMonotonic) {
  const auto map = rawMap();
  const TurbineEntry full(map, 1.0);
  const int NN = 150, NE = 300;
  std::vector<double> prev_n(NE + 1, 1e300);
  for (int i = 0; i <= NN; ++i) {
    const double n = 12000.0 * i / NN;  // up to 2.5 × the highest line
    double prev_er = -1.0;
    for (int j = 0; j <= NE; ++j) {
      const double er = 0.5 + 19.5 * j / NE;
      const auto p = map.at(n, er);
      ASSERT_TRUE(std::isfinite(p.mfp) && std::isfinite(p.eta)) << n << " " << er;
      ASSERT_GE(p.mfp, 0.0);
      ASSERT_GE(p.eta, 0.0);
      ASSERT_LT(p.eta, 1.0);
      EXPECT_GE(p.mfp, prev_er - 1e-15) << "flow falls with ER at N=" << n << " ER=" << er;
      EXPECT_LE(p.mfp, prev_n[j] + 1e-15) << "flow rises with N at N=" << n << " ER=" << er;
      prev_er = p.mfp;
      prev_n[j] = p.mfp;
      const double T3 = 900.0, p4 = 1.05e5;
      const auto s = full.evaluate(er * p4, T3, p4, n * std::sqrt(T3) * M_PI / 30.0);
      ASSERT_TRUE(std::isfinite(s.power_W) && std::isfinite(s.outlet_total_temperature_K));
      ASSERT_GE(s.power_W, 0.0);
      ASSERT_GT(s.outlet_total_temperature_K, 0.0);
      ASSERT_LE(s.outlet_total_temperature_K, T3 + 1e-9);
    }
  }
}

TEST(TurbineEntry, PowerAndOutletTemperatureFromEnthalpyDrop) {
  const TurbineEntry full(rawMap(), 1.0);
  const double T3 = 950.0, p3 = 250000.0, p4 = 105000.0, w = 9000.0;
  const auto s = full.evaluate(p3, T3, p4, w);
  const double cp = kGamma * 287.0 / (kGamma - 1.0), k = (kGamma - 1.0) / kGamma;
  const double dhs = cp * T3 * (1.0 - std::pow(p4 / p3, k));
  EXPECT_NEAR(s.mass_flow_kg_s, s.mfp * 250.0 / std::sqrt(T3), 1e-12);
  EXPECT_NEAR(s.power_W, s.mass_flow_kg_s * dhs * s.eta, 1e-6);
  EXPECT_NEAR(s.outlet_total_temperature_K, T3 - s.eta * dhs / cp, 1e-9);
  EXPECT_NEAR(s.torque_Nm, s.power_W / w, 1e-9);
}

TEST(TwinEntryTurbine, EqualAdmissionSplitAndWastegateOrifice) {
  const auto map = rawMap();
  const hbt::PerfectGas exh{kGamma, 287.0};
  const double A = 3e-4, cd = 0.8;
  const TwinEntryTurbine tw(map, Wastegate(cd, A, exh));
  const TurbineEntry full(map, 1.0);
  const double p3 = 240000.0, T3 = 920.0, p4 = 104000.0, w = 10000.0;
  const auto s = tw.evaluate(p3, T3, p3, T3, p4, w, 0.0);
  const auto f = full.evaluate(p3, T3, p4, w);
  EXPECT_NEAR(s.entry[0].mass_flow_kg_s + s.entry[1].mass_flow_kg_s, f.mass_flow_kg_s, 1e-12);
  EXPECT_NEAR(s.power_W, f.power_W, 1e-6);
  EXPECT_EQ(s.wastegate_flow_kg_s, 0.0);
  // unequal admission: each entry follows its own pressure
  const auto u = tw.evaluate(p3, T3, 150000.0, T3, p4, w, 0.0);
  EXPECT_NEAR(u.entry[0].mass_flow_kg_s, 0.5 * f.mass_flow_kg_s, 1e-12);
  EXPECT_LT(u.entry[1].mass_flow_kg_s, u.entry[0].mass_flow_kg_s);
  // wastegate: choked orifice ṁ = C_d A p √(γ/(R T)) (2/(γ+1))^((γ+1)/(2(γ−1))), entry 1 only
  const auto o = tw.evaluate(p3, T3, 150000.0, 800.0, p4, w, 1.0);
  const double choked = cd * A * p3 * std::sqrt(kGamma / (287.0 * T3)) *
                        std::pow(2.0 / (kGamma + 1.0), (kGamma + 1.0) / (2.0 * (kGamma - 1.0)));
  EXPECT_NEAR(o.wastegate_flow_kg_s, choked, 1e-12);
  EXPECT_NEAR(tw.evaluate(p3, T3, p3, T3, p4, w, 0.5).wastegate_flow_kg_s, 0.5 * choked, 1e-12);
  // subsonic: incompressible limit for a small drop, ṁ ≈ C_d A √(2 ρ Δp)
  const double pin = 104500.0, rho = pin / (287.0 * T3);
  const double sub = tw.wastegate().massFlow(pin, T3, p4, 1.0);
  EXPECT_NEAR(sub, cd * A * std::sqrt(2.0 * rho * (pin - p4)), 0.005 * sub);
  EXPECT_EQ(tw.wastegate().massFlow(p4, T3, pin, 1.0), 0.0);  // no reverse flow
  // mixed outlet temperature: adiabatic mixing (flow-weighted, equal c_p)
  const double h = o.entry[0].mass_flow_kg_s * o.entry[0].outlet_total_temperature_K +
                   o.entry[1].mass_flow_kg_s * o.entry[1].outlet_total_temperature_K +
                   o.wastegate_flow_kg_s * T3;
  EXPECT_NEAR(o.outlet_mixed_temperature_K * o.total_flow_kg_s, h, 1e-9);
}
