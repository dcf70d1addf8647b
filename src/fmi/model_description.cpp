#include "fmi/model_description.hpp"

#include <tinyxml2.h>

#include <cerrno>
#include <cstdlib>

#include "fmi/fmu_error.hpp"

namespace hbt::fmi {

const char* name(Causality c) {
  static const char* const k[] = {"parameter", "calculatedParameter", "input",
                                  "output",    "local",               "independent"};
  return k[static_cast<int>(c)];
}
const char* name(Variability v) {
  static const char* const k[] = {"constant", "fixed", "tunable", "discrete", "continuous"};
  return k[static_cast<int>(v)];
}
const char* name(VarType t) {
  static const char* const k[] = {"Real", "Integer", "Boolean", "String", "Enumeration"};
  return k[static_cast<int>(t)];
}

using tinyxml2::XMLElement;

// The stages of parse(): each reads one part of the document into md_, failing with the FMU
// file and the element/attribute at fault.
class ModelDescriptionParser {
 public:
  ModelDescriptionParser(ModelDescription& md) : md_(md) {}

  void parseRoot(const XMLElement& root) {
    if (std::string(root.Name()) != "fmiModelDescription") {
      fail("root element is <" + std::string(root.Name()) + ">, not <fmiModelDescription>");
    }
    const char* version = root.Attribute("fmiVersion");
    if (!version) fail("<fmiModelDescription> has no attribute fmiVersion");
    if (std::string(version) != "2.0") {
      fail("fmiVersion \"" + std::string(version) +
           "\" is not supported (this importer reads FMI 2.0 only)");
    }
    md_.model_name_ = required(root, "modelName");
    md_.guid_ = required(root, "guid");
    md_.n_event_indicators_ = static_cast<int>(number(root, "numberOfEventIndicators", 0.0));
  }

  void parseInterfaces(const XMLElement& root) {
    if (const XMLElement* cs = root.FirstChildElement("CoSimulation")) {
      md_.cs_id_ = required(*cs, "modelIdentifier");
    }
    if (const XMLElement* me = root.FirstChildElement("ModelExchange")) {
      md_.me_id_ = required(*me, "modelIdentifier");
    }
    if (!md_.cs_id_ && !md_.me_id_) {
      fail("neither <CoSimulation> nor <ModelExchange>: the FMU declares no interface type");
    }
  }

  void parseExperiment(const XMLElement& root) {
    const XMLElement* e = root.FirstChildElement("DefaultExperiment");
    if (!e) return;
    DefaultExperiment& x = md_.experiment_;
    if (e->Attribute("startTime")) x.start_time_s = number(*e, "startTime", 0.0);
    if (e->Attribute("stopTime")) x.stop_time_s = number(*e, "stopTime", 0.0);
    if (e->Attribute("tolerance")) x.tolerance = number(*e, "tolerance", 0.0);
    if (e->Attribute("stepSize")) x.step_size_s = number(*e, "stepSize", 0.0);
  }

  void parseUnits(const XMLElement& root) {
    const XMLElement* defs = root.FirstChildElement("UnitDefinitions");
    if (!defs) return;
    for (const XMLElement* u = defs->FirstChildElement("Unit"); u; u = u->NextSiblingElement("Unit")) {
      UnitDefinition d;
      d.name = required(*u, "name");
      if (const XMLElement* base = u->FirstChildElement("BaseUnit")) {
        for (int i = 0; i < 8; ++i) {
          d.dimension.exponent[i] = static_cast<int>(integer(*base, SiDimension::baseName(i), 0));
        }
        d.factor = number(*base, "factor", 1.0);
        d.offset = number(*base, "offset", 0.0);
        if (d.factor == 0.0) fail("<Unit name=\"" + d.name + "\"> <BaseUnit> has factor 0");
      }
      md_.units_[d.name] = d;
    }
  }

