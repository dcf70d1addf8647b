// ModelDescription::parse: what an FMI 2.0 modelDescription.xml declares (against the text of
// the test FMU's own file, read independently here), and each rejection naming the FMU file
// and the element, attribute or variable at fault.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "fmi/fmu_error.hpp"
#include "fmi/model_description.hpp"
#include "fmi_test_util.hpp"

namespace hbt::fmi {
namespace {

// the test FMU's template with its fmiVersion filled in
std::string thermalMassXml(const std::string& version = "2.0") {
  std::ifstream f(std::string(HBT_TEST_FMU_SOURCE_DIR) + "/thermal_mass.xml.in");
  std::stringstream s;
  s << f.rdbuf();
  return std::regex_replace(s.str(), std::regex("@FMI_VERSION@"), version);
}

// xml with the first occurrence of `from` replaced by `to` (the case must change the text)
std::string edited(const std::string& from, const std::string& to) {
  std::string xml = thermalMassXml();
  const auto at = xml.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return xml.replace(at, from.size(), to);
}

TEST(ModelDescription, ReadsWhatTheThermalMassDeclares) {
  const ModelDescription md = ModelDescription::parse(thermalMassXml(), "tm.fmu");
  EXPECT_EQ(md.modelName(), "thermal_mass");
  EXPECT_EQ(md.guid(), "{4f1c2a7e-hbt-thermal-mass-1}");
  EXPECT_EQ(md.coSimulationId().value_or(""), "thermal_mass");
  EXPECT_FALSE(md.modelExchangeId().has_value());
  const DefaultExperiment& x = md.defaultExperiment();
  EXPECT_EQ(x.start_time_s.value_or(-1), 0.0);
  EXPECT_EQ(x.stop_time_s.value_or(-1), 3600.0);
  EXPECT_EQ(x.tolerance.value_or(-1), 1e-6);
  EXPECT_EQ(x.step_size_s.value_or(-1), 0.5);
  ASSERT_EQ(md.units().count("degC"), 1u);
  EXPECT_EQ(md.units().at("degC").offset, 273.15);
  EXPECT_EQ(md.units().at("degC").dimension.str(), "K");
  EXPECT_EQ(md.units().at("kW").factor, 1000.0);
  EXPECT_EQ(md.units().at("kW").dimension.str(), "kg.m2.s-3");
  EXPECT_EQ(md.types().at("CelsiusTemperature").unit, "degC");
  ASSERT_EQ(md.variables().size(), 7u);

  const ScalarVariable& T = md.variable("T");
  EXPECT_EQ(T.value_reference, 0u);
  EXPECT_EQ(T.causality, Causality::kOutput);
  EXPECT_EQ(T.variability, Variability::kContinuous);
  EXPECT_EQ(T.type, VarType::kReal);
  EXPECT_EQ(T.declared_type, "CelsiusTemperature");
  EXPECT_EQ(T.unit, "degC");  // from the declared type
  EXPECT_FALSE(T.start.has_value());
  const ScalarVariable& T_start = md.variable("T_start");
  EXPECT_EQ(T_start.causality, Causality::kParameter);
  EXPECT_EQ(T_start.variability, Variability::kFixed);
  EXPECT_EQ(T_start.start.value_or(""), "20");
  EXPECT_EQ(md.variable("Q").unit, "kW");
  EXPECT_EQ(md.variable("steps").type, VarType::kInteger);
  EXPECT_EQ(md.variable("insulated").type, VarType::kBoolean);
  EXPECT_EQ(md.variable("insulated").value_reference, 5u);
}

TEST(ModelDescription, RejectsOtherFmiVersionsNamingThem) {
  testing::expectThrowWith<FmuError>([] { ModelDescription::parse(thermalMassXml("1.0"), "a.fmu"); },
                                     {"a.fmu", "fmiVersion", "\"1.0\""});
  testing::expectThrowWith<FmuError>([] { ModelDescription::parse(thermalMassXml("3.0"), "a.fmu"); },
                                     {"a.fmu", "fmiVersion", "\"3.0\""});
}

TEST(ModelDescription, RejectsMalformedXml) {
  testing::expectThrowWith<FmuError>(
      [] { ModelDescription::parse(edited("</ModelVariables>", ""), "a.fmu"); },
      {"a.fmu", "modelDescription.xml", "malformed XML"});
}

TEST(ModelDescription, RejectsMissingPartsNamingThem) {
  const auto reject = [](const std::string& xml, std::initializer_list<std::string> frags) {
    testing::expectThrowWith<FmuError>([&] { ModelDescription::parse(xml, "a.fmu"); }, frags);
  };
  reject(edited("guid=", "uuid="), {"a.fmu", "<fmiModelDescription>", "guid"});
  reject(edited("<CoSimulation modelIdentifier=\"thermal_mass\"", "<CoSimulation"),
         {"<CoSimulation>", "modelIdentifier"});
  reject(edited("<CoSimulation", "<NoSimulation"), {"neither <CoSimulation> nor <ModelExchange>"});
  reject(edited("causality=\"output\"", "causality=\"result\""),
         {"variable 'T'", "causality \"result\""});
  reject(edited("variability=\"fixed\"", "variability=\"frozen\""),
         {"variable 'T_start'", "variability \"frozen\""});
  reject(edited("<Real unit=\"kW\"", "<Real unit=\"MW\""), {"variable 'Q'", "unit \"MW\""});
  reject(edited("<Real declaredType=\"CelsiusTemperature\"/>", "<Real declaredType=\"Kelvin\"/>"),
         {"variable 'T'", "declaredType \"Kelvin\""});
  reject(edited("<Integer/>", "<Complex/>"), {"variable 'steps'", "<Complex>"});
  reject(edited("valueReference=\"4\"", ""), {"variable 'steps'", "valueReference"});
  reject(edited("valueReference=\"4\"", "valueReference=\"four\""), {"variable 'steps'", "\"four\""});
  reject(edited("name=\"steps\"", "name=\"T\""), {"variable 'T'", "declared twice"});
  reject(edited("stopTime=\"3600\"", "stopTime=\"1h\""), {"<DefaultExperiment>", "stopTime", "\"1h\""});
}

TEST(ModelDescription, UnknownVariableNamed) {
  const ModelDescription md = ModelDescription::parse(thermalMassXml(), "tm.fmu");
  testing::expectThrowWith<FmuError>([&] { md.variable("T_oil"); }, {"tm.fmu", "'T_oil'"});
}

}  // namespace
}  // namespace hbt::fmi
