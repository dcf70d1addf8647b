// resolveMapping (src/fmi/fmu_mapping.hpp): the mapping between an FMU's variables and a
// participant's message fields, on modelDescription.xml texts written here and on the test FMU
// thermal_mass (test/fmi/fmus):
// - the naming convention alone (no mapping file) binds <producer>.<key>.<field> inputs,
//   <participant>.<key>.<field> outputs and scenario.<name> parameters; an input of alternative
//   producers <a>|<b>.<key>.<field> to the first of them that runs;
// - unit conversions against hand-computed values: degC <-> K (offset 273.15), kW <-> W (1000),
//   a parameter given in SI (K) set in the FMU's degC, /scenario/ambient_temperature_c (degC by
//   its name) into a parameter declared in K; the field's own unit declared by the FMU passes bit
//   for bit;
// - every rejection names what is wrong: an output field neither mapped nor declared not
//   provided, wrong causality, wrong type, incompatible unit, a topic not in the scenario, a
//   not_provided without its reason, a scenario parameter the scenario does not set, Model
//   Exchange without CVODE tolerances, a parameter outside the FMU's min/max (in its unit) or of
//   the wrong type.
#include <gtest/gtest.h>

#include <sstream>

#include "common/errors.hpp"
#include "fmi/fmu_archive.hpp"
#include "fmi/fmu_error.hpp"
#include "fmi/fmu_mapping.hpp"
#include "fmi_test_util.hpp"

