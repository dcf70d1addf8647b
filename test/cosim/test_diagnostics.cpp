// The ROS-free part of the participants' diagnostics (src/cosim/core/diagnostics.hpp): compute-time
// window statistics, the hysteresis switch, a warning's persistence / first-time latch / re-raise,
// the status cadence in simulated time and the status keys, and config/diagnostics.yaml's binding (the status period)
// (every key of the shipped file known, bad keys and values rejected naming file and key).
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>

#include "common/errors.hpp"
#include "common/yaml_params.hpp"
#include "cosim/core/diagnostics.hpp"
#include "cosim/core/diagnostics_params.hpp"
#include "../common/param_checks.hpp"

using namespace hbt::cosim::core;

namespace {
constexpr Nanos MS = 1000000, S = 1000000000;

std::map<std::string, std::string> valuesOf(const DiagStatus& s) {
  std::map<std::string, std::string> m;
  for (const auto& kv : s.values) {
    EXPECT_EQ(m.count(kv.key), 0u) << "duplicate key " << kv.key;
    m[kv.key] = kv.value;
  }
  return m;
}

std::string sourceDir() {
  const char* d = std::getenv("HBT_SOURCE_DIR");
  return d ? d : ".";
}
}  // namespace

TEST(Diagnostics, WindowStatsMeanMaxCountPerWindowAndRun) {
  WindowStats w;
  EXPECT_EQ(w.count(), 0u);
  EXPECT_EQ(w.mean(), 0.0);
  EXPECT_EQ(w.max(), 0.0);
  for (double x : {2.0, 6.0, 1.0}) w.add(x);
  EXPECT_EQ(w.count(), 3u);
  EXPECT_DOUBLE_EQ(w.mean(), 3.0);
  EXPECT_EQ(w.max(), 6.0);
  w.closeWindow();
  EXPECT_EQ(w.count(), 0u);
  EXPECT_EQ(w.max(), 0.0);
  w.add(0.5);  // a window's max is its own, also when smaller than the run's
  EXPECT_EQ(w.max(), 0.5);
  EXPECT_EQ(w.mean(), 0.5);
  EXPECT_EQ(w.totalCount(), 4u);
  EXPECT_DOUBLE_EQ(w.totalMean(), 9.5 / 4.0);
  EXPECT_EQ(w.totalMax(), 6.0);
}

TEST(Diagnostics, HysteresisOnAboveOffBelow) {
  Hysteresis h(3.0, 2.0);
  EXPECT_FALSE(h.update(2.5));  // between the levels from off: stays off
  EXPECT_FALSE(h.update(3.0));  // strictly above
  EXPECT_TRUE(h.update(3.01));
  EXPECT_TRUE(h.update(2.5));   // between the levels from on: stays on
  EXPECT_TRUE(h.update(2.0));
  EXPECT_FALSE(h.update(1.99));
  Hysteresis plain(1.0, 1.0);
  EXPECT_TRUE(plain.update(1.5));
  EXPECT_FALSE(plain.update(0.5));
  EXPECT_THROW(Hysteresis(1.0, 2.0), std::invalid_argument);
}

TEST(Diagnostics, WarningPersistenceFirstTimeAndReraise) {
  Warning w("x", toNanos(0.3));
  const Nanos dt = 100 * MS;
  // condition true from t = 0.5 s: raised when it has held for 0.3 s, i.e. at 0.8 s (not 0.7 s)
  std::vector<Nanos> raised_at;
  for (int k = 0; k <= 20; ++k) {
    const Nanos t = k * dt;
    const bool cond = (t >= 5 * dt && t < 12 * dt) || t >= 14 * dt;
    if (w.update(t, cond)) {
      raised_at.push_back(t);
      w.setMessage("raise at " + formatSeconds(t));
    }
  }
  // second episode from 1.4 s: raised again at 1.7 s; a break of 0.2 s restarts the delay
  EXPECT_EQ(raised_at, (std::vector<Nanos>{8 * dt, 17 * dt}));
  EXPECT_EQ(w.raised(), 2u);
  EXPECT_EQ(w.firstTime(), 8 * dt);
  EXPECT_EQ(w.firstMessage(), "raise at 0.800000000");
  EXPECT_EQ(w.message(), "raise at 1.700000000");
  EXPECT_TRUE(w.active());
  // active from 0.8 to 1.2 s (cleared by the false sample at 1.2 s) and from 1.7 to 2.0 s
  EXPECT_EQ(w.activeTime(), 4 * dt + 3 * dt);
  EXPECT_FALSE(w.update(21 * dt, false));
  EXPECT_FALSE(w.active());
  EXPECT_EQ(w.firstTime(), 8 * dt);  // latched

  Warning at_once("y", 0);  // no persistence: raised at the first true sample
  EXPECT_FALSE(at_once.update(0, false));
  EXPECT_EQ(at_once.firstTime(), -1);
  EXPECT_TRUE(at_once.update(10 * MS, true));
  EXPECT_FALSE(at_once.update(20 * MS, true));  // raised once per episode
  EXPECT_EQ(at_once.firstTime(), 10 * MS);
  EXPECT_THROW(Warning("z", -1), std::invalid_argument);
}