  void parseTypes(const XMLElement& root) {
    const XMLElement* defs = root.FirstChildElement("TypeDefinitions");
    if (!defs) return;
    for (const XMLElement* t = defs->FirstChildElement("SimpleType"); t;
         t = t->NextSiblingElement("SimpleType")) {
      SimpleType s;
      s.name = required(*t, "name");
      const XMLElement* elem = t->FirstChildElement();
      if (!elem) fail("<SimpleType name=\"" + s.name + "\"> has no type element");
      s.type = typeOf(*elem, "<SimpleType name=\"" + s.name + "\">");
      if (const char* unit = elem->Attribute("unit")) s.unit = checkedUnit(unit, "type " + s.name);
      md_.types_[s.name] = s;
    }
  }

  void parseVariables(const XMLElement& root) {
    const XMLElement* vars = root.FirstChildElement("ModelVariables");
    if (!vars) fail("no <ModelVariables>");
    for (const XMLElement* v = vars->FirstChildElement("ScalarVariable"); v;
         v = v->NextSiblingElement("ScalarVariable")) {
      ScalarVariable sv = parseVariable(*v);
      if (!md_.index_.emplace(sv.name, md_.variables_.size()).second) {
        fail("variable '" + sv.name + "' is declared twice in <ModelVariables>");
      }
      md_.variables_.push_back(sv);
    }
  }

  void parseStructure(const XMLElement& root) {
    const XMLElement* s = root.FirstChildElement("ModelStructure");
    const XMLElement* d = s ? s->FirstChildElement("Derivatives") : nullptr;
    if (!d) return;
    for (const XMLElement* u = d->FirstChildElement("Unknown"); u; u = u->NextSiblingElement("Unknown")) {
      const long index = integer(*u, "index", -1, "<Derivatives> <Unknown>");
      if (index < 1 || index > static_cast<long>(md_.variables_.size())) {
        fail("<Derivatives> <Unknown index=\"" + std::to_string(index) + "\"> is not a variable's index");
      }
      ++md_.n_states_;
    }
  }

  [[noreturn]] void fail(const std::string& what) const { throw FmuError(md_.fmu_file_, "modelDescription.xml: " + what); }

 private:
  ScalarVariable parseVariable(const XMLElement& v) {
    ScalarVariable sv;
    sv.name = required(v, "name");
    const std::string where = "variable '" + sv.name + "'";
    sv.value_reference = static_cast<unsigned>(integer(v, "valueReference", -1, where));
    if (const char* d = v.Attribute("description")) sv.description = d;
    sv.causality = enumValue<Causality>(v, "causality", Causality::kLocal, 6, where);
    sv.variability = enumValue<Variability>(v, "variability", Variability::kContinuous, 5, where);
    const XMLElement* elem = v.FirstChildElement();
    if (!elem) fail(where + " has no type element (Real, Integer, Boolean, String, Enumeration)");
    sv.type = typeOf(*elem, where);
    if (const char* t = elem->Attribute("declaredType")) {
      auto it = md_.types_.find(t);
      if (it == md_.types_.end()) fail(where + ": declaredType \"" + t + "\" is not in <TypeDefinitions>");
      sv.declared_type = t;
      sv.unit = it->second.unit;
    }
    if (const char* unit = elem->Attribute("unit")) sv.unit = checkedUnit(unit, where);
    if (const char* start = elem->Attribute("start")) sv.start = start;
    if (elem->Attribute("min")) sv.min = number(*elem, "min", 0.0);
    if (elem->Attribute("max")) sv.max = number(*elem, "max", 0.0);
    if (sv.causality == Causality::kInput && !sv.start) {
      fail(where + ": an input needs a start value (FMI 2.0, ScalarVariable: start is required for causality input)");
    }
    return sv;
  }

  std::string checkedUnit(const std::string& unit, const std::string& where) const {
    if (!md_.units_.count(unit)) fail(where + ": unit \"" + unit + "\" is not in <UnitDefinitions>");
    return unit;
  }

