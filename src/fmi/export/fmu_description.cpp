#include "fmi/export/fmu_description.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "common/errors.hpp"

namespace hbt::fmi::exported {
namespace {

std::string readText(const std::string& path, const std::string& what_file, const std::string& key) {
  std::ifstream f(path);
  if (!f) throw InputError(what_file, key, "cannot read '" + path + "'");
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// field name -> the comment of its line in a .msg file
std::map<std::string, std::string> fieldComments(const std::string& text) {
  std::map<std::string, std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const auto hash = line.find('#');
    const std::string decl = trim(line.substr(0, hash));
    if (decl.empty()) continue;
    std::istringstream d(decl);
    std::string type, name;
    d >> type >> name;
    if (!name.empty() && hash != std::string::npos) out[name] = trim(line.substr(hash + 1));
  }
  return out;
}

struct Message {
  MessageLayout layout;
  std::map<std::string, std::string> comments;
};

Message readMessage(const std::string& msg_dir, const std::string& type, const std::string& spec, const std::string& key) {
  const std::string text = readText(msg_dir + "/" + type + ".msg", spec, key);
  return {MessageLayout::parse("hybrid_bus_twin/" + type, text), fieldComments(text)};
}

// "<producer>.<key>" (alternatives "<a>|<b>.<key>") -> the C++ member "<producer>_<key>" ("a_or_b_key")
std::string cppGroup(const std::string& topic) {
  std::string g;
  for (char c : topic) g += c == '.' ? std::string("_") : c == '|' ? std::string("_or_") : std::string(1, c);
  return g;
}

// "<producer>.<key>" for an input (the producer part may list alternatives a|b, README "Naming
// convention"), "<participant>.<key>" for an output: names of letters, digits and _
void checkTopic(const std::string& topic, bool input, const std::string& spec, const std::string& key) {
  const auto dot = topic.find('.');
  bool ok = dot != std::string::npos && dot > 0 && dot + 1 < topic.size();
  std::string part;
  for (std::size_t i = 0; ok && i <= topic.size(); ++i) {
    const char c = i < topic.size() ? topic[i] : '\0';
    if (c == '.' || c == '|' || c == '\0') {
      ok = !part.empty() && (c != '|' || (input && i < dot)) && (c != '.' || i == dot);
      part.clear();
    } else {
      ok = std::isalnum(static_cast<unsigned char>(c)) || c == '_';
      part += c;
    }
  }
  if (!ok)
    throw InputError(spec, key, "'" + topic + "' is not " + (input ? "<producer>.<key> (alternatives <a>|<b>.<key>)" : "<participant>.<key>"));
}

ExportedVariable fieldVariable(const std::string& topic, const FieldInfo& f, const Message& m, const std::string& causality,
                               const std::string& spec, const std::string& key) {
  if (f.kind != FieldKind::kFloat64 && f.kind != FieldKind::kBool && f.kind != FieldKind::kInteger)
    throw InputError(spec, key, "field " + f.name + " of " + m.layout.datatype() + " (" + f.type + ") cannot be an FMU variable");
  ExportedVariable v;
  v.name = topic + "." + f.name;
  v.group = cppGroup(topic);
  v.member = f.name;
  v.kind = f.kind;
  v.causality = causality;
  v.unit = unitOfName(f.name);
  const auto c = m.comments.find(f.name);
  v.description = c == m.comments.end() ? "" : c->second;
  return v;
}

const YAML::Node required(const YAML::Node& n, const std::string& key, const std::string& spec) {
  if (!n[key]) throw InputError(spec, key, "missing");
  return n[key];
}

void readInputs(const YAML::Node& root, const std::string& spec, const std::string& msg_dir, FmuDescription& d) {
  for (const auto& in : required(root, "inputs", spec)) {
    const std::string topic = required(in, "topic", spec).as<std::string>();
    checkTopic(topic, true, spec, "inputs/" + topic);
    const Message m = readMessage(msg_dir, required(in, "type", spec).as<std::string>(), spec, "inputs/" + topic);
    for (const auto& f : required(in, "fields", spec)) {
      const auto i = m.layout.find(f.as<std::string>());
      if (!i) throw InputError(spec, "inputs/" + topic, "no field " + f.as<std::string>() + " in " + m.layout.datatype());
      d.variables.push_back(fieldVariable(topic, m.layout.fields()[*i], m, "input", spec, "inputs/" + topic));
      if (in["start"]) d.variables.back().start = in["start"].as<double>();  // in the field's unit
    }
  }
}

void readOutputs(const YAML::Node& root, const std::string& spec, const std::string& msg_dir, FmuDescription& d) {
  for (const auto& out : required(root, "outputs", spec)) {
    const std::string topic = required(out, "topic", spec).as<std::string>();
    checkTopic(topic, false, spec, "outputs/" + topic);
    const Message m = readMessage(msg_dir, required(out, "type", spec).as<std::string>(), spec, "outputs/" + topic);
    for (const auto& f : m.layout.fields())
      d.variables.push_back(fieldVariable(topic, f, m, "output", spec, "outputs/" + topic));
  }
}

// `warnings:` (optional) [{name: <participant>.warning.<name>, description}]: Boolean outputs,
// true while the participant's warning <name> is raised (src/fmi/README.md, naming convention)
void readWarnings(const YAML::Node& root, const std::string& spec, FmuDescription& d) {
  if (!root["warnings"]) return;
  for (const auto& w : root["warnings"]) {
    ExportedVariable v;
    v.name = required(w, "name", spec).as<std::string>();
    const auto dot = v.name.find(".warning.");
    if (dot == std::string::npos || dot == 0 || v.name.find('.', dot + 9) != std::string::npos)
      throw InputError(spec, "warnings/" + v.name, "not <participant>.warning.<name>");
    checkTopic(v.name.substr(0, dot + 8), false, spec, "warnings/" + v.name);
    checkTopic("warning." + v.name.substr(dot + 9), false, spec, "warnings/" + v.name);
    v.group = cppGroup(v.name.substr(0, dot + 8));
    v.member = v.name.substr(dot + 9);
    v.kind = FieldKind::kBool;
    v.causality = "output";
    v.unit = unitOfName(v.member);
    v.description = required(w, "description", spec).as<std::string>();
    d.variables.push_back(v);
  }
}

void readParameters(const YAML::Node& root, const std::string& spec, FmuDescription& d) {
  for (const auto& p : required(root, "parameters", spec)) {
    ExportedVariable v;
    v.name = required(p, "name", spec).as<std::string>();
    if (v.name.rfind("scenario.", 0) != 0) throw InputError(spec, "parameters/" + v.name, "not a scenario.<name>");
    v.group = "scenario";
    v.member = v.name.substr(9);
    v.causality = "parameter";
    v.unit = unitOfName(v.member);
    v.description = required(p, "description", spec).as<std::string>();
    v.start = required(p, "start", spec).as<double>();
    v.min = required(p, "min", spec).as<double>();
    v.max = required(p, "max", spec).as<double>();
    d.variables.push_back(v);
  }
}

// a key "a/b/c" of a nested YAML mapping; nullopt when absent (a default YAML::Node is a defined
// null, not an absent one)
std::optional<YAML::Node> at(const YAML::Node& root, const std::string& key) {
  YAML::Node n = YAML::Clone(root);
  std::istringstream in(key);
  for (std::string part; std::getline(in, part, '/');) {
    if (!n.IsMap() || !n[part]) return std::nullopt;
    n.reset(n[part]);  // rebinds (operator= would assign into the node)
  }
  return n;
}

YAML::Node loadConfig(const std::string& package_root, const std::string& file, const std::string& spec, const std::string& key) {
  try {
    return YAML::LoadFile(package_root + "/" + file);
  } catch (const std::exception& e) {
    throw InputError(spec, key, "cannot read " + file + ": " + e.what());
  }
}

// The FMU's step size [s]: the config's cosim/macro_step_s, or for a participant without one (it
// steps at the stepper's base step) the spec's step_size_s; one of the two, not both.
double stepSize(const YAML::Node& root, const YAML::Node& config, const std::string& spec, const std::string& config_file) {
  const std::optional<YAML::Node> step = at(config, "cosim/macro_step_s");
  if (step && root["step_size_s"])
    throw InputError(spec, "step_size_s", "given twice: " + config_file + " has cosim/macro_step_s (the participant's step)");
  if (!step && !root["step_size_s"])
    throw InputError(spec, "step_size_s", "missing: " + config_file + " has no cosim/macro_step_s, so the spec states the step");
  const double h = (step ? *step : root["step_size_s"]).as<double>();
  if (!(h > 0.0)) throw InputError(step ? config_file : spec, step ? "cosim/macro_step_s" : "step_size_s", "must be > 0 [s]");
  return h;
}

// A data_files entry: a key of the config (its value a package-relative path), or
// {config: <one of config/configs>, key: <key>, dir_key: <key of a folder the path is relative to>}
std::string dataFile(const YAML::Node& entry, const std::map<std::string, YAML::Node>& configs, const std::string& main,
                     const std::string& spec) {
  const bool plain = entry.IsScalar();
  const std::string file = plain ? main : required(entry, "config", spec).as<std::string>();
  const std::string key = plain ? entry.as<std::string>() : required(entry, "key", spec).as<std::string>();
  const auto c = configs.find(file);
  if (c == configs.end()) throw InputError(spec, "data_files/" + key, "config " + file + " is neither config nor one of configs");
  const std::optional<YAML::Node> f = at(c->second, key);
  if (!f) throw InputError(file, key, "missing (named in " + spec + " data_files)");
  if (plain || !entry["dir_key"]) return f->as<std::string>();
  const std::optional<YAML::Node> dir = at(c->second, entry["dir_key"].as<std::string>());
  if (!dir) throw InputError(file, entry["dir_key"].as<std::string>(), "missing (named in " + spec + " data_files)");
  return dir->as<std::string>() + "/" + f->as<std::string>();
}

std::string xmlEscape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string number(double v) {
  char b[32];
  for (int digits = 15; digits <= 17; ++digits) {  // the shortest text that reads back as v
    std::snprintf(b, sizeof b, "%.*g", digits, v);
    if (std::strtod(b, nullptr) == v) break;
  }
  return b;
}

const char* fmiType(FieldKind k) { return k == FieldKind::kBool ? "Boolean" : k == FieldKind::kInteger ? "Integer" : "Real"; }

void writeUnitDefinitions(const std::vector<ExportedVariable>& vars, std::ostream& o) {
  std::map<std::string, FieldUnit> units;  // ordered by name: deterministic
  for (const auto& v : vars)
    if (v.kind == FieldKind::kFloat64 && !fmiUnitName(v.unit).empty()) units.emplace(fmiUnitName(v.unit), v.unit);
  o << "  <UnitDefinitions>\n";
  for (const auto& [name, u] : units) {
    o << "    <Unit name=\"" << xmlEscape(name) << "\"><BaseUnit";
    for (int i = 0; i < 8; ++i)
      if (u.si.dimension.exponent[i] != 0) o << " " << SiDimension::baseName(i) << "=\"" << u.si.dimension.exponent[i] << "\"";
    if (u.factor != 1.0) o << " factor=\"" << number(u.factor) << "\"";
    if (u.offset != 0.0) o << " offset=\"" << number(u.offset) << "\"";
    o << "/></Unit>\n";
  }
  o << "  </UnitDefinitions>\n";
}

void writeVariable(const ExportedVariable& v, std::size_t vr, std::ostream& o) {
  const bool out = v.causality == "output";
  const char* variability = v.causality == "parameter" ? "fixed" : v.kind == FieldKind::kFloat64 ? "continuous" : "discrete";
  o << "    <ScalarVariable name=\"" << xmlEscape(v.name) << "\" valueReference=\"" << vr << "\" causality=\""
    << v.causality << "\" variability=\"" << variability << "\"";
  if (out) o << " initial=\"calculated\"";
  if (v.causality == "parameter") o << " initial=\"exact\"";
  o << " description=\"" << xmlEscape(v.description) << "\">\n      <" << fmiType(v.kind);
  if (v.kind == FieldKind::kFloat64 && !fmiUnitName(v.unit).empty()) o << " unit=\"" << xmlEscape(fmiUnitName(v.unit)) << "\"";
  if (v.min) o << " min=\"" << number(*v.min) << "\"";
  if (v.max) o << " max=\"" << number(*v.max) << "\"";
  if (!out) o << " start=\"" << (v.kind == FieldKind::kBool ? (v.start != 0.0 ? "true" : "false") : number(v.start)) << "\"";
  o << "/>\n    </ScalarVariable>\n";
}

std::string describe(const FmuDescription& d, const std::string& guid) {
  std::ostringstream o;
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<fmiModelDescription fmiVersion=\"2.0\" modelName=\"" << d.model_identifier << "\" guid=\"" << guid
    << "\"\n    description=\"" << xmlEscape(d.description) << "\"\n"
    << "    generationTool=\"hybrid_bus_twin src/fmi/export\" variableNamingConvention=\"flat\" numberOfEventIndicators=\"0\">\n"
    << "  <CoSimulation modelIdentifier=\"" << d.model_identifier << "\" needsExecutionTool=\"false\""
    << " canHandleVariableCommunicationStepSize=\"true\" canInterpolateInputs=\"false\" maxOutputDerivativeOrder=\"0\""
    << " canRunAsynchronuously=\"false\" canBeInstantiatedOnlyOncePerProcess=\"false\" canNotUseMemoryManagementFunctions=\"true\""
    << " canGetAndSetFMUstate=\"false\" canSerializeFMUstate=\"false\" providesDirectionalDerivative=\"false\"/>\n";
  writeUnitDefinitions(d.variables, o);
  o << "  <LogCategories>\n    <Category name=\"error\" description=\"failures: instantiation (the file and key at fault), calls, steps\"/>\n"
    << "  </LogCategories>\n"
    << "  <DefaultExperiment startTime=\"0\" stepSize=\"" << number(d.step_size_s) << "\"/>\n  <ModelVariables>\n";
  for (std::size_t i = 0; i < d.variables.size(); ++i) writeVariable(d.variables[i], i, o);
  o << "  </ModelVariables>\n  <ModelStructure>\n    <Outputs>\n";
  for (std::size_t i = 0; i < d.variables.size(); ++i)
    if (d.variables[i].causality == "output") o << "      <Unknown index=\"" << i + 1 << "\"/>\n";
  o << "    </Outputs>\n    <InitialUnknowns>\n";
  for (std::size_t i = 0; i < d.variables.size(); ++i)
    if (d.variables[i].causality == "output") o << "      <Unknown index=\"" << i + 1 << "\"/>\n";
  o << "    </InitialUnknowns>\n  </ModelStructure>\n</fmiModelDescription>\n";
  return o.str();
}

const char* cppType(FieldKind k) { return k == FieldKind::kBool ? "bool" : k == FieldKind::kInteger ? "long" : "double"; }

}  // namespace

std::string fmiUnitName(const FieldUnit& u) {
  if (u.offset == 273.15) return "degC";
  if (u.factor == 3600.0 && u.si.name == "A.s") return "A.h";
  if (u.factor == 0.01) return "%";
  if (u.factor == 1e-6) return "ppm";
  if (u.factor != 1.0 || u.offset != 0.0) throw InputError("(unit table)", u.si.name, "no FMI unit name for this factor");
  return u.si.name == "1" ? "" : u.si.name;
}

FmuDescription FmuDescription::read(const std::string& spec, const std::string& msg_dir, const std::string& package_root) {
  YAML::Node root;
  try {
    root = YAML::LoadFile(spec);
  } catch (const std::exception& e) {
    throw InputError(spec, "(file)", e.what());
  }
  FmuDescription d;
  d.model_identifier = required(root, "model_identifier", spec).as<std::string>();
  d.description = required(root, "description", spec).as<std::string>();
  d.config_file = required(root, "config", spec).as<std::string>();
  const YAML::Node config = loadConfig(package_root, d.config_file, spec, "config");
  d.step_size_s = stepSize(root, config, spec, d.config_file);
  std::map<std::string, YAML::Node> configs = {{d.config_file, config}};
  if (root["configs"])
    for (const auto& c : root["configs"]) {
      d.config_files.push_back(c.as<std::string>());
      configs.emplace(d.config_files.back(), loadConfig(package_root, d.config_files.back(), spec, "configs"));
    }
  for (const auto& k : required(root, "data_files", spec)) d.data_files.push_back(dataFile(k, configs, d.config_file, spec));
  readInputs(root, spec, msg_dir, d);
  readOutputs(root, spec, msg_dir, d);
  readWarnings(root, spec, d);
  readParameters(root, spec, d);
  std::set<std::string> names;
  for (const auto& v : d.variables)
    if (!names.insert(v.name).second) throw InputError(spec, v.name, "declared twice");
  return d;
}

std::string FmuDescription::guid() const {
  std::uint64_t h = 1469598103934665603ULL;  // FNV-1a 64
  for (unsigned char c : describe(*this, "")) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  char b[64];
  std::snprintf(b, sizeof b, "{hbt-%s-%016llx}", model_identifier.c_str(), static_cast<unsigned long long>(h));
  return b;
}

std::string FmuDescription::modelDescriptionXml() const { return describe(*this, guid()); }

std::string FmuDescription::variablesHeader() const {
  std::ostringstream o;
  o << "// Generated by hbt_fmu_describe (src/fmi/export) from the export spec of " << model_identifier
    << " and msg/*.msg. Do not edit.\n#pragma once\n#include \"fmi/export/exported_model.hpp\"\n\n"
    << "namespace hbt::fmi::exported {\nconst char* const kGuid = \"" << guid() << "\";\n"
    << "const char* const kModelIdentifier = \"" << model_identifier << "\";\n\nnamespace generated {\n\n"
    << "/// One member per FMU variable, grouped by message (<producer>_<key>) and scenario; start values.\nstruct Variables {\n";
  std::vector<std::string> groups;
  for (const auto& v : variables)
    if (std::find(groups.begin(), groups.end(), v.group) == groups.end()) groups.push_back(v.group);
  for (const auto& g : groups) {
    o << "  struct {\n";
    for (const auto& v : variables)
      if (v.group == g)
        o << "    " << cppType(v.kind) << " " << v.member << " = " << (v.kind == FieldKind::kBool ? (v.start != 0.0 ? "true" : "false") : number(v.start))
          << ";\n";
    o << "  } " << g << ";\n";
  }
  o << "};\n\n/// The variables by value reference, for the fmi2 functions.\nclass VariablesModel : public ExportedModel {\n public:\n";
  const char* kinds[3][2] = {{"double", "real"}, {"bool", "boolean"}, {"long", "integer"}};
  const FieldKind fk[3] = {FieldKind::kFloat64, FieldKind::kBool, FieldKind::kInteger};
  for (int k = 0; k < 3; ++k) {
    o << "  " << kinds[k][0] << "* " << kinds[k][1] << "(unsigned vr) override {\n    switch (vr) {\n";
    for (std::size_t i = 0; i < variables.size(); ++i)
      if (variables[i].kind == fk[k]) o << "      case " << i << ": return &v_." << variables[i].group << "." << variables[i].member << ";\n";
    o << "      default: return nullptr;\n    }\n  }\n";
  }
  o << "  Causality causality(unsigned vr) const override {\n    static const Causality kCausality[] = {";
  for (const auto& v : variables)
    o << (v.causality == "input" ? "Causality::kInput, " : v.causality == "output" ? "Causality::kOutput, " : "Causality::kParameter, ");
  o << "};\n    return kCausality[vr];\n  }\n\n protected:\n  Variables v_;\n};\n\n}  // namespace generated\n}  // namespace hbt::fmi::exported\n";
  return o.str();
}

}  // namespace hbt::fmi::exported
