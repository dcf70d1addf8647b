// MeInstance on the Model Exchange test FMU switched_decay (test/fmi/fmus): dx/dt = -k x + b,
// a time event at t_switch (b1 -> b2), a state event whenever x falls through x_threshold
// (x := x_reset), one step event. Against the exact piecewise solution computed here from the
// FMU's declared start values:
//   x(t) = b/k + (x(t0) - b/k) exp(-k (t - t0)) between events, the crossing times
//   t_c = t0 + ln((x(t0) - b/k) / (x_threshold - b/k)) / k,
// at every macro-step end, for macro steps that fall on, between and across the events.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/errors.hpp"
#include "fmi/fmu_error.hpp"
#include "fmi/cs_instance.hpp"
#include "fmi/me_instance.hpp"
#include "fmi_test_util.hpp"

namespace hbt::fmi {
namespace {

using testing::expectThrowWith;
using testing::testFmu;

struct Parameters {
  double x0, k, b1, b2, t_switch, x_threshold, x_reset;
};

Parameters declared(const ModelDescription& md) {
  const auto start = [&](const char* name) { return std::stod(md.variable(name).start.value()); };
  return {start("x"), start("k"), start("b1"), start("b2"), start("t_switch"), start("x_threshold"),
          start("x_reset")};
}

struct Exact {
  double x;
  int resets;
};

Exact exactAt(const Parameters& p, double t) {
  const double eq1 = p.b1 / p.k, eq2 = p.b2 / p.k;
  if (t <= p.t_switch) return {eq1 + (p.x0 - eq1) * std::exp(-p.k * t), 0};
  double t0 = p.t_switch, x_0 = eq1 + (p.x0 - eq1) * std::exp(-p.k * p.t_switch);
  int resets = 0;
  for (;;) {
    const double t_cross = t0 + std::log((x_0 - eq2) / (p.x_threshold - eq2)) / p.k;
    if (t_cross > t) break;
    ++resets;
    t0 = t_cross;
    x_0 = p.x_reset;
  }
  return {eq2 + (x_0 - eq2) * std::exp(-p.k * (t - t0)), resets};
}

std::unique_ptr<MeInstance> initialised(std::shared_ptr<const LoadedFmu> fmu) {
  auto me = std::make_unique<MeInstance>(fmu, "decay", nullptr, 1e-10, 1e-12, 100000);
  me->setupExperiment(1e-10, 0.0, 6.0);
  me->enterInitializationMode();
  me->exitInitializationMode();
  return me;
}

TEST(MeInstance, ReadsStatesAndIndicatorsFromTheDescription) {
  auto fmu = LoadedFmu::load(testFmu("switched_decay"), testing::freshDir("x"), InterfaceType::kModelExchange);
  EXPECT_EQ(fmu->modelDescription().numberOfContinuousStates(), 1);
  EXPECT_EQ(fmu->modelDescription().numberOfEventIndicators(), 1);
  expectThrowWith<FmuError>(
      [&] { LoadedFmu::load(testFmu("switched_decay"), testing::freshDir("y"), InterfaceType::kCoSimulation); },
      {"switched_decay.fmu", "no <CoSimulation>"});
  expectThrowWith<FmuError>([&] { CsInstance cs(fmu, "cs", nullptr); }, {"loaded as ModelExchange"});
}

TEST(MeInstance, TimeStateAndStepEventsMatchTheExactSolution) {
  auto fmu = LoadedFmu::load(testFmu("switched_decay"), testing::freshDir("x"), InterfaceType::kModelExchange);
  const Parameters p = declared(fmu->modelDescription());
  // on the time event (0.5), between events (0.3), one step across all events (6)
  for (const double h : {0.5, 0.3, 6.0}) {
    SCOPED_TRACE("macro step " + std::to_string(h) + " s");
    auto me = initialised(fmu);
    const VariableRef x = me->gettable("x", VarType::kReal);
    const VariableRef resets = me->gettable("resets", VarType::kInteger);
    EXPECT_EQ(me->getReal(x), p.x0);
    const int n = static_cast<int>(std::lround(6.0 / h));
    double max_error = 0.0;
    for (int i = 1; i <= n; ++i) {
      me->doStep(h);
      const Exact e = exactAt(p, i * h);
      max_error = std::max(max_error, std::abs(me->getReal(x) - e.x));
      ASSERT_NEAR(me->getReal(x), e.x, 1e-7) << "t = " << i * h;
      ASSERT_EQ(me->getInteger(resets), e.resets) << "t = " << i * h;
      ASSERT_EQ(me->states().at(0), me->getReal(x));
    }
    EXPECT_EQ(exactAt(p, 6.0).resets, 5);  // the scenario has the events it is meant to test
    EXPECT_EQ(me->timeEvents(), 1);
    EXPECT_EQ(me->stateEvents(), 5);
    EXPECT_EQ(me->stepEvents(), 1);
    EXPECT_EQ(me->getInteger(me->gettable("step_events", VarType::kInteger)), 1);
    EXPECT_DOUBLE_EQ(me->time(), 6.0);
    std::printf("macro step %.1f s: max |x - x_exact| = %.3g\n", h, max_error);
  }
}

TEST(MeInstance, ParameterChangesTheDynamicsAsTheExactSolutionSays) {
  auto fmu = LoadedFmu::load(testFmu("switched_decay"), testing::freshDir("x"), InterfaceType::kModelExchange);
  Parameters p = declared(fmu->modelDescription());
  p.k = 1.25;
  MeInstance me(fmu, "decay", nullptr, 1e-10, 1e-12, 100000);
  me.setupExperiment(std::nullopt, 0.0, std::nullopt);
  me.setReal(me.settable("k", VarType::kReal), p.k);
  me.enterInitializationMode();
  me.exitInitializationMode();
  me.doStep(4.0);
  const Exact e = exactAt(p, 4.0);
  EXPECT_NEAR(me.getReal(me.gettable("x", VarType::kReal)), e.x, 1e-7);
  EXPECT_EQ(me.getInteger(me.gettable("resets", VarType::kInteger)), e.resets);
  EXPECT_GT(e.resets, 0);
}

}  // namespace
}  // namespace hbt::fmi