namespace hbt::fmi {
namespace {

using testing::expectThrowWith;
using testing::testFmu;

MessageLayout layout(const std::string& type, const std::string& fields) {
  return MessageLayout::parse(type, "std_msgs/Header header\n" + fields);
}

/// Participant "pack" publishing state (temperature_k, power_w, steps, fan_on); producer "motor"
/// publishing state (electrical_power_w, torque_nm); /scenario/ambient_temperature_c = 5.
MappingContext context() {
  MappingContext c;
  c.participant = "pack";
  c.publishes.emplace("state", layout("t/PackState", "float64 temperature_k\nfloat64 power_w\nint32 steps\nbool fan_on\n"));
  c.produced = [](const std::string& p, const std::string& k) -> std::optional<MessageLayout> {
    if (p == "motor" && k == "state") return layout("t/MotorState", "float64 electrical_power_w\nfloat64 torque_nm\n");
    return std::nullopt;
  };
  c.scenario["ambient_temperature_c"] = 5.0;
  return c;
}

std::string var(const std::string& name, const std::string& causality, const std::string& type_elem,
                const std::string& variability = "continuous") {
  static int vr = 0;
  return "<ScalarVariable name=\"" + name + "\" valueReference=\"" + std::to_string(vr++) + "\" causality=\"" + causality +
         "\" variability=\"" + variability + "\">" + type_elem + "</ScalarVariable>\n";
}

ModelDescription description(const std::string& variables) {
  const std::string xml =
      "<?xml version=\"1.0\"?>\n<fmiModelDescription fmiVersion=\"2.0\" modelName=\"m\" guid=\"{g}\">\n"
      "<CoSimulation modelIdentifier=\"m\"/>\n<UnitDefinitions>\n"
      "<Unit name=\"degC\"><BaseUnit K=\"1\" offset=\"273.15\"/></Unit>\n"
      "<Unit name=\"K\"><BaseUnit K=\"1\"/></Unit>\n"
      "<Unit name=\"kW\"><BaseUnit kg=\"1\" m=\"2\" s=\"-3\" factor=\"1000\"/></Unit>\n"
      "<Unit name=\"W\"><BaseUnit kg=\"1\" m=\"2\" s=\"-3\"/></Unit>\n"
      "</UnitDefinitions>\n<ModelVariables>\n" + variables + "</ModelVariables>\n<ModelStructure/>\n</fmiModelDescription>\n";
  return ModelDescription::parse(xml, "m.fmu");
}

/// An FMU exported by this project's convention: every field of pack/state, one input, one scenario parameter.
std::string conventional(const std::string& extra = "") {
  return var("pack.state.temperature_k", "output", "<Real unit=\"degC\"/>") +
         var("pack.state.power_w", "output", "<Real unit=\"kW\"/>") +
         var("pack.state.steps", "output", "<Integer/>", "discrete") +
         var("pack.state.fan_on", "output", "<Boolean/>", "discrete") +
         var("motor.state.electrical_power_w", "input", "<Real unit=\"W\" start=\"0\"/>") +
         var("scenario.ambient_temperature_c", "parameter", "<Real unit=\"K\" start=\"293.15\"/>", "fixed") + extra;
}

TEST(FmuMapping, NamingConventionNeedsNoMappingFile) {
  const ModelDescription md = description(conventional());
  const ResolvedMapping r = resolveMapping(MappingSpec{}, md, context());
  EXPECT_EQ(r.interface, InterfaceType::kCoSimulation);
  ASSERT_EQ(r.outputs.size(), 4u);
  EXPECT_TRUE(r.not_provided.empty());
  // degC -> K: 20 degC is 293.15 K; kW -> W: 1.5 kW is 1500 W
  const Binding& temp = r.outputs[0];
  EXPECT_EQ(temp.variable, "pack.state.temperature_k");
  EXPECT_DOUBLE_EQ(temp.fieldFromFmu(20.0), 293.15);
  EXPECT_DOUBLE_EQ(r.outputs[1].fieldFromFmu(1.5), 1500.0);
  EXPECT_EQ(r.outputs[2].type, VarType::kInteger);
  EXPECT_EQ(r.outputs[3].type, VarType::kBoolean);
  ASSERT_EQ(r.inputs.size(), 1u);
  EXPECT_EQ(r.inputs[0].participant, "motor");
  EXPECT_DOUBLE_EQ(r.inputs[0].fmuFromField(-2500.0), -2500.0);
  // /scenario/ambient_temperature_c = 5 (degC by its name) into a parameter declared in K
  ASSERT_EQ(r.parameters.size(), 1u);
  EXPECT_DOUBLE_EQ(r.parameters[0].value_fmu, 278.15);
  EXPECT_EQ(r.parameters[0].source, "/scenario/ambient_temperature_c");
}

// An input "<a>|<b>.<key>.<field>" is fed by the first alternative that publishes the key in the
// scenario (the engine's command: ems|vehicle), never by the participant itself; by none, it keeps
// its start value.
TEST(FmuMapping, AlternativeProducersFeedAnInputFromTheFirstThatRuns) {
  const ModelDescription md = description(conventional(var("ctrl|pack|motor.state.electrical_power_w", "input", "<Real unit=\"W\" start=\"0\"/>") +
                                                       var("ctrl|other.state.electrical_power_w", "input", "<Real unit=\"W\" start=\"0\"/>")));
  MappingContext ctx = context();
  ResolvedMapping r = resolveMapping(MappingSpec{}, md, ctx);  // ctrl does not run, pack is the reader
  ASSERT_EQ(r.inputs.size(), 2u);
  EXPECT_EQ(r.inputs[1].variable, "ctrl|pack|motor.state.electrical_power_w");
  EXPECT_EQ(r.inputs[1].participant, "motor");
  EXPECT_EQ(r.inputs[1].field_name, "motor.state.electrical_power_w");
  EXPECT_EQ(r.inputs[1].field, 0u);  // MotorState's fields (the header is none): electrical_power_w, torque_nm
  ctx.produced = [](const std::string& p, const std::string& k) -> std::optional<MessageLayout> {
    if ((p == "motor" || p == "ctrl") && k == "state") return layout("t/MotorState", "float64 electrical_power_w\nfloat64 torque_nm\n");
    return std::nullopt;
  };
  r = resolveMapping(MappingSpec{}, md, ctx);  // ctrl runs: it feeds both alternatives' inputs
  ASSERT_EQ(r.inputs.size(), 3u);
  EXPECT_EQ(r.inputs[1].participant, "ctrl");
  EXPECT_EQ(r.inputs[1].variable, "ctrl|pack|motor.state.electrical_power_w");
  EXPECT_EQ(r.inputs[2].participant, "ctrl");
  EXPECT_EQ(r.inputs[2].field_name, "ctrl.state.electrical_power_w");
}

TEST(FmuMapping, ExplicitEntriesOnTheTestFmuWithUnitConversions) {
  const FmuArchive a(testFmu("thermal_mass"));
  MappingSpec s;
  s.file = "map.yaml";
  s.outputs = {{"pack.state.temperature_k", "T", ""}, {"pack.state.steps", "steps", ""}};
  s.inputs = {{"motor.state.electrical_power_w", "Q", ""}};
  s.not_provided = {{"pack.state.power_w", 0.0, "the thermal mass has no electrical side"},
                    {"pack.state.fan_on", 0.0, "no fan"}};
  s.parameters = {{"T_start", 300.0, VarType::kReal}};  // 300 K in SI
  const ResolvedMapping r = resolveMapping(s, a.modelDescription(), context());
  ASSERT_EQ(r.outputs.size(), 2u);
  EXPECT_DOUBLE_EQ(r.outputs[0].fieldFromFmu(-273.15), 0.0);
  EXPECT_DOUBLE_EQ(r.inputs[0].fmuFromField(2000.0), 2.0);  // W -> kW
  ASSERT_EQ(r.parameters.size(), 1u);
  EXPECT_NEAR(r.parameters[0].value_fmu, 26.85, 1e-12);  // 300 K in degC
  EXPECT_EQ(r.not_provided.size(), 2u);
  std::ostringstream csv;
  r.writeCsv(csv, "thermal_mass.fmu");
  EXPECT_NE(csv.str().find("not_provided,pack.state.power_w,,,,,,,,0,the thermal mass has no electrical side"), std::string::npos)
      << csv.str();
}

// A field in A h from an FMU declaring A h (factor 3600 to A s, as the exported battery does):
// passed unchanged (through A s, 3600 v / 3600 differs from v in the last bit for this v, a
// charge throughput of the battery FMU's round trip). Another unit still converts.
TEST(FmuMapping, TheFieldsOwnUnitPassesBitForBit) {
  Binding b;
  b.unit = unitOfName("charge_throughput_ah");
  b.fmu = UnitConversion{3600.0, 0.0};
  const double v = 0.010047224304778668;  // [A h]
  ASSERT_NE(b.unit.fromSi(b.fmu.toSi(v)), v);  // what the conversion through SI would give
  EXPECT_EQ(b.fieldFromFmu(v), v);
  EXPECT_EQ(b.fmuFromField(v), v);
  b.fmu = UnitConversion{3.6e6, 0.0};  // kA h
  EXPECT_DOUBLE_EQ(b.fieldFromFmu(v), 1000.0 * v);
  EXPECT_DOUBLE_EQ(b.fmuFromField(v), 1e-3 * v);
}

TEST(FmuMapping, AnOutputFieldNeitherMappedNorDeclaredIsRejected) {
  const ModelDescription md = description(conventional().substr(0, 0) + var("pack.state.temperature_k", "output", "<Real unit=\"K\"/>"));
  expectThrowWith<InputError>([&] { resolveMapping(MappingSpec{}, md, context()); },
                              {"pack.state.power_w", "/pack/state", "not_provided"});
}

TEST(FmuMapping, WrongCausalityTypeOrUnitNamesTheVariable) {
  const FmuArchive a(testFmu("thermal_mass"));
  const ModelDescription& md = a.modelDescription();
  MappingSpec s;
  s.not_provided = {{"pack.state.power_w", 0, "r"}, {"pack.state.steps", 0, "r"}, {"pack.state.fan_on", 0, "r"}};
  s.outputs = {{"pack.state.temperature_k", "T_amb", ""}};  // an input mapped as output
  expectThrowWith<FmuError>([&] { resolveMapping(s, md, context()); }, {"thermal_mass.fmu", "'T_amb'", "causality input", "must be an output"});
  s.outputs = {{"pack.state.temperature_k", "steps", ""}};  // Integer into a float64 field
  expectThrowWith<FmuError>([&] { resolveMapping(s, md, context()); }, {"'steps' is Integer", "float64"});
  s.outputs = {{"pack.state.temperature_k", "T", ""}};
  s.inputs = {{"motor.state.torque_nm", "Q", ""}};  // N.m into kW
  expectThrowWith<FmuError>([&] { resolveMapping(s, md, context()); }, {"'Q'", "\"kW\"", "incompatible", "N.m"});
  s.inputs = {{"motor.state.electrical_power_w", "T_oil", ""}};
  expectThrowWith<FmuError>([&] { resolveMapping(s, md, context()); }, {"no variable 'T_oil'"});
}

TEST(FmuMapping, MappingFileMistakesNameFileAndKey) {
  const ModelDescription md = description(conventional());
  MappingSpec s;
  s.file = "map.yaml";
  s.inputs = {{"engine.state.speed_rad_s", "motor.state.electrical_power_w", ""}};
  expectThrowWith<InputError>([&] { resolveMapping(s, md, context()); }, {"map.yaml", "inputs", "/engine/state", "not published"});
  s.inputs.clear();
  s.not_provided = {{"pack.state.power_w", 0.0, ""}};
  expectThrowWith<InputError>([&] { resolveMapping(s, md, context()); }, {"map.yaml", "not_provided", "reason"});
  s.not_provided.clear();
  s.parameters = {{"scenario.ambient_temperature_c", 1.0, VarType::kBoolean}};
  expectThrowWith<InputError>([&] { resolveMapping(s, md, context()); }, {"parameters/scenario.ambient_temperature_c", "Real"});
  s.parameters.clear();
  s.interface = InterfaceType::kModelExchange;
  expectThrowWith<FmuError>([&] { resolveMapping(s, md, context()); }, {"no <ModelExchange>"});
}

TEST(FmuMapping, ParameterValuesAreCheckedAgainstTheFmusRange) {
  // T_set declared in degC with max 90 degC: 370 K (96.85 degC) is outside, 350 K (76.85 degC) inside
  const ModelDescription md = description(conventional(
      var("T_set", "parameter", "<Real unit=\"degC\" min=\"-40\" max=\"90\" start=\"20\"/>", "fixed") +
      var("cells", "parameter", "<Integer min=\"1\" max=\"16\" start=\"13\"/>", "fixed")));
  MappingSpec s;
  s.file = "map.yaml";
  s.parameters = {{"T_set", 370.0, VarType::kReal}};
  expectThrowWith<InputError>([&] { resolveMapping(s, md, context()); },
                              {"map.yaml", "parameters/T_set", "96.85", "degC", "outside the FMU's range [-40.0", "90.0"});
  s.parameters = {{"T_set", 350.0, VarType::kReal}, {"cells", 17, VarType::kInteger}};
  expectThrowWith<InputError>([&] { resolveMapping(s, md, context()); }, {"parameters/cells", "17", "[1.0", "16.0"});
  s.parameters = {{"T_set", 350.0, VarType::kReal}, {"cells", 7, VarType::kInteger}};
  const ResolvedMapping r = resolveMapping(s, md, context());
  EXPECT_NEAR(r.parameters[0].value_fmu, 76.85, 1e-12);
  EXPECT_EQ(r.parameters[1].value_fmu, 7.0);
  s.parameters = {{"cells", 7.5, VarType::kReal}};  // a number where the FMU wants an integer
  expectThrowWith<InputError>([&] { resolveMapping(s, md, context()); }, {"parameters/cells", "Integer"});
}

TEST(FmuMapping, ScenarioParameterTheScenarioDoesNotSetIsRejected) {
  const ModelDescription md = description(conventional(var("scenario.payload_kg", "parameter", "<Real start=\"0\"/>", "fixed")));
  // payload_kg is dimensionless in this FMU: the unit check fires first when the scenario sets it
  MappingContext c = context();
  expectThrowWith<FmuError>([&] { resolveMapping(MappingSpec{}, md, c); }, {"scenario.payload_kg", "/scenario/payload_kg", "not a number set"});
  c.scenario["payload_kg"] = 1500.0;
  expectThrowWith<FmuError>([&] { resolveMapping(MappingSpec{}, md, c); }, {"scenario.payload_kg", "incompatible", "kg"});
}

TEST(FmuMapping, ModelExchangeNeedsItsCvodeSettings) {
  const FmuArchive a(testFmu("switched_decay"));
  MappingContext c = context();
  c.publishes.clear();
  MappingSpec s;
  s.file = "map.yaml";
  expectThrowWith<InputError>([&] { resolveMapping(s, a.modelDescription(), c); }, {"map.yaml", "model_exchange/rtol"});
  s.me_rtol = 1e-10;
  s.me_atol = 1e-12;
  s.me_max_steps = 100000;
  const ResolvedMapping r = resolveMapping(s, a.modelDescription(), c);
  EXPECT_EQ(r.interface, InterfaceType::kModelExchange);
}

}  // namespace
}  // namespace hbt::fmi
