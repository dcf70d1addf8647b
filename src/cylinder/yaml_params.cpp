#include "cylinder/yaml_params.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <vector>

#include "common/errors.hpp"

namespace hbt::cyl {
namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

std::string stripComment(const std::string& s) {
  bool sq = false, dq = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\'' && !dq) sq = !sq;
    if (s[i] == '"' && !sq) dq = !dq;
    if (s[i] == '#' && !sq && !dq && (i == 0 || s[i - 1] == ' ' || s[i - 1] == '\t'))
      return s.substr(0, i);
  }
  return s;
}

bool parseNumber(const std::string& t, double& v) {
  if (t.empty()) return false;
  char* end = nullptr;
  v = std::strtod(t.c_str(), &end);
  return end && *end == '\0';
}

ParamValue parseScalar(const std::string& t, const std::string& file, const std::string& key) {
  double v;
  if (t == "true" || t == "True") return true;
  if (t == "false" || t == "False") return false;
  if (parseNumber(t, v)) return v;
  if (t.size() >= 2 && (t.front() == '"' || t.front() == '\'') && t.back() == t.front())
    return t.substr(1, t.size() - 2);
  if (t.empty()) throw InputError(file, key, "empty value");
  return t;
}

}  // namespace

ParamSource parseYamlParams(const std::string& text, const std::string& file) {
  ParamSource src;
  src.file = file;
  std::vector<std::pair<int, std::string>> stack;  // (indent, key)
  std::istringstream in(text);
  std::string raw;
  int lineno = 0;
  while (std::getline(in, raw)) {
    ++lineno;
    std::string line = stripComment(raw);
    if (trim(line).empty()) continue;
    if (line.find('\t') != std::string::npos)
      throw InputError(file, "line " + std::to_string(lineno), "tab characters are not allowed");
    const int indent = static_cast<int>(line.find_first_not_of(' '));
    const std::string body = trim(line);
    const auto colon = body.find(':');
    if (colon == std::string::npos || body[0] == '-')
      throw InputError(file, "line " + std::to_string(lineno), "expected 'key: value'");
    const std::string key = trim(body.substr(0, colon));
    std::string value = trim(body.substr(colon + 1));
    while (!stack.empty() && stack.back().first >= indent) stack.pop_back();
    std::string full;
    for (const auto& s : stack) full += s.second + "/";
    full += key;
    if (value.empty()) {
      stack.emplace_back(indent, key);
      continue;
    }
    if (value[0] == '[') {
      while (value.find(']') == std::string::npos) {
        if (!std::getline(in, raw))
          throw InputError(file, full, "unterminated list starting at line " + std::to_string(lineno));
        ++lineno;
        value += " " + trim(stripComment(raw));
      }
      const auto close = value.find(']');
      if (!trim(value.substr(close + 1)).empty())
        throw InputError(file, full, "text after ']'");
      std::vector<double> list;
      std::stringstream ss(value.substr(1, close - 1));
      std::string item;
      while (std::getline(ss, item, ',')) {
        item = trim(item);
        if (item.empty()) continue;
        double v;
        if (!parseNumber(item, v)) throw InputError(file, full, "non-numeric list item '" + item + "'");
        list.push_back(v);
      }
      src.set(full, list);
      continue;
    }
    src.set(full, parseScalar(value, file, full));
  }
  return src;
}

ParamSource readYamlParams(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw InputError(path, "(file)", "cannot open");
  std::stringstream ss;
  ss << f.rdbuf();
  return parseYamlParams(ss.str(), path);
}

}  // namespace hbt::cyl
