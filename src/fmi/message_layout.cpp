#include "fmi/message_layout.hpp"

#include <sstream>
#include <utility>

namespace hbt::fmi {
namespace {

SiUnit unit(const char* n, int kg, int m, int s, int A, int K, int mol, int rad) {
  SiUnit u{n, {}};
  u.dimension.exponent = {kg, m, s, A, K, mol, 0, rad};
  return u;
}

/// Name suffix -> unit, longest suffixes first (w_k before k). Sources: the package's field
/// naming rule (README.md "Units") and the bracketed units of msg/*.msg, against which
/// test/fmi/test_message_layout.cpp checks every field that states one.
struct Suffix {
  const char* suffix;
  FieldUnit unit;
};
const std::vector<Suffix>& suffixes() {
  static const std::vector<Suffix> kTable = {
      {"_rad_s", {unit("rad/s", 0, 0, -1, 0, 0, 0, 1)}},
      {"_m_s2", {unit("m/s2", 0, 1, -2, 0, 0, 0, 0)}},
      {"_m3_s", {unit("m3/s", 0, 3, -1, 0, 0, 0, 0)}},
      {"_kg_s", {unit("kg/s", 1, 0, -1, 0, 0, 0, 0)}},
      {"_m_s", {unit("m/s", 0, 1, -1, 0, 0, 0, 0)}},
      {"_w_k", {unit("W/K", 1, 2, -3, 0, -1, 0, 0)}},
      {"_kg_k", {unit("kg.K", 1, 0, 0, 0, 1, 0, 0)}},   // an integral of mass times temperature
      {"_k_s", {unit("K.s", 0, 0, 1, 0, 1, 0, 0)}},     // an integral of temperature over time
      {"_g_l", {unit("kg/m3", 1, -3, 0, 0, 0, 0, 0)}},  // g/L = kg/m3
      {"_ah", {unit("A.s", 0, 0, 1, 1, 0, 0, 0), 3600.0}},
      {"_percent", {unit("1", 0, 0, 0, 0, 0, 0, 0), 0.01}},
      {"_ppm", {unit("1", 0, 0, 0, 0, 0, 0, 0), 1e-6}},
      {"_nm", {unit("N.m", 1, 2, -2, 0, 0, 0, 0)}},
      {"_pa", {unit("Pa", 1, -1, -2, 0, 0, 0, 0)}},
      {"_kg", {unit("kg", 1, 0, 0, 0, 0, 0, 0)}},
      {"_mol", {unit("mol", 0, 0, 0, 0, 0, 1, 0)}},
      {"_rad", {unit("rad", 0, 0, 0, 0, 0, 0, 1)}},
      {"_j", {unit("J", 1, 2, -2, 0, 0, 0, 0)}},
      {"_w", {unit("W", 1, 2, -3, 0, 0, 0, 0)}},
      {"_k", {unit("K", 0, 0, 0, 0, 1, 0, 0)}},
      {"_c", {unit("K", 0, 0, 0, 0, 1, 0, 0), 1.0, 273.15}},  // degC (scenario ambient_temperature_c)
      {"_s", {unit("s", 0, 0, 1, 0, 0, 0, 0)}},
      {"_a", {unit("A", 0, 0, 0, 1, 0, 0, 0)}},
      {"_v", {unit("V", 1, 2, -3, -1, 0, 0, 0)}},
      {"_m", {unit("m", 0, 1, 0, 0, 0, 0, 0)}},
  };
  return kTable;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

FieldKind kindOf(const std::string& type) {
  if (type == "float64") return FieldKind::kFloat64;
  if (type == "bool") return FieldKind::kBool;
  if (type == "float64[]") return FieldKind::kFloat64Array;
  for (const char* t : {"int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64"})
    if (type == t) return FieldKind::kInteger;
  return FieldKind::kUnsupported;
}

}  // namespace

const char* name(FieldKind k) {
  switch (k) {
    case FieldKind::kFloat64: return "float64";
    case FieldKind::kBool: return "bool";
    case FieldKind::kInteger: return "integer";
    case FieldKind::kFloat64Array: return "float64[]";
    default: return "unsupported";
  }
}

FieldUnit unitOfName(const std::string& field_name) {
  for (const auto& s : suffixes())
    if (endsWith(field_name, s.suffix)) return s.unit;
  return {unit("1", 0, 0, 0, 0, 0, 0, 0)};
}

std::optional<FieldUnit> unitNamed(const std::string& si_name) {
  if (si_name == "1") return FieldUnit{unit("1", 0, 0, 0, 0, 0, 0, 0)};
  for (const auto& s : suffixes())
    if (s.unit.si.name == si_name && s.unit.factor == 1.0 && s.unit.offset == 0.0) return s.unit;
  return std::nullopt;
}

MessageLayout MessageLayout::parse(const std::string& datatype, const std::string& definition) {
  MessageLayout m;
  m.datatype_ = datatype;
  std::istringstream in(definition);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("===", 0) == 0) break;  // the nested types' definitions follow
    line = line.substr(0, line.find('#'));
    std::istringstream words(line);
    std::string type, field;
    if (!(words >> type >> field)) continue;
    if (field.find('=') != std::string::npos || line.find('=') != std::string::npos) continue;  // constant
    if (type == "std_msgs/Header" || type == "Header") {
      m.has_header_ = true;
      continue;
    }
    m.fields_.push_back({field, type, kindOf(type)});
  }
  return m;
}

std::optional<std::size_t> MessageLayout::find(const std::string& name) const {
  for (std::size_t i = 0; i < fields_.size(); ++i)
    if (fields_[i].name == name) return i;
  return std::nullopt;
}

}  // namespace hbt::fmi
