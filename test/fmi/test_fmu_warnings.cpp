// The FMU participant's warnings (src/fmi/fmu_warnings.hpp, README "Naming convention of the
// project's FMUs"): which FMU variables are the participant's warnings, which are refused, the
// message of a raise; and that the importer's rule (a warning with no on-delay, fed with the
// FMU's Boolean at every state time) reproduces, raise for raise, a warning whose persistence the
// FMU holds itself: on a condition trace whose raise and clear times are known by hand.
#include "fmi/fmu_warnings.hpp"

#include <gtest/gtest.h>

#include <string>

#include "cosim/core/diagnostics.hpp"
#include "fmi/fmu_error.hpp"

namespace hbt::fmi {
namespace {

std::string var(const std::string& name, const std::string& causality, const std::string& type_elem) {
  static int vr = 0;
  const std::string variability = type_elem == "<Real/>" ? "continuous" : "discrete";
  return "<ScalarVariable name=\"" + name + "\" valueReference=\"" + std::to_string(vr++) + "\" causality=\"" + causality +
         "\" variability=\"" + variability + "\"" + (causality == "input" ? "" : " initial=\"calculated\"") + ">" +
         type_elem + "</ScalarVariable>\n";
}

ModelDescription description(const std::string& variables) {
  return ModelDescription::parse(
      "<?xml version=\"1.0\"?>\n<fmiModelDescription fmiVersion=\"2.0\" modelName=\"m\" guid=\"{g}\">\n"
      "<CoSimulation modelIdentifier=\"m\"/>\n<ModelVariables>\n" + variables +
          "</ModelVariables>\n<ModelStructure/>\n</fmiModelDescription>\n",
      "m.fmu");
}

TEST(FmuWarnings, BooleanOutputsNamedParticipantWarningNameAreItsWarningsInOrder) {
  const ModelDescription md = description(var("pack.state.fan_on", "output", "<Boolean/>") +
                                          var("pack.warning.too_hot", "output", "<Boolean/>") +
                                          var("motor.warning.overspeed", "output", "<Boolean/>") +
                                          var("pack.state.temperature_k", "output", "<Real/>") +
                                          var("pack.warning.low_soc", "output", "<Boolean/>"));
  const auto w = warningOutputs(md, "pack");
  ASSERT_EQ(w.size(), 2u);  // not the state's flag, not another participant's warning
  EXPECT_EQ(w[0].name, "too_hot");
  EXPECT_EQ(w[0].variable, "pack.warning.too_hot");
  EXPECT_EQ(w[1].name, "low_soc");
  EXPECT_TRUE(warningOutputs(md, "vehicle").empty());
}

void expectRefused(const std::string& variable, const std::string& causality, const std::string& type_elem) {
  const ModelDescription md = description(var(variable, causality, type_elem));
  try {
    warningOutputs(md, "pack");
    ADD_FAILURE() << variable << " accepted as a warning";
  } catch (const FmuError& e) {
    EXPECT_NE(std::string(e.what()).find("m.fmu"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(variable), std::string::npos) << e.what();
  }
}

TEST(FmuWarnings, AWarningNameThatIsNoBooleanOutputIsRefusedNamingFmuAndVariable) {
  expectRefused("pack.warning.too_hot", "output", "<Real/>");
  expectRefused("pack.warning.too_hot", "input", "<Boolean start=\"false\"/>");
  expectRefused("pack.warning.too.hot", "output", "<Boolean/>");
}

TEST(FmuWarnings, MessageNamesTheFmuTheVariableAndTheLogOfTheStep) {
  const WarningOutput w{"boost_limited", "engine.warning.boost_limited"};
  const std::string plain = warningMessage("/x/engine_map.fmu", w, "");
  EXPECT_NE(plain.find("/x/engine_map.fmu"), std::string::npos) << plain;
  EXPECT_NE(plain.find("engine.warning.boost_limited"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("log"), std::string::npos) << plain;
  const std::string logged = warningMessage("/x/engine_map.fmu", w, "boost low");
  EXPECT_NE(logged.find("boost low"), std::string::npos) << logged;
}

// Condition (10 ms states over 8 s): true in [0.5, 1.0) (shorter than the 1 s persistence),
// [2.0, 4.0) and [5.0, 7.5). By hand: raised at 3.0 s and 6.0 s, cleared at 4.0 s and 7.5 s.
TEST(FmuWarnings, ImporterWithoutOnDelayReproducesThePersistenceTheFmuHolds) {
  using cosim::core::Nanos;
  using cosim::core::toNanos;
  cosim::core::Warning in_fmu("w", toNanos(1.0));  // the FMU's own rule (the exported engine's)
  cosim::core::Warning imported("w", 0);           // the FMU participant's
  auto condition = [](double t) { return (t >= 0.5 && t < 1.0) || (t >= 2.0 && t < 4.0) || (t >= 5.0 && t < 7.5); };
  for (int k = 0; k <= 800; ++k) {
    const Nanos t = static_cast<Nanos>(k) * 10000000;
    in_fmu.update(t, condition(k * 0.01 + 1e-9));
    imported.update(t, in_fmu.active());  // the FMU's Boolean output at this state
    const double ts = k * 0.01;
    const bool by_hand = (ts >= 3.0 - 1e-9 && ts < 4.0 - 1e-9) || (ts >= 6.0 - 1e-9 && ts < 7.5 - 1e-9);
    ASSERT_EQ(imported.active(), by_hand) << "t = " << ts << " s";
  }
  EXPECT_EQ(imported.raised(), 2u);
  EXPECT_EQ(imported.firstTime(), toNanos(3.0));
  EXPECT_EQ(imported.activeTime(), toNanos(1.0 + 1.5));
}

}  // namespace
}  // namespace hbt::fmi
