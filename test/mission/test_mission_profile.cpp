// Whole pre-processing on the real VECTO cycles: Urban acceptance figures, limits, stops,
// look-ahead, kinematic consistency, CSV output, every cycle of config/data/cycles/vecto, CLI.
// References are taken from the raw files through hbt::CsvTable (not from the reader under test).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "mission/mission_preprocessor.hpp"
#include "../common/input_errors.hpp"

using namespace hbt::mission;

namespace {

const std::string kVacc = "config/data/vehicle/citybus_P1_hybrid_48V/Bus.vacc";

// Independent look-ups on the raw tables.
struct RawCycle {
  std::vector<double> s, v, grad, stop;  // v in m/s
  explicit RawCycle(const std::string& path) {
    const auto t = hbt::CsvTable::read(path);
    s = t.column("s");
    grad = t.column("grad");
    stop = t.column("stop");
    for (double x : t.column("v")) v.push_back(x / 3.6);
  }
  std::size_t row(double x) const {  // left sample
    const auto it = std::upper_bound(s.begin(), s.end(), x);
    return it == s.begin() ? 0 : static_cast<std::size_t>(it - s.begin()) - 1;
  }
  double target(std::size_t k) const {  // interval target (after a stop: next positive target)
    if (v[k] > 0) return v[k];
    for (std::size_t j = k + 1; j < v.size(); ++j)
      if (v[j] > 0) return v[j];
    return 0;
  }
};
double rawLimit(const hbt::CsvTable& t, const char* col, double v_m_s) {
  const auto& x = t.column("v");
  const auto& y = t.column(col);
  const double kmh = v_m_s * 3.6;
  if (kmh <= x.front()) return y.front();
  if (kmh >= x.back()) return y.back();
  std::size_t i = 0;
  while (x[i + 1] < kmh) ++i;
  return y[i] + (y[i + 1] - y[i]) * (kmh - x[i]) / (x[i + 1] - x[i]);
}

const MissionProfile& urban() {
  static const MissionProfile p = [] {
    MissionParams m;  // defaults: Urban.vdri, Bus.vacc, dt 0.1 s
    return buildMissionProfile(m);
  }();
  return p;
}

}  // namespace

TEST(Urban, DistanceDurationAndStops) {
  const MissionProfile& p = urban();
  const ProfileSummary s = p.summary();
  std::printf("Urban: duration %.1f s, distance %.2f m, stops served %zu/%zu, a in [%.3f, %.3f]\n",
              s.duration_s, s.distance_m, s.stops_served, s.stops_in_cycle, s.max_decel_m_s2,
              s.max_accel_m_s2);
  EXPECT_NEAR(s.distance_m, 39551.0, 0.001 * 39551.0);
  EXPECT_GT(s.duration_s, 7000.0);  // SPEC: "about 8,000 s"
  EXPECT_LT(s.duration_s, 9000.0);
  // Every stop of the raw file: the vehicle stands at its position for its stop time.
  const RawCycle raw("config/data/cycles/vecto/Urban.vdri");
  std::size_t stops = 0;
  for (std::size_t k = 0; k < raw.s.size(); ++k) {
    if (!(raw.v[k] == 0 && raw.stop[k] > 0)) continue;
    ++stops;
    double standing = 0.0;
    for (const auto& x : p.samples())
      if (std::fabs(x.distance_m - raw.s[k]) < 0.01 && x.v_target_m_s == 0.0 && x.stop_flag)
        standing += p.dt_s();
    EXPECT_GE(standing, raw.stop[k] - p.dt_s() - 1e-6) << "stop at s = " << raw.s[k];
    EXPECT_LE(standing, raw.stop[k] + p.dt_s() + 1e-6) << "stop at s = " << raw.s[k];
  }
  EXPECT_EQ(stops, 121u);
  EXPECT_EQ(s.stops_served, 121u);
  EXPECT_EQ(s.stops_in_cycle, 121u);
}

