// CsInstance on the test FMU thermal_mass (C dT/dt = Q - G (T - T_amb), test/fmi/fmus):
// - each communication step against the exact solution for inputs held over the step,
//   T(t+h) = T_amb + Q/G + (T(t) - T_amb - Q/G) exp(-G h / C), with C and G read here from the
//   FMU's resources file, and the limit G = 0 (insulated: T rises by Q h / C);
// - the resources location reaches the FMU (a changed C in the extracted resources changes the
//   time constant as the exact solution says; a missing file fails instantiation);
// - the FMU's log messages reach the sink, formatted; errors name FMU, call or variable, time;
// - two instances of one FMU are independent and bit-identical for the same inputs;
// - batched calls (one fmi2Set/Get over a value-reference vector) give the exact solution and
//   the single calls' values bit for bit; a failing batched call names every variable of its
//   batch, a NaN in a batched read names its variable.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "common/errors.hpp"
#include "fmi/cs_instance.hpp"
#include "fmi/fmu_error.hpp"
#include "fmi_test_util.hpp"

namespace hbt::fmi {
namespace {

namespace fs = std::filesystem;
using testing::expectThrowWith;
using testing::testFmu;

// key -> value of a thermal_mass.txt parameter file
std::map<std::string, double> readParameters(const fs::path& file) {
  std::ifstream f(file);
  std::map<std::string, double> p;
  std::string line;
  while (std::getline(f, line)) {
    std::istringstream s(line);
    std::string key;
    double value;
    if (line.empty() || line[0] == '#' || !(s >> key >> value)) continue;
    p[key] = value;
  }
  return p;
}

struct LogLine {
  std::string instance, category, message;
  fmi2Status status;
};

// an instance of the thermal mass, initialised with T_start [degC] at t = 0
struct ThermalMass {
  std::vector<LogLine> log;
  CsInstance fmu;
  VariableRef T, Q, T_amb, steps, insulated;
  ThermalMass(std::shared_ptr<const LoadedFmu> loaded, const std::string& name, double T_start_degC)
      : fmu(loaded, name, [this](const std::string& i, fmi2Status s, const std::string& c,
                                 const std::string& m) { log.push_back({i, c, m, s}); }),
        T(fmu.gettable("T", VarType::kReal)),
        Q(fmu.settable("Q", VarType::kReal)),
        T_amb(fmu.settable("T_amb", VarType::kReal)),
        steps(fmu.gettable("steps", VarType::kInteger)),
        insulated(fmu.settable("insulated", VarType::kBoolean)) {
    fmu.setupExperiment(1e-6, 0.0, 3600.0);
    fmu.setReal(fmu.settable("T_start", VarType::kReal), T_start_degC);
    fmu.enterInitializationMode();
    fmu.exitInitializationMode();
  }
};

std::shared_ptr<const LoadedFmu> load(const std::string& name, const std::string& dir) {
  return LoadedFmu::load(testFmu(name), dir, InterfaceType::kCoSimulation);
}

// exact T [K] after h [s] from T0 [K] with Q [W], T_amb [K], C [J/K], G [W/K] held
double exactT(double T0, double Q, double T_amb, double C, double G, double h) {
  const double T_inf = T_amb + Q / G;
  return T_inf + (T0 - T_inf) * std::exp(-G * h / C);
}

TEST(CsInstance, EachStepMatchesTheExactExponential) {
  const auto p = readParameters(fs::path(HBT_TEST_FMU_SOURCE_DIR) / "resources/thermal_mass.txt");
  const double C = p.at("heat_capacity_J_per_K"), G = p.at("conductance_W_per_K");
  auto loaded = load("thermal_mass", testing::freshDir("x"));
  ThermalMass m(loaded, "tm", 35.0);
  const ModelDescription& md = loaded->modelDescription();
  const UnitConversion T_si = md.unitToSi(*m.T.variable, si::kelvin());
  const UnitConversion Q_si = md.unitToSi(*m.Q.variable, si::watt());
  double T_K = T_si.toSi(m.fmu.getReal(m.T));
  EXPECT_DOUBLE_EQ(T_K, 308.15);
  const double h = 7.5;  // [s]
  double max_error_K = 0.0;
  for (int k = 0; k < 40; ++k) {
    const double Q_W = (k % 3 == 0) ? 1500.0 : -400.0;
    const double T_amb_K = 263.15 + 2.0 * k;
    m.fmu.setReal(m.Q, Q_si.fromSi(Q_W));
    m.fmu.setReal(m.T_amb, T_si.fromSi(T_amb_K));
    m.fmu.doStep(h);
    const double expected = exactT(T_K, Q_W, T_amb_K, C, G, h);
    T_K = T_si.toSi(m.fmu.getReal(m.T));
    max_error_K = std::max(max_error_K, std::abs(T_K - expected));
    ASSERT_NEAR(T_K, expected, 1e-9) << "step " << k;
  }
  std::printf("max |T - T_exact| = %.3g K over 40 steps\n", max_error_K);
  EXPECT_EQ(m.fmu.getInteger(m.steps), 40);
  EXPECT_DOUBLE_EQ(m.fmu.time(), 300.0);
}

TEST(CsInstance, InsulatedMassRisesByQhOverC) {
  const auto p = readParameters(fs::path(HBT_TEST_FMU_SOURCE_DIR) / "resources/thermal_mass.txt");
  ThermalMass m(load("thermal_mass", testing::freshDir("x")), "tm", 20.0);
  m.fmu.setBoolean(m.insulated, true);
  EXPECT_TRUE(m.fmu.getBoolean(m.insulated));
  m.fmu.setReal(m.Q, 2.0);      // kW
  m.fmu.setReal(m.T_amb, -30);  // no effect without conductance
  m.fmu.doStep(90.0);
  EXPECT_NEAR(m.fmu.getReal(m.T), 20.0 + 2000.0 * 90.0 / p.at("heat_capacity_J_per_K"), 1e-10);
}

TEST(CsInstance, ResourcesLocationReachesTheFmu) {
  EXPECT_EQ(fileUri("/tmp/a b/100%/resources"), "file:///tmp/a%20b/100%25/resources");
  // a directory name that must be percent-encoded; the FMU decodes it and reads its file there
  auto loaded = load("thermal_mass", testing::freshDir("with space %"));
  EXPECT_NE(loaded->resourceUri().find("%20"), std::string::npos) << loaded->resourceUri();
  const fs::path res = fs::path(loaded->directory()) / "resources/thermal_mass.txt";
  { std::ofstream(res) << "heat_capacity_J_per_K 3000\nconductance_W_per_K 60\n"; }
  ThermalMass m(loaded, "tm", 80.0);
  m.fmu.setReal(m.T_amb, 20.0);
  m.fmu.doStep(50.0);  // tau = 3000 / 60 = 50 s: the excess falls to 1/e
  EXPECT_NEAR(m.fmu.getReal(m.T), 20.0 + 60.0 * std::exp(-1.0), 1e-9);
  ASSERT_FALSE(m.log.empty());
  EXPECT_NE(m.log[0].message.find(res.string()), std::string::npos) << m.log[0].message;

  fs::remove(res);  // without its file the FMU refuses to instantiate
  std::vector<std::string> messages;
  expectThrowWith<FmuError>(
      [&] { CsInstance c(loaded, "tm2", [&](auto&, fmi2Status, auto&, const std::string& msg) {
              messages.push_back(msg); }); },
      {"thermal_mass.fmu", "fmi2Instantiate", "'tm2'", "returned NULL"});
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0], "cannot open " + res.string());
}

