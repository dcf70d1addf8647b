#include "common/params.hpp"

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "common/errors.hpp"

namespace hbt {

void ParamSet::add(const std::string& key, double& ref, const std::string& unit, double min,
                   double max, const std::string& doc) {
  entries_.push_back({prefix_ + key, unit, doc, &ref, min, max});
}
void ParamSet::add(const std::string& key, bool& ref, const std::string& doc) {
  entries_.push_back({prefix_ + key, "-", doc, &ref, 0, 0});
}
void ParamSet::add(const std::string& key, std::string& ref, const std::string& doc) {
  entries_.push_back({prefix_ + key, "-", doc, &ref, 0, 0});
}
void ParamSet::add(const std::string& key, std::vector<double>& ref, const std::string& unit,
                   double min, double max, const std::string& doc) {
  entries_.push_back({prefix_ + key, unit, doc, &ref, min, max});
}
void ParamSet::add(const std::string& key, int& ref, const std::string& unit, int min, int max,
                   const std::string& doc) {
  entries_.push_back({prefix_ + key, unit, doc, &ref, double(min), double(max)});
}

namespace {

void checkRange(const std::string& file, const ParamSet::Entry& e, double v) {
  if (!std::isfinite(v)) throw InputError(file, e.key, "value is NaN or infinite");
  if (v < e.min || v > e.max) {
    std::ostringstream os;
    os << "value " << v << " " << e.unit << " outside the allowed range [" << e.min << ", "
       << e.max << "]";
    throw InputError(file, e.key, os.str());
  }
}

bool asDouble(const ParamValue& v, double& out) {
  if (const auto* d = std::get_if<double>(&v)) { out = *d; return true; }
  return false;
}

}  // namespace

namespace {
thread_local ParamCapture* t_capture = nullptr;

std::string number(double d) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", d);
  return buf;
}

std::string valueText(const ParamSet::Entry& e) {
  if (auto* pd = std::get_if<double*>(&e.ref)) return number(**pd);
  if (auto* pi = std::get_if<int*>(&e.ref)) return std::to_string(**pi);
  if (auto* pb = std::get_if<bool*>(&e.ref)) return **pb ? "true" : "false";
  if (auto* ps = std::get_if<std::string*>(&e.ref)) return **ps;
  std::string out = "[";
  for (double d : **std::get_if<std::vector<double>*>(&e.ref)) out += (out.size() > 1 ? ", " : "") + number(d);
  return out + "]";
}
}  // namespace

void ParamSet::intendedDefault(const std::string& source) {
  if (entries_.empty() || source.empty())
    throw InputError("(parameter declaration)", entries_.empty() ? "" : entries_.back().key,
                     "intendedDefault needs a key declared before it and a source");
  entries_.back().default_source = source;
}

void requireKeys(const ParamSet& ps, const ParamSource& src, const std::vector<std::string>& set_elsewhere) {
  for (const auto& e : ps.entries()) {
    bool elsewhere = false;
    for (const auto& p : set_elsewhere) elsewhere = elsewhere || e.key.rfind(p, 0) == 0;
    if (!elsewhere && e.default_source.empty() && !src.values.count(e.key))
      throw InputError(src.file, e.key,
                       "required key missing (" + e.doc + (e.unit.empty() || e.unit == "-" ? "" : ", " + e.unit) +
                           "): a model's built-in value is never used in its place");
  }
}

ParamCapture::ParamCapture() : outer_(t_capture) { t_capture = this; }
ParamCapture::~ParamCapture() { t_capture = outer_; }

void applyParams(const ParamSet& ps, const ParamSource& src,
                 const std::vector<std::string>& ignore_prefixes) {
  const std::string& file = src.file;
  std::set<std::string> known;
  for (const auto& e : ps.entries()) {
    known.insert(e.key);
    const auto it = src.values.find(e.key);
    if (it == src.values.end()) {
      continue;  // the field keeps its value (requireKeys: only where the file may omit it)
    }
    const ParamValue& v = it->second;
    if (auto* pd = std::get_if<double*>(&e.ref)) {
      double d;
      if (!asDouble(v, d)) throw InputError(file, e.key, "expected a number (" + e.unit + ")");
      checkRange(file, e, d);
      **pd = d;
    } else if (auto* pi = std::get_if<int*>(&e.ref)) {
      double d;
      if (!asDouble(v, d) || std::floor(d) != d)
        throw InputError(file, e.key, "expected an integer (" + e.unit + ")");
      checkRange(file, e, d);
      **pi = static_cast<int>(d);
    } else if (auto* pb = std::get_if<bool*>(&e.ref)) {
      const auto* b = std::get_if<bool>(&v);
      if (!b) throw InputError(file, e.key, "expected true or false");
      **pb = *b;
    } else if (auto* ps_ = std::get_if<std::string*>(&e.ref)) {
      const auto* s = std::get_if<std::string>(&v);
      if (!s) throw InputError(file, e.key, "expected a string");
      **ps_ = *s;
    } else if (auto* pv = std::get_if<std::vector<double>*>(&e.ref)) {
      const auto* vec = std::get_if<std::vector<double>>(&v);
      if (!vec) throw InputError(file, e.key, "expected a list of numbers (" + e.unit + ")");
      for (double d : *vec) checkRange(file, e, d);
      **pv = *vec;
    }
  }
  auto declaresUnder = [&](const std::string& section) {
    for (const auto& k : known)
      if (k.rfind(section, 0) == 0) return true;
    return false;
  };
  for (const auto& kv : src.values) {
    if (known.count(kv.first)) continue;
    bool ignored = false;
    for (const auto& p : ignore_prefixes)
      if (kv.first.rfind(p, 0) == 0) ignored = true;
    for (const auto& p : kParticipantSections)  // the participant's, unless this set is that reader
      if (kv.first.rfind(p, 0) == 0 && !declaresUnder(p)) ignored = true;
    if (!ignored) throw InputError(file, kv.first, "unknown key (misspelt or not used by this model)");
  }
  if (t_capture)
    for (const auto& e : ps.entries())
      t_capture->add({file, e.key, valueText(e), e.unit, src.values.count(e.key) > 0});
}

std::string describeParams(const ParamSet& ps) {
  std::ostringstream os;
  for (const auto& e : ps.entries()) {
    os << e.key << " [" << e.unit << "]";
    if (auto* pd = std::get_if<double*>(&e.ref)) os << " = " << **pd;
    if (auto* pi = std::get_if<int*>(&e.ref)) os << " = " << **pi;
    if (auto* pb = std::get_if<bool*>(&e.ref)) os << " = " << (**pb ? "true" : "false");
    if (auto* pstr = std::get_if<std::string*>(&e.ref)) os << " = " << **pstr;
    os << "  # " << e.doc
       << (e.default_source.empty() ? " (required)" : " (intended default: " + e.default_source + ")") << "\n";
  }
  return os.str();
}

}  // namespace hbt