TEST(Urban, AccelerationWithinBusVaccLimits) {
  const MissionProfile& p = urban();
  const auto t = hbt::CsvTable::read(kVacc);
  const auto& x = p.samples();
  // a_k is the mean over [t_k, t_k+1]: compare with the limit range over that speed interval
  // (1e-3 m/s^2 covers a kink of the table inside one 0.1 s interval).
  for (std::size_t k = 0; k + 1 < x.size(); ++k) {
    const double va = x[k].v_target_m_s, vb = x[k + 1].v_target_m_s;
    const double amax = std::max(rawLimit(t, "acc", va), rawLimit(t, "acc", vb));
    const double amin = std::min(rawLimit(t, "dec", va), rawLimit(t, "dec", vb));
    ASSERT_LE(x[k].a_target_m_s2, amax + 1e-3) << "t = " << x[k].t_s;
    ASSERT_GE(x[k].a_target_m_s2, amin - 1e-3) << "t = " << x[k].t_s;
  }
}

TEST(Urban, SpeedNeverAboveTargetPlusAllowedOverspeed) {
  const MissionProfile& p = urban();
  const RawCycle raw("config/data/cycles/vecto/Urban.vdri");
  const DriverRules r;  // VECTO: +5 km/h only for targets >= 50 km/h
  double maxOver = 0.0;
  for (const auto& x : p.samples()) {
    const double vt = raw.target(raw.row(x.distance_m));
    const double allowed = vt >= r.overspeed_min_speed_m_s - 1e-9 ? r.overspeed_m_s : 0.0;
    ASSERT_LE(x.v_target_m_s, vt + allowed + 1e-9) << "t = " << x.t_s << " s = " << x.distance_m;
    maxOver = std::max(maxOver, x.v_target_m_s - vt);
  }
  std::printf("Urban: largest speed above target %.3f km/h\n", maxOver * 3.6);
}

TEST(Urban, LookAheadMeetsEveryLowerTargetAtItsPosition) {
  // Distance grid of the planner (exact positions) and the 0.1 s samples.
  MissionParams m;
  const DrivingCycle c = readVdri(m.cycle_file);
  const DistanceProfile dp =
      planSpeedOverDistance(c, AccelerationLimits::readVacc(kVacc), RoadLoad(m.vehicle), m.driver,
                            m.ds_max_m);
  const MissionProfile& p = urban();
  const RawCycle raw("config/data/cycles/vecto/Urban.vdri");
  const auto& x = p.samples();
  std::size_t drops = 0, fromAbove = 0, i = 0, k0 = 0;
  for (std::size_t k = 1; k < raw.s.size(); ++k) {
    const double vPrev = raw.target(k - 1), vNew = raw.v[k];  // v = 0 for a stop point
    if (!(vNew < vPrev - 1e-9)) continue;
    ++drops;
    while (dp.s_m[i] < raw.s[k]) ++i;
    ASSERT_EQ(dp.s_m[i], raw.s[k]);
    EXPECT_LE(dp.v_m_s[i], vNew + 1e-12) << "drop at s = " << raw.s[k];
    // Speed 20 m before the point; if it was above the new target the driver slowed down
    // before the point, i.e. the deceleration started ahead of it.
    std::size_t j = i;
    while (j > 0 && dp.s_m[j] > raw.s[k] - 20.0) --j;
    if (dp.v_m_s[j] > vNew + 0.5) {
      ++fromAbove;
      double minA = 0.0;
      for (std::size_t q = j; q < i; ++q) minA = std::min(minA, dp.stepAccel_m_s2(q));
      EXPECT_LT(minA, -0.3) << "drop at s = " << raw.s[k];
    }
    // Samples: the speed when passing the point is within one sample step (|a| dt <= 0.1 m/s).
    while (k0 + 1 < x.size() && x[k0 + 1].distance_m < raw.s[k]) ++k0;
    EXPECT_LE(std::min(x[k0].v_target_m_s, x[k0 + 1].v_target_m_s), vNew + 0.1)
        << "drop at s = " << raw.s[k];
  }
  std::printf("Urban: %zu target drops (incl. 120 stops after the start), %zu approached from "
              "above\n", drops, fromAbove);
  EXPECT_GT(fromAbove, 121u);
}

