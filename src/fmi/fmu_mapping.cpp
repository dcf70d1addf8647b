#include "fmi/fmu_mapping.hpp"

#include <cmath>
#include <set>

#include "common/errors.hpp"
#include "fmi/fmu_error.hpp"

namespace hbt::fmi {
namespace {

/// "<participant>.<key>.<field>" or "<participant>.<key>.<field>[i]", split.
struct FieldPath {
  std::string participant, key, field;
  int element = -1;
};

std::optional<FieldPath> splitPath(const std::string& s) {
  const auto a = s.find('.');
  const auto b = a == std::string::npos ? a : s.find('.', a + 1);
  if (a == std::string::npos || b == std::string::npos || a == 0 || b == a + 1 || b + 1 >= s.size())
    return std::nullopt;
  FieldPath p{s.substr(0, a), s.substr(a + 1, b - a - 1), s.substr(b + 1)};
  const auto br = p.field.find('[');
  if (br != std::string::npos) {
    if (p.field.back() != ']' || br == 0) return std::nullopt;
    const std::string idx = p.field.substr(br + 1, p.field.size() - br - 2);
    if (idx.empty() || idx.size() > 6 || idx.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    p.element = std::stoi(idx);
    p.field = p.field.substr(0, br);
  }
  return p;
}

VarType varTypeOf(FieldKind k) {
  switch (k) {
    case FieldKind::kBool: return VarType::kBoolean;
    case FieldKind::kInteger: return VarType::kInteger;
    default: return VarType::kReal;
  }
}

bool causalityIs(const ScalarVariable& v, std::initializer_list<Causality> ok) {
  for (Causality c : ok)
    if (v.causality == c) return true;
  return false;
}

class Resolver {
 public:
  Resolver(const MappingSpec& spec, const ModelDescription& md, const MappingContext& ctx)
      : spec_(spec), md_(md), ctx_(ctx) {}

  ResolvedMapping run() {
    chooseInterface();
    for (const auto& l : spec_.outputs) explicitOutput(l);
    for (const auto& f : spec_.not_provided) fixedOutput(f);
    conventionalOutputs();
    for (const auto& l : spec_.inputs) addInput(l, "inputs");
    conventionalInputs();
    for (const auto& p : spec_.parameters) parameter(p);
    scenarioParameters();
    return std::move(r_);
  }

 private:
  [[noreturn]] void mapError(const std::string& key, const std::string& what) const {
    throw InputError(spec_.file, key, what);
  }

  void chooseInterface() {
    const bool cs = md_.coSimulationId().has_value(), me = md_.modelExchangeId().has_value();
    r_.interface = spec_.interface ? *spec_.interface : (cs ? InterfaceType::kCoSimulation : InterfaceType::kModelExchange);
    if (r_.interface == InterfaceType::kCoSimulation && !cs)
      throw FmuError(md_.fmuFile(), "modelDescription.xml has no <CoSimulation> (mapping file " + spec_.file +
                                        " asks for interface cs)");
    if (r_.interface == InterfaceType::kModelExchange && !me)
      throw FmuError(md_.fmuFile(), "modelDescription.xml has no <ModelExchange> (mapping file " + spec_.file +
                                        " asks for interface me)");
    if (r_.interface != InterfaceType::kModelExchange) return;
    if (!spec_.me_rtol) mapError("model_exchange/rtol", "required for a Model Exchange FMU (CVODE relative tolerance [-])");
    if (!spec_.me_atol) mapError("model_exchange/atol", "required for a Model Exchange FMU (CVODE absolute tolerance [state units])");
    if (!spec_.me_max_steps) mapError("model_exchange/max_steps", "required for a Model Exchange FMU (CVODE steps per segment)");
    r_.me_rtol = *spec_.me_rtol;
    r_.me_atol = *spec_.me_atol;
    r_.me_max_steps = *spec_.me_max_steps;
  }

  /// The variable `name`, checked for the causality the mapping needs and the field's type.
  const ScalarVariable& variable(const std::string& name, bool input, FieldKind kind) const {
    const ScalarVariable& v = md_.variable(name);  // FmuError "no variable"
    if (input ? !causalityIs(v, {Causality::kInput}) : !causalityIs(v, {Causality::kOutput})) {
      throw FmuError(md_.fmuFile(), "variable '" + name + "' has causality " + hbt::fmi::name(v.causality) +
                                        " and variability " + hbt::fmi::name(v.variability) + ": mapped as " +
                                        (input ? "an input it must be an input" : "an output it must be an output"));
    }
    const VarType want = varTypeOf(kind);
    const bool enum_ok = want == VarType::kInteger && v.type == VarType::kEnumeration;
    if (v.type != want && !enum_ok) {
      throw FmuError(md_.fmuFile(), "variable '" + name + "' is " + hbt::fmi::name(v.type) + ", but the field it is mapped to is " +
                                        hbt::fmi::name(kind) + " (needs " + hbt::fmi::name(want) + ")");
    }
    return v;
  }

  Binding bind(const FieldPath& p, const MessageLayout& layout, const std::string& path, const std::string& var,
               const std::string& unit_name, bool input, const std::string& where) const {
    const auto idx = layout.find(p.field);
    if (!idx) mapError(where, "'" + path + "': " + layout.datatype() + " has no field '" + p.field + "'");
    const FieldInfo& f = layout.fields()[*idx];
    if (f.kind == FieldKind::kUnsupported)
      mapError(where, "'" + path + "': field type " + f.type + " cannot be mapped (float64, bool, integers, float64[] only)");
    if ((f.kind == FieldKind::kFloat64Array) != (p.element >= 0))
      mapError(where, "'" + path + "': " + (p.element >= 0 ? "not an array field" : "an array field: name its elements, " + p.field + "[i]"));
    Binding b;
    b.participant = p.participant;
    b.key = p.key;
    b.field = *idx;
    b.element = p.element;
    b.field_name = path;
    b.variable = var;
    const FieldKind scalar = f.kind == FieldKind::kFloat64Array ? FieldKind::kFloat64 : f.kind;
    const ScalarVariable& v = variable(var, input, scalar);
    b.type = v.type == VarType::kEnumeration ? VarType::kInteger : v.type;
    b.fmu_unit = v.unit;
    if (p.element >= 0) {
      const auto u = unitNamed(unit_name);
      if (!u) mapError(where, "'" + path + "': an array element needs unit: one of K, W, J, s, A, V, N.m, kg, Pa, mol, m, rad, rad/s, m/s, kg/s, W/K, 1 (got '" + unit_name + "')");
      b.unit = *u;
    } else {
      if (!unit_name.empty()) mapError(where, "'" + path + "': unit is given by the field's name; unit: is for array elements only");
      b.unit = unitOfName(p.field);
    }
    if (b.type == VarType::kReal) b.fmu = md_.unitToSi(v, b.unit.si);  // FmuError: incompatible unit
    return b;
  }

  // --- outputs ---
  const MessageLayout& ownLayout(const FieldPath& p, const std::string& path, const std::string& where) const {
    if (p.participant != ctx_.participant)
      mapError(where, "'" + path + "': " + ctx_.participant + " publishes only its own fields (" + ctx_.participant + ".<key>.<field>)");
    const auto it = ctx_.publishes.find(p.key);
    if (it == ctx_.publishes.end())
      mapError(where, "'" + path + "': " + ctx_.participant + " does not publish key '" + p.key + "' (its topics.yaml)");
    return it->second;
  }

  void claim(const std::string& path, const std::string& where) {
    if (!claimed_.insert(path).second) mapError(where, "'" + path + "' is mapped twice");
  }

  void explicitOutput(const MappingSpec::Link& l) {
    const auto p = splitPath(l.field);
    if (!p) mapError("outputs", "'" + l.field + "': expected <participant>.<key>.<field>");
    const MessageLayout& layout = ownLayout(*p, l.field, "outputs");
    claim(l.field, "outputs");
    r_.outputs.push_back(bind(*p, layout, l.field, l.variable, l.unit, false, "outputs"));
    if (p->element >= 0) {
      auto& n = r_.array_sizes[p->key];
      n = std::max<std::size_t>(n, static_cast<std::size_t>(p->element) + 1);
    }
  }

  void fixedOutput(const MappingSpec::Fixed& f) {
    const auto p = splitPath(f.field);
    if (!p || p->element >= 0) mapError("not_provided", "'" + f.field + "': expected <participant>.<key>.<field> (a scalar field)");
    const MessageLayout& layout = ownLayout(*p, f.field, "not_provided");
    const auto idx = layout.find(p->field);
    if (!idx) mapError("not_provided", "'" + f.field + "': " + layout.datatype() + " has no field '" + p->field + "'");
    if (!std::isfinite(f.value)) mapError("not_provided", "'" + f.field + "': value must be finite");
    if (f.reason.empty()) mapError("not_provided", "'" + f.field + "': reason: say why the FMU does not provide it");
    claim(f.field, "not_provided");
    r_.not_provided.push_back({p->key, *idx, f.field, f.reason, f.value});
  }

  void conventionalOutputs() {
    for (const auto& [key, layout] : ctx_.publishes) {
      for (std::size_t i = 0; i < layout.fields().size(); ++i) {
        const FieldInfo& f = layout.fields()[i];
        const std::string path = ctx_.participant + "." + key + "." + f.name;
        if (f.kind == FieldKind::kFloat64Array) {
          checkArrayCovered(key, f.name);
          continue;
        }
        if (claimed_.count(path)) continue;
        const bool exists = hasVariable(path);
        if (!exists)
          mapError("outputs", "field " + path + " of " + topic(ctx_.participant, key) + " (" + layout.datatype() +
                                  ") is not provided: FMU " + md_.fmuFile() + " has no output '" + path +
                                  "'; map it (outputs) or declare it (not_provided, with the value it is published as)");
        claim(path, "outputs");
        r_.outputs.push_back(bind({ctx_.participant, key, f.name, -1}, layout, path, path, "", false, "outputs"));
      }
    }
  }

  void checkArrayCovered(const std::string& key, const std::string& field) {
    const std::size_t n = r_.array_sizes.count(key) ? r_.array_sizes[key] : 0;
    for (std::size_t e = 0; e < n; ++e) {
      const std::string path = ctx_.participant + "." + key + "." + field + "[" + std::to_string(e) + "]";
      if (!claimed_.count(path)) mapError("outputs", "'" + path + "' is not mapped, but a later element is (every element up to the last must be)");
    }
  }

  // --- inputs ---
  void addInput(const MappingSpec::Link& l, const std::string& where) {
    const auto p = splitPath(l.field);
    if (!p) mapError(where, "'" + l.field + "': expected <producer>.<key>.<field>");
    if (p->participant == ctx_.participant) mapError(where, "'" + l.field + "': a participant does not read its own output");
    const auto layout = ctx_.produced(p->participant, p->key);
    if (!layout)
      mapError(where, "'" + l.field + "': " + topic(p->participant, p->key) + " is not published in this scenario (" +
                          p->participant + " does not run or does not declare '" + p->key + "')");
    if (!claimed_inputs_.insert(l.variable).second) mapError(where, "FMU input '" + l.variable + "' is fed twice");
    r_.inputs.push_back(bind(*p, *layout, l.field, l.variable, l.unit, true, where));
  }

  void conventionalInputs() {
    for (const auto& v : md_.variables()) {
      if (v.causality != Causality::kInput || claimed_inputs_.count(v.name)) continue;
      const auto p = splitPath(v.name);
      if (!p || p->element >= 0 || p->participant == "scenario") continue;
      const std::string producer = firstRunningProducer(p->participant, p->key);
      if (producer.empty()) continue;  // not a topic of this scenario: keeps its start value
      addInput({producer + "." + p->key + "." + p->field, v.name, ""}, "inputs (naming convention)");
    }
  }

  /// Of the producer part of an input's name, "<a>" or the alternatives "<a>|<b>|...", the first
  /// that publishes /<producer>/<key> in this scenario (not the participant itself); "" if none.
  std::string firstRunningProducer(const std::string& producers, const std::string& key) const {
    std::size_t from = 0;
    while (from <= producers.size()) {
      const auto bar = producers.find('|', from);
      const std::string p = producers.substr(from, bar == std::string::npos ? std::string::npos : bar - from);
      if (!p.empty() && p != ctx_.participant && ctx_.produced(p, key)) return p;
      if (bar == std::string::npos) break;
      from = bar + 1;
    }
    return "";
  }

  // --- parameters ---
  void setParameter(const std::string& name, double value, VarType given, const std::string& source,
                    const std::optional<FieldUnit>& si_unit) {
    const ScalarVariable& v = md_.variable(name);
    const bool settable = v.causality == Causality::kParameter &&
                          (v.variability == Variability::kFixed || v.variability == Variability::kTunable);
    if (!settable)
      throw FmuError(md_.fmuFile(), "variable '" + name + "' has causality " + hbt::fmi::name(v.causality) + " and variability " +
                                        hbt::fmi::name(v.variability) + ": not a parameter the importer can set (" + source + ")");
    ParamSetting s{name, v.type, value, source};
    const std::string key = "parameters/" + name;
    if (!std::isfinite(value)) mapError(key, "must be finite");
    if (v.type == VarType::kReal) {
      if (given == VarType::kBoolean) mapError(key, "FMU parameter is Real: give a number");
      UnitDefinition u;
      if (!v.unit.empty()) u = md_.units().at(v.unit);
      const SiUnit own{v.unit.empty() ? "1" : v.unit, u.dimension};
      const double si = si_unit ? si_unit->toSi(value) : value;
      s.value_fmu = md_.unitToSi(v, si_unit ? si_unit->si : own).fromSi(si);
    } else if (v.type == VarType::kInteger || v.type == VarType::kEnumeration) {
      if (given != VarType::kInteger) mapError(key, "FMU parameter is Integer: give an integer");
      s.type = VarType::kInteger;
    } else if (v.type == VarType::kBoolean) {
      if (given != VarType::kBoolean) mapError(key, "FMU parameter is Boolean: give true or false");
    } else {
      mapError(key, std::string("FMU parameter is ") + hbt::fmi::name(v.type) + ": not settable from the mapping");
    }
    checkRange(v, s.value_fmu, key);
    r_.parameters.push_back(s);
  }

  /// The FMU's own range of a parameter (its min / max, in its declared unit), as for our keys.
  void checkRange(const ScalarVariable& v, double value_fmu, const std::string& key) const {
    const bool low = v.min && value_fmu < *v.min, high = v.max && value_fmu > *v.max;
    if (!low && !high) return;
    auto str = [](const std::optional<double>& x, const char* none) { return x ? std::to_string(*x) : std::string(none); };
    mapError(key, std::to_string(value_fmu) + " " + (v.unit.empty() ? "" : v.unit + " ") + "is outside the FMU's range [" +
                      str(v.min, "-inf") + ", " + str(v.max, "inf") + "] of variable '" + v.name + "'");
  }

  void parameter(const MappingSpec::Param& p) {
    if (!claimed_params_.insert(p.variable).second) mapError("parameters/" + p.variable, "set twice");
    setParameter(p.variable, p.value, p.type, "mapping file (SI)", std::nullopt);
  }

  void scenarioParameters() {
    static const std::string kPrefix = "scenario.";
    for (const auto& v : md_.variables()) {
      if (v.name.rfind(kPrefix, 0) != 0 || claimed_params_.count(v.name)) continue;
      const std::string n = v.name.substr(kPrefix.size());
      const auto it = ctx_.scenario.find(n);
      if (it == ctx_.scenario.end())
        throw FmuError(md_.fmuFile(), "parameter '" + v.name + "': /scenario/" + n + " is not a number set in this scenario");
      setParameter(v.name, it->second, VarType::kReal, "/scenario/" + n, unitOfName(n));
    }
  }

  bool hasVariable(const std::string& n) const {
    for (const auto& v : md_.variables())
      if (v.name == n) return true;
    return false;
  }
  static std::string topic(const std::string& p, const std::string& k) { return "/" + p + "/" + k; }

  const MappingSpec& spec_;
  const ModelDescription& md_;
  const MappingContext& ctx_;
  ResolvedMapping r_;
  std::set<std::string> claimed_, claimed_inputs_, claimed_params_;
};

std::string csv(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

ResolvedMapping resolveMapping(const MappingSpec& spec, const ModelDescription& md, const MappingContext& ctx) {
  return Resolver(spec, md, ctx).run();
}

void ResolvedMapping::writeCsv(std::ostream& os, const std::string& fmu_file) const {
  os.precision(17);
  os << "# FMU " << fmu_file << " (" << name(interface) << ")";
  if (interface == InterfaceType::kModelExchange)
    os << ": CVODE rtol " << me_rtol << ", atol " << me_atol << ", max_steps " << me_max_steps;
  os << "\n# value_field = (factor * value_FMU + offset - field_offset) / field_factor\n"
     << "direction,field,variable,fmu_unit,factor,offset,field_unit,field_factor,field_offset,value,source\n";
  auto binding = [&](const char* dir, const Binding& b) {
    os << dir << "," << csv(b.field_name) << "," << csv(b.variable) << "," << csv(b.fmu_unit) << "," << b.fmu.factor << ","
       << b.fmu.offset << "," << csv(b.unit.si.name) << "," << b.unit.factor << "," << b.unit.offset << ",,\n";
  };
  for (const auto& b : inputs) binding("input", b);
  for (const auto& b : outputs) binding("output", b);
  for (const auto& f : not_provided)
    os << "not_provided," << csv(f.field_name) << ",,,,,,,," << f.value << "," << csv(f.reason) << "\n";
  for (const auto& p : parameters)
    os << "parameter,," << csv(p.variable) << ",,,,,,," << p.value_fmu << "," << csv(p.source) << "\n";
}

}  // namespace hbt::fmi