TEST(Diagnostics, StatusDueAtEveryPeriodOfSimulatedTime) {
  Diagnostics d;
  d.setPeriod(S);
  std::vector<Nanos> due;
  for (int k = 0; k <= 12; ++k)  // states every 0.3 s: the first at or after each second
    if (d.due(k * 300 * MS)) due.push_back(k * 300 * MS);
  EXPECT_EQ(due, (std::vector<Nanos>{0, 1200 * MS, 2100 * MS, 3000 * MS}));
  Diagnostics e;
  e.setPeriod(S);
  int n = 0;
  for (int k = 0; k <= 1000; ++k) n += e.due(k * 10 * MS);  // 10 ms states over 10 s: 0, 1, ..., 10 s
  EXPECT_EQ(n, 11);
  EXPECT_THROW(e.setPeriod(0), std::invalid_argument);
}

TEST(Diagnostics, StatusKeysWindowAndWarnings) {
  Diagnostics d;
  Warning& a = d.addWarning("ats_below_light_off", 30.0);
  d.addWarning("coolant_overheat", 0.0);
  EXPECT_THROW(d.addWarning("coolant_overheat", 1.0), std::invalid_argument);
  d.addStepTime(0.002);
  d.addStepTime(0.004);
  DiagStatus s0 = d.status(S, false, 0.25);
  auto v = valuesOf(s0);
  EXPECT_EQ(s0.level, DiagStatus::Ok);
  EXPECT_EQ(s0.message, "OK");
  EXPECT_EQ(v["sim_time_s"], "1.000000000");
  EXPECT_EQ(v["final"], "false");
  EXPECT_EQ(v["steps_window"], "2");
  EXPECT_EQ(v["step_compute_ms_mean"], "3");
  EXPECT_EQ(v["step_compute_ms_max"], "4");
  EXPECT_EQ(v["compute_time_s"], "0.25");
  EXPECT_EQ(v["warnings_checked"], "ats_below_light_off, coolant_overheat");
  EXPECT_EQ(v.count("warning/ats_below_light_off/first_time_s"), 0u);  // only raised ones

  for (Nanos t = 0; t <= 30 * S; t += 100 * MS)
    if (a.update(t, true)) a.setMessage("not lit off");
  d.addStepTime(0.001);
  DiagStatus s1 = d.status(31 * S, true, 0.5);
  v = valuesOf(s1);
  EXPECT_EQ(s1.level, DiagStatus::Warn);
  EXPECT_EQ(s1.message, "active: ats_below_light_off");
  EXPECT_EQ(v["final"], "true");
  EXPECT_EQ(v["steps_window"], "1");  // the window closed with the previous status
  EXPECT_EQ(v["step_compute_ms_max"], "1");
  EXPECT_EQ(v["steps_total"], "3");
  EXPECT_EQ(v["step_compute_ms_max_run"], "4");
  EXPECT_EQ(v["step_compute_ms_mean_run"], "2.33333");
  EXPECT_EQ(v["warning/ats_below_light_off/first_time_s"], "30.000000000");
  EXPECT_EQ(v["warning/ats_below_light_off/raised"], "1");
  EXPECT_EQ(v["warning/ats_below_light_off/active"], "true");
  EXPECT_EQ(v["warning/ats_below_light_off/message"], "not lit off");
  a.update(32 * S, false);
  DiagStatus s2 = d.status(32 * S, true, 0.5);
  EXPECT_EQ(s2.level, DiagStatus::Ok);
  EXPECT_EQ(s2.message, "earlier: ats_below_light_off");
  EXPECT_EQ(valuesOf(s2)["warning/ats_below_light_off/active_s"], "2.000000000");
}

TEST(Diagnostics, FormatSecondsIsExact) {
  EXPECT_EQ(formatSeconds(0), "0.000000000");
  EXPECT_EQ(formatSeconds(8115 * S + 10 * MS), "8115.010000000");
  EXPECT_EQ(formatSeconds(-1), "-0.000000001");
  EXPECT_EQ(std::strtod(formatSeconds(toNanos(0.3)).c_str(), nullptr), 0.3);
}

TEST(Diagnostics, ShippedConfigKnownAndBadValuesRejected) {
  const std::string file = sourceDir() + "/config/diagnostics.yaml";
  hbt::ParamSource src = hbt::readYamlParams(file);
  DiagnosticsParams p;
  hbt::ParamSet ps;
  p.declare(ps);
  hbt::applyParams(ps, src);  // every key of the shipped file is known and in range
  EXPECT_EQ(p.period_s, 1.0);
  ASSERT_EQ(src.file, file);
  auto rejected = [&](const std::string& key, hbt::ParamValue v) {
    hbt::ParamSource bad = src;
    bad.set(key, v);
    hbt::testing::expectRejected<DiagnosticsParams>(bad, key);
  };
  rejected("period_s", 0.0);
  rejected("period_s", std::nan(""));
  rejected("perod_s", 1.0);  // typo: unknown key
}
