// FmuDescription (src/fmi/export/fmu_description.hpp): what an exported FMU declares, from an
// export spec written here and the package's msg/*.msg, read back by the importer's own parser
// (ModelDescription::parse, written from the standard independently of the writer):
// - inputs are the listed fields, outputs every field of the published message (header excepted),
//   parameters scenario.<name> with start/min/max; value references 0.. in that order;
// - every Real's declared unit converts to the SI unit its field's name states with the same
//   factor and offset (A.h = 3600 A s, degC = K + 273.15, W), dimensionless without a unit;
// - the GUID is deterministic and changes with the description;
// - spec mistakes name the spec file and key (a field the message does not have, a parameter
//   that is not scenario.<name>, a malformed topic, the step size given twice);
// - an input of alternative producers <a>|<b>.<key> keeps its name (src/fmi/README.md);
// - a warning <participant>.warning.<name> (spec `warnings`) is a discrete Boolean output after the
//   messages' fields, a member of the header's <participant>_warning group; another form is refused.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "common/errors.hpp"
#include "exported_fmu_test_util.hpp"
#include "fmi/export/fmu_description.hpp"
#include "fmi/model_description.hpp"

namespace hbt::fmi::exported {
namespace {

namespace fs = std::filesystem;

std::string writeSpec(const std::string& name, const std::string& inputs, const std::string& parameter) {
  const fs::path p = fs::path(fmi::testing::freshExportDir("description", name)) / "spec.yaml";
  std::ofstream f(p);
  f << "model_identifier: battery\ndescription: test\nconfig: config/battery.yaml\n"
    << "data_files: [cell/table_file]\ninputs:\n" << inputs
    << "outputs:\n  - {topic: battery.state, type: BatteryState}\nparameters:\n" << parameter;
  return p.string();
}

const char* kInputs = "  - {topic: emachine.state, type: EMachineState, fields: [electrical_power_w]}\n";
const char* kParameter = "  - {name: scenario.ambient_temperature_c, start: 25, min: -60, max: 60, description: air}\n";

FmuDescription read(const std::string& spec) { return FmuDescription::read(spec, HBT_MSG_DIR, HBT_SOURCE_DIR); }

TEST(FmuDescription, VariablesAndUnitsReadBackByTheImporter) {
  const FmuDescription d = read(writeSpec("ok", kInputs, kParameter));
  const ModelDescription md = ModelDescription::parse(d.modelDescriptionXml(), "battery.fmu");
  EXPECT_EQ(md.guid(), d.guid());
  EXPECT_EQ(md.defaultExperiment().step_size_s.value_or(0.0), 0.01);  // cosim/macro_step_s of battery.yaml
  ASSERT_EQ(md.variables().size(), 1u + 40u + 1u);  // 1 input, BatteryState's 40 fields, 1 parameter
  EXPECT_EQ(md.variables()[0].name, "emachine.state.electrical_power_w");
  EXPECT_EQ(md.variables()[0].causality, Causality::kInput);
  EXPECT_EQ(md.variables()[1].name, "battery.state.terminal_voltage_v");  // the .msg's first field
  EXPECT_EQ(md.variables()[1].description.substr(0, 3), "[V]");
  EXPECT_EQ(md.variables().back().causality, Causality::kParameter);
  EXPECT_EQ(md.variables().back().max.value_or(0.0), 60.0);
  for (std::size_t i = 0; i < md.variables().size(); ++i) {
    const ScalarVariable& v = md.variables()[i];
    EXPECT_EQ(v.value_reference, i);
    if (v.type != VarType::kReal) continue;
    const FieldUnit field = unitOfName(v.name.substr(v.name.rfind('.') + 1));
    const UnitConversion c = md.unitToSi(v, field.si);  // throws on another dimension
    EXPECT_EQ(c.factor, field.factor) << v.name;
    EXPECT_EQ(c.offset, field.offset) << v.name;
  }
  EXPECT_EQ(md.variable("battery.state.charge_throughput_ah").unit, "A.h");
  EXPECT_EQ(md.variable("scenario.ambient_temperature_c").unit, "degC");
  EXPECT_EQ(md.variable("battery.state.soc").unit, "");
  EXPECT_EQ(md.variable("battery.state.request_limited").type, VarType::kBoolean);
}

TEST(FmuDescription, GuidIsDeterministicAndFollowsTheDescription) {
  const std::string a = read(writeSpec("a", kInputs, kParameter)).guid();
  EXPECT_EQ(read(writeSpec("a", kInputs, kParameter)).guid(), a);
  const std::string more = std::string(kInputs) + "  - {topic: vehicle.state, type: VehicleState, fields: [speed_m_s]}\n";
  EXPECT_NE(read(writeSpec("b", more, kParameter)).guid(), a);
}

TEST(FmuDescription, SpecMistakesNameFileAndKey) {
  const std::string bad_field = writeSpec("field", "  - {topic: emachine.state, type: EMachineState, fields: [power_w]}\n", kParameter);
  try {
    read(bad_field);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string w = e.what();
    EXPECT_NE(w.find(bad_field), std::string::npos) << w;
    EXPECT_NE(w.find("no field power_w in hybrid_bus_twin/EMachineState"), std::string::npos) << w;
  }
  const std::string bad_param = writeSpec("param", kInputs, "  - {name: ambient, start: 1, min: 0, max: 2, description: x}\n");
  try {
    read(bad_param);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a scenario.<name>"), std::string::npos) << e.what();
  }
}

TEST(FmuDescription, WarningsAreDiscreteBooleanOutputsNamedByTheConvention) {
  const std::string warning = "warnings:\n  - {name: battery.warning.hot, description: too hot}\n";
  const FmuDescription d = read(writeSpec("warning", kInputs, std::string(kParameter) + warning));
  const ModelDescription md = ModelDescription::parse(d.modelDescriptionXml(), "battery.fmu");
  ASSERT_EQ(md.variables().size(), 1u + 40u + 1u + 1u);
  const ScalarVariable& w = md.variables()[41];  // after the input and BatteryState's 40 fields
  EXPECT_EQ(w.name, "battery.warning.hot");
  EXPECT_EQ(w.type, VarType::kBoolean);
  EXPECT_EQ(w.causality, Causality::kOutput);
  EXPECT_EQ(w.variability, Variability::kDiscrete);
  EXPECT_EQ(w.description, "too hot");
  EXPECT_NE(d.variablesHeader().find("  struct {\n    bool hot = false;\n  } battery_warning;"), std::string::npos)
      << d.variablesHeader();
  for (const char* bad : {"battery.hot", "battery.warning.too.hot", "warning.hot", "battery.warning."}) {
    const std::string spec = writeSpec("bad_warning", kInputs, std::string(kParameter) + "warnings:\n  - {name: \"" + bad +
                                                                "\", description: x}\n");
    try {
      read(spec);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("warnings/") + bad), std::string::npos) << e.what();
    }
  }
}

