// The parameters of an exported model from its FMU's resources/ (src/fmi/export): the model's
// YAML read with the node's checks (an unknown key or a bad value named first, then every
// declared key required), the node's own keys (cosim/, diagnostics/: cosim::nodeKeyPrefixes)
// ignored; a data file the YAML names is taken from resources/ under its own file name.
// Throws hbt::InputError naming the file and key.
#pragma once
#include <filesystem>
#include <string>
#include <utility>

#include "common/params.hpp"
#include "common/yaml_params.hpp"

namespace hbt::fmi::exported {

/// The model's keys of a YAML in resources/ (the node's own keys removed), for a model that
/// reads its ParamSource itself (as cosim::loadModelParams gives it to the node).
inline ParamSource readResourceSource(const std::string& yaml_file) {
  ParamSource src = readYamlParams(yaml_file);
  for (auto it = src.values.begin(); it != src.values.end();) {
    bool node_key = false;
    for (const auto& p : kParticipantSections) node_key = node_key || it->first.rfind(p, 0) == 0;
    it = node_key ? src.values.erase(it) : std::next(it);
  }
  return src;
}

inline void applyResourceParams(const ParamSet& ps, const std::string& yaml_file) {
  const ParamSource src = readYamlParams(yaml_file);
  applyParams(ps, src, kParticipantSections);
  requireKeys(ps, src);
}

/// A model's parameter struct (declare(ParamSet&)) from its YAML, as applyResourceParams reads it.
template <class Params>
Params readResourceParams(const std::string& yaml_file) {
  Params p;
  ParamSet ps;
  p.declare(ps);
  applyResourceParams(ps, yaml_file);
  return p;
}

/// A participant's warning thresholds W (declare(ParamSet&, declare_args...)) from the
/// `diagnostics:` section of its YAML in resources/, read as cosim::Participant::readWarningThresholds
/// reads them for the node: that section only, every declared key required.
template <class W, class... Args>
W readResourceWarnings(const std::string& yaml_file, Args&&... declare_args) {
  static const std::string kSection = "diagnostics/";
  W w;
  ParamSet ps;
  ps.setPrefix(kSection);
  w.declare(ps, std::forward<Args>(declare_args)...);
  ps.setPrefix("");
  const ParamSource all = readYamlParams(yaml_file);
  ParamSource own;
  own.file = all.file;
  for (const auto& kv : all.values)
    if (kv.first.rfind(kSection, 0) == 0) own.values.insert(kv);
  applyParams(ps, own);
  requireKeys(ps, own);
  return w;
}

/// resources_dir/<file name of configured_path>
inline std::string resourceFile(const std::string& resources_dir, const std::string& configured_path) {
  return resources_dir + "/" + std::filesystem::path(configured_path).filename().string();
}

}  // namespace hbt::fmi::exported
