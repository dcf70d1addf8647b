#include "common/yaml_params.hpp"

#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"

namespace hbt {
namespace {

void walk(const YAML::Node& n, const std::string& key, ParamSource& out) {
  if (n.IsMap()) {
    for (const auto& kv : n) {
      const std::string k = kv.first.as<std::string>();
      walk(kv.second, key.empty() ? k : key + "/" + k, out);
    }
  } else if (n.IsSequence()) {
    std::vector<double> v;
    for (std::size_t i = 0; i < n.size(); ++i) {
      const std::string s = n[i].as<std::string>();
      char* end = nullptr;
      const double d = std::strtod(s.c_str(), &end);
      if (s.empty() || *end != '\0')
        throw InputError(out.file, key, "list element " + std::to_string(i) + " '" + s +
                                            "' is not a number");
      v.push_back(d);
    }
    out.set(key, v);
  } else if (n.IsScalar()) {
    const std::string s = n.as<std::string>();
    char* end = nullptr;
    const double d = std::strtod(s.c_str(), &end);
    if (s == "true" || s == "false") out.set(key, s == "true");
    else if (!s.empty() && *end == '\0') out.set(key, d);
    else out.set(key, s);
  } else if (n.IsNull() && !key.empty()) {
    out.set(key, std::string());
  }
}

}  // namespace

ParamSource parseYamlParams(const std::string& text, const std::string& file_name) {
  ParamSource src;
  src.file = file_name;
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(file_name, "line " + std::to_string(e.mark.line + 1), e.msg);
  }
  walk(root, "", src);
  return src;
}

void applyParamFile(const ParamSet& ps, const std::string& path) {
  const ParamSource src = readYamlParams(path);
  applyParams(ps, src);
  requireKeys(ps, src);  // after: a misspelt key is named as unknown first
}

ParamSource readYamlParams(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "(file)", "cannot open file (missing or unreadable)");
  std::stringstream ss;
  ss << in.rdbuf();
  return parseYamlParams(ss.str(), path);
}

}  // namespace hbt