  VarType typeOf(const XMLElement& elem, const std::string& where) const {
    static const char* const kTypes[] = {"Real", "Integer", "Boolean", "String", "Enumeration"};
    for (int i = 0; i < 5; ++i) {
      if (std::string(elem.Name()) == kTypes[i]) return static_cast<VarType>(i);
    }
    fail(where + ": unknown type element <" + std::string(elem.Name()) + ">");
  }

  template <class E>
  E enumValue(const XMLElement& e, const char* attr, E fallback, int n, const std::string& where) const {
    const char* text = e.Attribute(attr);
    if (!text) return fallback;
    for (int i = 0; i < n; ++i) {
      if (std::string(text) == name(static_cast<E>(i))) return static_cast<E>(i);
    }
    fail(where + ": " + attr + " \"" + text + "\" is not one of FMI 2.0's values");
  }

  std::string required(const XMLElement& e, const char* attr) const {
    const char* text = e.Attribute(attr);
    if (!text || !*text) fail("<" + std::string(e.Name()) + "> has no attribute " + attr);
    return text;
  }

  double number(const XMLElement& e, const char* attr, double fallback) const {
    const char* text = e.Attribute(attr);
    if (!text) return fallback;
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(text, &end);
    if (end == text || *end != '\0' || errno != 0) {
      fail("<" + std::string(e.Name()) + "> attribute " + attr + " \"" + text + "\" is not a number");
    }
    return x;
  }

  long integer(const XMLElement& e, const char* attr, long fallback, const std::string& where = "") const {
    const char* text = e.Attribute(attr);
    const std::string at = where.empty() ? "<" + std::string(e.Name()) + ">" : where;
    if (!text) {
      if (fallback >= 0 || where.empty()) return fallback;
      fail(at + " has no attribute " + attr);
    }
    char* end = nullptr;
    errno = 0;
    const long x = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || errno != 0) {
      fail(at + " attribute " + attr + " \"" + text + "\" is not an integer");
    }
    return x;
  }

  ModelDescription& md_;
};

ModelDescription ModelDescription::parse(const std::string& xml, const std::string& fmu_file) {
  ModelDescription md;
  md.fmu_file_ = fmu_file;
  ModelDescriptionParser p(md);
  tinyxml2::XMLDocument doc;
  if (doc.Parse(xml.c_str(), xml.size()) != tinyxml2::XML_SUCCESS) {
    p.fail(std::string("malformed XML: ") + doc.ErrorStr());
  }
  const XMLElement* root = doc.RootElement();
  if (!root) p.fail("no root element");
  p.parseRoot(*root);
  p.parseInterfaces(*root);
  p.parseExperiment(*root);
  p.parseUnits(*root);
  p.parseTypes(*root);
  p.parseVariables(*root);
  p.parseStructure(*root);
  return md;
}

const ScalarVariable& ModelDescription::variable(const std::string& name) const {
  auto it = index_.find(name);
  if (it == index_.end()) throw FmuError(fmu_file_, "no variable '" + name + "' in modelDescription.xml");
  return variables_[it->second];
}

UnitConversion ModelDescription::unitToSi(const ScalarVariable& v, const SiUnit& expected) const {
  if (v.type != VarType::kReal) {
    throw FmuError(fmu_file_, "variable '" + v.name + "' is " + name(v.type) +
                                  ", not Real: it has no unit to convert to " + expected.name);
  }
  UnitDefinition u;  // no unit: dimensionless, factor 1
  if (!v.unit.empty()) u = units_.at(v.unit);
  if (u.dimension != expected.dimension) {
    const std::string unit = v.unit.empty() ? "none (dimensionless)" : "\"" + v.unit + "\"";
    throw FmuError(fmu_file_, "variable '" + v.name + "': unit " + unit + " [" + u.dimension.str() +
                                  "] is incompatible with the expected " + expected.name + " [" +
                                  expected.dimension.str() + "]");
  }
  return {u.factor, u.offset};
}

}  // namespace hbt::fmi