TEST(Urban, KinematicConsistency) {
  const MissionProfile& p = urban();
  const auto& x = p.samples();
  const double dt = p.dt_s();
  double s = x[0].distance_m, v = x[0].v_target_m_s, maxDs = 0.0, maxDv = 0.0;
  for (std::size_t k = 1; k < x.size(); ++k) {
    s += 0.5 * dt * (x[k - 1].v_target_m_s + x[k].v_target_m_s);  // integral of v dt
    v += dt * x[k - 1].a_target_m_s2;                               // integral of a dt
    maxDs = std::max(maxDs, std::fabs(s - x[k].distance_m));
    maxDv = std::max(maxDv, std::fabs(v - x[k].v_target_m_s));
  }
  std::printf("Urban: max |int v dt - distance| = %.4f m, max |int a dt - v| = %.2e m/s\n",
              maxDs, maxDv);
  EXPECT_LT(maxDs, 0.5);   // trapezoid of the sampled speed vs the exact position
  EXPECT_LT(maxDv, 1e-8);  // a_target is the mean acceleration of each sample interval
  EXPECT_NEAR(s, x.back().distance_m, 0.5);
}

TEST(Urban, InterpolationHelpers) {
  const MissionProfile& p = urban();
  const auto& x = p.samples();
  const std::size_t k = 12345;
  const double t = x[k].t_s + 0.25 * p.dt_s();
  EXPECT_NEAR(p.speedAt(t), 0.75 * x[k].v_target_m_s + 0.25 * x[k + 1].v_target_m_s, 1e-12);
  EXPECT_NEAR(p.speedAt(t), x[k].v_target_m_s + 0.25 * p.dt_s() * p.accelAt(t), 1e-9);
  EXPECT_NEAR(p.distanceAt(t), 0.75 * x[k].distance_m + 0.25 * x[k + 1].distance_m, 1e-9);
  EXPECT_EQ(p.accelAt(t), x[k].a_target_m_s2);
  EXPECT_EQ(p.speedAt(-5.0), x.front().v_target_m_s);
  EXPECT_EQ(p.speedAt(1e9), x.back().v_target_m_s);
  const RawCycle raw("config/data/cycles/vecto/Urban.vdri");
  for (double s : {0.0, 0.5, 1.0, 167.0, 12345.6, 39550.9})
    EXPECT_EQ(p.gradeAtDistance(s), raw.grad[raw.row(s)]) << s;
  EXPECT_EQ(p.gradeAt(t), raw.grad[raw.row(p.distanceAt(t))]);
  for (std::size_t j = 0; j < x.size(); j += 997)
    EXPECT_EQ(x[j].grade_percent, raw.grad[raw.row(x[j].distance_m)]);
  EXPECT_TRUE(p.standingAtStop(1.0));  // 12.6 s stop at s = 0
  EXPECT_FALSE(p.standingAtStop(20.0));
}

TEST(Urban, CsvRoundTripAndDeterminism) {
  MissionParams m;
  m.profile_csv_file = ::testing::TempDir() + "urban_profile.csv";
  const MissionProfile p2 = buildMissionProfile(m);
  const MissionProfile& p = urban();
  ASSERT_EQ(p2.samples().size(), p.samples().size());
  for (std::size_t k = 0; k < p.samples().size(); ++k) {
    ASSERT_EQ(p2.samples()[k].v_target_m_s, p.samples()[k].v_target_m_s);
    ASSERT_EQ(p2.samples()[k].distance_m, p.samples()[k].distance_m);
  }
  const auto t = hbt::CsvTable::read(m.profile_csv_file);
  const std::vector<std::string> hdr{"t_s", "v_target_m_s", "a_target_m_s2", "distance_m",
                                     "grade_percent", "altitude_m", "stop_flag"};
  EXPECT_EQ(t.header(), hdr);
  ASSERT_EQ(t.rows(), p.samples().size());
  for (std::size_t k = 0; k < t.rows(); k += 101) {
    const auto& x = p.samples()[k];
    EXPECT_NEAR(t.column("t_s")[k], x.t_s, 1e-6);
    EXPECT_NEAR(t.column("v_target_m_s")[k], x.v_target_m_s, 1e-9);
    EXPECT_NEAR(t.column("a_target_m_s2")[k], x.a_target_m_s2, 1e-9);
    EXPECT_NEAR(t.column("distance_m")[k], x.distance_m, 1e-6);
    EXPECT_NEAR(t.column("altitude_m")[k], x.altitude_m, 1e-6);
    EXPECT_EQ(t.column("stop_flag")[k], x.stop_flag);
  }
  std::remove(m.profile_csv_file.c_str());
}