TEST(CsInstance, LogSinkReceivesFormattedMessages) {
  auto loaded = load("thermal_mass", testing::freshDir("x"));
  std::vector<LogLine> log;
  {
    ThermalMass m(loaded, "mass_1", 20.0);
    m.fmu.doStep(1.0);
    log = m.log;
    ASSERT_EQ(log.size(), 1u);
    EXPECT_EQ(log[0].instance, "mass_1");
    EXPECT_EQ(log[0].category, "info");
    EXPECT_EQ(log[0].status, fmi2OK);
    EXPECT_EQ(log[0].message, "parameters read from " + loaded->directory() + "/resources/thermal_mass.txt");
    m.fmu.doStep(1.0);
    EXPECT_EQ(m.log.size(), 1u);  // the FMU logs nothing per step
  }
}

TEST(CsInstance, TerminateMessageAtDestructionIsFormatted) {
  auto loaded = load("thermal_mass", testing::freshDir("x"));
  std::vector<std::string> messages;
  {
    CsInstance c(loaded, "tm", [&](auto&, fmi2Status, auto&, const std::string& m) { messages.push_back(m); });
    c.setupExperiment(std::nullopt, 0.0, std::nullopt);
    c.enterInitializationMode();
    c.exitInitializationMode();
  }
  ASSERT_EQ(messages.size(), 2u);
  EXPECT_EQ(messages[1], "terminated (no error)");  // "%s" filled from the FMU's argument
}