// An input of alternative producers (the engine's command: ems|vehicle) keeps its name, and its
// C++ group in the binary's header joins them with _or_; a malformed topic or a step size given
// both by the config (cosim/macro_step_s) and the spec (step_size_s) names the spec and key.
TEST(FmuDescription, AlternativeProducersAndTheStepSize) {
  const std::string alt = "  - {topic: ems|vehicle.engine_command, type: EngineCommand, fields: [torque_request_nm]}\n";
  const FmuDescription d = read(writeSpec("alt", alt, kParameter));
  EXPECT_EQ(d.variables[0].name, "ems|vehicle.engine_command.torque_request_nm");
  EXPECT_NE(d.variablesHeader().find("} ems_or_vehicle_engine_command;"), std::string::npos);
  const ModelDescription md = ModelDescription::parse(d.modelDescriptionXml(), "battery.fmu");
  EXPECT_EQ(md.variable("ems|vehicle.engine_command.torque_request_nm").unit, "N.m");
  for (const char* topic : {"ems|.engine_command", "|vehicle.engine_command", "vehicle.engine|command", "vehicle.a.b"}) {
    const std::string spec = writeSpec("topic", std::string("  - {topic: \"") + topic + "\", type: EngineCommand, fields: [torque_request_nm]}\n", kParameter);
    try {
      read(spec);
      ADD_FAILURE() << topic << ": no error";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("is not <producer>.<key>"), std::string::npos) << e.what();
    }
  }
  const std::string twice = writeSpec("step", kInputs, std::string(kParameter) + "step_size_s: 0.01\n");
  try {
    read(twice);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("step_size_s"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("given twice"), std::string::npos) << e.what();
  }
}

TEST(FmuDescription, FmiUnitNames) {
  EXPECT_EQ(fmiUnitName(unitOfName("x_ah")), "A.h");
  EXPECT_EQ(fmiUnitName(unitOfName("x_c")), "degC");
  EXPECT_EQ(fmiUnitName(unitOfName("x_percent")), "%");
  EXPECT_EQ(fmiUnitName(unitOfName("x_ppm")), "ppm");
  EXPECT_EQ(fmiUnitName(unitOfName("x_w")), "W");
  EXPECT_EQ(fmiUnitName(unitOfName("soc")), "");
}

}  // namespace
}  // namespace hbt::fmi::exported