TEST(Mission, BadFilesNameTheFile) {
  MissionParams m;
  m.accel_limits_file = "config/data/vehicle/none.vacc";
  hbt::testing::expectInputError([&] { buildMissionProfile(m); }, m.accel_limits_file, "(file)");
  m = MissionParams{};
  m.profile_csv_file = "/nonexistent_dir/p.csv";
  EXPECT_THROW(buildMissionProfile(m), hbt::InputError);
}

TEST(AllCycles, EveryVectoCycleIsPreprocessed) {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator("config/data/cycles/vecto"))
    if (e.path().extension() == ".vdri") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  ASSERT_EQ(files.size(), 10u);
  const auto vacc = hbt::CsvTable::read(kVacc);
  for (const auto& f : files) {
    MissionParams m;
    m.cycle_file = f;
    const MissionProfile p = buildMissionProfile(m);
    const ProfileSummary s = p.summary();
    const RawCycle raw(f);
    std::size_t stops = 0;
    for (std::size_t k = 0; k < raw.s.size(); ++k) stops += raw.v[k] == 0 && raw.stop[k] > 0;
    const double len = raw.s.back() - raw.s.front();
    std::printf("%-40s %9.1f m (last <s> %9.1f)  %8.1f s  stops %3zu/%3zu  mean %.1f km/h\n",
                f.c_str(), s.distance_m, raw.s.back(), s.duration_s, s.stops_served, stops,
                3.6 * s.distance_m / s.duration_s);
    EXPECT_NEAR(s.distance_m, len, 0.001 * len) << f;
    EXPECT_EQ(s.stops_served, stops) << f;
    const auto& x = p.samples();
    for (std::size_t k = 0; k + 1 < x.size(); ++k) {
      const double va = x[k].v_target_m_s, vb = x[k + 1].v_target_m_s;
      ASSERT_LE(x[k].a_target_m_s2,
                std::max(rawLimit(vacc, "acc", va), rawLimit(vacc, "acc", vb)) + 1e-3) << f;
      ASSERT_GE(x[k].a_target_m_s2,
                std::min(rawLimit(vacc, "dec", va), rawLimit(vacc, "dec", vb)) - 1e-3) << f;
      ASSERT_GE(x[k + 1].distance_m, x[k].distance_m) << f;
    }
  }
}

TEST(Cli, UsageErrorsAndSummary) {
  const std::string exe = HBT_MISSION_PROFILE_EXE;
  EXPECT_EQ(WEXITSTATUS(std::system((exe + " --cycle x.vdri > /dev/null 2>&1").c_str())), 2);
  EXPECT_EQ(WEXITSTATUS(std::system((exe + " --out a.csv --bogus > /dev/null 2>&1").c_str())), 2);
  EXPECT_EQ(WEXITSTATUS(std::system((exe + " --cycle a --out b --dt x > /dev/null 2>&1").c_str())), 2);
  const std::string out = ::testing::TempDir() + "cli_profile.csv";
  EXPECT_EQ(WEXITSTATUS(std::system((exe + " --cycle config/data/cycles/vecto/NoSuch.vdri --out " +
                                     out + " > /dev/null 2>&1").c_str())), 1);
  const std::string log = ::testing::TempDir() + "cli.txt";
  ASSERT_EQ(WEXITSTATUS(std::system((exe + " --cycle config/data/cycles/vecto/MunicipalUtility.vdri"
                                     " --out " + out + " --dt 0.5 > " + log).c_str())), 0);
  const auto t = hbt::CsvTable::read(out);
  EXPECT_NEAR(t.column("t_s")[1], 0.5, 1e-12);
  EXPECT_NEAR(t.column("distance_m").back(), 9962.0, 1e-6);
  std::FILE* f = std::fopen(log.c_str(), "r");
  ASSERT_TRUE(f);
  char buf[4096] = {0};
  const std::size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  const std::string text(buf, n);
  EXPECT_NE(text.find("stops served   58 of 58"), std::string::npos) << text;
  std::remove(out.c_str());
  std::remove(log.c_str());
}