TEST(CsInstance, ErrorStatusNamesFmuCallAndTime) {
  auto loaded = load("error_at_2s", testing::freshDir("x"));
  ThermalMass m(loaded, "failing", 20.0);
  for (int k = 0; k < 4; ++k) m.fmu.doStep(0.5);
  expectThrowWith<ModelDivergence>([&] { m.fmu.doStep(0.5); },
                                   {"error_at_2s.fmu", "'failing'", "fmi2DoStep", "fmi2Error", "t = 2 s"});
  ASSERT_EQ(m.log.size(), 2u);
  EXPECT_EQ(m.log[1].status, fmi2Error);
  EXPECT_EQ(m.log[1].message, "deliberate failure (test variant error_at_2s)");
  expectThrowWith<ModelDivergence>([&] { m.fmu.doStep(0.5); }, {"fmi2DoStep", "after an error"});
}

TEST(CsInstance, NanOutputNamesVariableAndTime) {
  ThermalMass m(load("nan_at_2s", testing::freshDir("x")), "nan", 20.0);
  for (int k = 0; k < 4; ++k) {
    m.fmu.doStep(0.5);
    EXPECT_TRUE(std::isfinite(m.fmu.getReal(m.T)));
  }
  m.fmu.doStep(0.5);
  expectThrowWith<ModelDivergence>([&] { m.fmu.getReal(m.T); },
                                   {"nan_at_2s.fmu", "variable 'T'", "NaN", "t = 2.5 s"});
}

TEST(CsInstance, WrongCausalityTypeAndStopTimeRejected) {
  ThermalMass m(load("thermal_mass", testing::freshDir("x")), "tm", 20.0);
  expectThrowWith<FmuError>([&] { m.fmu.settable("T", VarType::kReal); },
                            {"thermal_mass.fmu", "'T'", "causality output"});
  expectThrowWith<FmuError>([&] { m.fmu.settable("time", VarType::kReal); }, {"'time'", "causality independent"});
  expectThrowWith<FmuError>([&] { m.fmu.gettable("steps", VarType::kReal); }, {"'steps'", "Integer, not Real"});
  expectThrowWith<FmuError>([&] { m.fmu.gettable("T_oil", VarType::kReal); }, {"'T_oil'"});
  expectThrowWith<ModelDivergence>([&] { m.fmu.setReal(m.fmu.settable("T_start", VarType::kReal), 5.0); },
                                   {"'T_start'", "fixed parameter", "t = 0 s"});
  m.fmu.doStep(3000.0);
  expectThrowWith<ModelDivergence>([&] { m.fmu.doStep(601.0); }, {"fmi2DoStep", "stop time", "t = 3000 s"});
}

TEST(CsInstance, TwoInstancesAreIndependentAndBitIdentical) {
  auto loaded = load("thermal_mass", testing::freshDir("x"));
  ThermalMass a(loaded, "a", 25.0), b(loaded, "b", 25.0), c(loaded, "c", 90.0);
  for (int k = 0; k < 50; ++k) {  // interleaved: c's different inputs between a's and b's calls
    const double Q_kW = 0.1 * k - 2.0, T_amb = 5.0 + 0.3 * k;
    a.fmu.setReal(a.Q, Q_kW);
    c.fmu.setReal(c.Q, -Q_kW);
    a.fmu.setReal(a.T_amb, T_amb);
    b.fmu.setReal(b.Q, Q_kW);
    c.fmu.setReal(c.T_amb, -T_amb);
    b.fmu.setReal(b.T_amb, T_amb);
    a.fmu.doStep(1.25);
    c.fmu.doStep(1.25);
    b.fmu.doStep(1.25);
    ASSERT_EQ(a.fmu.getReal(a.T), b.fmu.getReal(b.T)) << "step " << k;  // bit for bit
    ASSERT_NE(a.fmu.getReal(a.T), c.fmu.getReal(c.T));
  }
  EXPECT_EQ(a.fmu.getInteger(a.steps), 50);
  EXPECT_EQ(c.fmu.getInteger(c.steps), 50);
}

