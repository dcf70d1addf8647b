// Minimal reader for the commented rosparam YAML files of config/ (test helper only): maps
// "key: value" lines (nested blocks by indentation -> "parent/child") to an hbt::ParamSource,
// so tests can check that every YAML key is declared by the model and every value is valid.
// Supports numbers, "strings", true/false and [number, ...] lists; '#' starts a comment.
#pragma once
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/params.hpp"

namespace hbt::testutil {

inline std::string trimYaml(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

inline ParamValue parseYamlScalar(const std::string& v, const std::string& where) {
  if (v.size() >= 2 && (v.front() == '"' || v.front() == '\''))
    return v.substr(1, v.size() - 2);
  if (v == "true") return true;
  if (v == "false") return false;
  if (v.front() == '[') {
    std::vector<double> out;
    std::string body = v.substr(1, v.find(']') - 1), cell;
    std::size_t pos = 0;
    while (pos <= body.size()) {
      const auto c = body.find(',', pos);
      cell = trimYaml(body.substr(pos, c == std::string::npos ? std::string::npos : c - pos));
      if (!cell.empty()) {
        char* end = nullptr;
        out.push_back(std::strtod(cell.c_str(), &end));
        if (*end != '\0') throw std::runtime_error(where + ": bad list element " + cell);
      }
      if (c == std::string::npos) break;
      pos = c + 1;
    }
    return out;
  }
  char* end = nullptr;
  const double d = std::strtod(v.c_str(), &end);
  if (*end != '\0') throw std::runtime_error(where + ": cannot parse value '" + v + "'");
  return d;
}

inline ParamSource readFlatYaml(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  ParamSource src;
  src.file = path;
  std::vector<std::pair<std::size_t, std::string>> stack;  // (indent, key)
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    std::string s = line;
    bool inq = false;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s[i] == '"') inq = !inq;
      if (s[i] == '#' && !inq) { s = s.substr(0, i); break; }
    }
    if (trimYaml(s).empty()) continue;
    const std::size_t indent = s.find_first_not_of(' ');
    const auto colon = s.find(':');
    if (colon == std::string::npos) throw std::runtime_error(path + ":" + std::to_string(n) + ": no ':'");
    const std::string key = trimYaml(s.substr(0, colon));
    const std::string val = trimYaml(s.substr(colon + 1));
    while (!stack.empty() && stack.back().first >= indent) stack.pop_back();
    std::string full;
    for (const auto& p : stack) full += p.second + "/";
    full += key;
    if (val.empty()) { stack.push_back({indent, key}); continue; }
    src.set(full, parseYamlScalar(val, path + ":" + std::to_string(n)));
  }
  return src;
}

}  // namespace hbt::testutil