TEST(CsInstance, BatchedCallsGiveTheExactSolutionAndTheSingleCallsBitForBit) {
  const auto p = readParameters(fs::path(HBT_TEST_FMU_SOURCE_DIR) / "resources/thermal_mass.txt");
  const double C = p.at("heat_capacity_J_per_K"), G = p.at("conductance_W_per_K");
  auto loaded = load("thermal_mass", testing::freshDir("x"));
  ThermalMass single(loaded, "single", 35.0), batched(loaded, "batched", 35.0);
  const VariableBatch in = batched.fmu.batch({batched.Q, batched.T_amb}, VarType::kReal);
  const VariableBatch out = batched.fmu.batch({batched.T, batched.T_amb}, VarType::kReal);
  const VariableBatch steps = batched.fmu.batch({batched.steps}, VarType::kInteger);
  const VariableBatch flags = batched.fmu.batch({batched.insulated}, VarType::kBoolean);
  double T_degC = 35.0;
  for (int k = 0; k < 20; ++k) {
    const double Q_kW = k % 2 ? 1.5 : -0.25, T_amb_degC = -10.0 + 3.0 * k, h = 4.0;
    const double u[2] = {Q_kW, T_amb_degC};
    batched.fmu.setReals(in, u);
    single.fmu.setReal(single.Q, Q_kW);
    single.fmu.setReal(single.T_amb, T_amb_degC);
    batched.fmu.doStep(h);
    single.fmu.doStep(h);
    double y[2] = {0.0, 0.0};
    batched.fmu.getReals(out, y);
    ASSERT_EQ(y[0], single.fmu.getReal(single.T)) << "step " << k;  // bit for bit
    ASSERT_EQ(y[1], T_amb_degC);
    // exact, in K and W (the FMU's degC and kW): offsets cancel in the differences
    ASSERT_NEAR(y[0], exactT(T_degC, 1000.0 * Q_kW, T_amb_degC, C, G, h), 1e-9) << "step " << k;
    T_degC = y[0];
  }
  int n = 0;
  batched.fmu.getIntegers(steps, &n);
  EXPECT_EQ(n, 20);
  const fmi2Boolean on = fmi2True;
  batched.fmu.setBooleans(flags, &on);
  EXPECT_TRUE(batched.fmu.getBoolean(batched.insulated));
  batched.fmu.setReals(batched.fmu.batch({}, VarType::kReal), nullptr);  // empty: nothing called
}

TEST(CsInstance, AFailingBatchedCallNamesEveryVariableOfItsBatch) {
  ThermalMass m(load("set_error_at_2s", testing::freshDir("x")), "failing", 20.0);
  const VariableBatch in = m.fmu.batch({m.Q, m.T_amb}, VarType::kReal);
  const double u[2] = {1.0, 10.0};
  for (int k = 0; k < 4; ++k) {
    m.fmu.setReals(in, u);
    m.fmu.doStep(0.5);
  }
  expectThrowWith<ModelDivergence>([&] { m.fmu.setReals(in, u); },
                                   {"set_error_at_2s.fmu", "'failing'", "fmi2SetReal of 2 variables 'Q', 'T_amb'",
                                    "fmi2Error", "t = 2 s"});
  expectThrowWith<ModelDivergence>([&] { m.fmu.doStep(0.5); }, {"fmi2DoStep", "after an error"});
}

TEST(CsInstance, BatchedReadNamesTheNanVariableAndBatchesCheckTheirTypes) {
  ThermalMass m(load("nan_at_2s", testing::freshDir("x")), "nan", 20.0);
  const VariableBatch out = m.fmu.batch({m.T_amb, m.T}, VarType::kReal);
  double y[2];
  for (int k = 0; k < 5; ++k) m.fmu.doStep(0.5);
  expectThrowWith<ModelDivergence>([&] { m.fmu.getReals(out, y); }, {"variable 'T'", "NaN", "t = 2.5 s"});
  expectThrowWith<FmuError>([&] { m.fmu.batch({m.T, m.steps}, VarType::kReal); }, {"'steps'", "Integer, not Real"});
  const VariableBatch fixed = m.fmu.batch({m.Q, m.fmu.settable("T_start", VarType::kReal)}, VarType::kReal);
  expectThrowWith<ModelDivergence>([&] { m.fmu.setReals(fixed, y); }, {"'T_start'", "fixed parameter"});
}

}  // namespace
}  // namespace hbt::fmi
