#include "cosim/param_loader.hpp"

#include <cmath>
#include <cstdlib>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::cosim {
namespace {

void flatten(const XmlRpc::XmlRpcValue& v, const std::string& key, ParamSource& out) {
  using X = XmlRpc::XmlRpcValue;
  switch (v.getType()) {
    case X::TypeStruct:
      for (auto it = v.begin(); it != v.end(); ++it)
        flatten(it->second, key.empty() ? it->first : key + "/" + it->first, out);
      return;
    case X::TypeBoolean: out.set(key, static_cast<bool>(const_cast<X&>(v))); return;
    case X::TypeInt: out.set(key, static_cast<double>(static_cast<int>(const_cast<X&>(v)))); return;
    case X::TypeDouble: out.set(key, static_cast<double>(const_cast<X&>(v))); return;
    case X::TypeString: {
      // PyYAML (rosparam) reads YAML 1.1, where 4.27e7 without an exponent sign is a string:
      // take a string that is entirely a finite number as that number.
      const std::string s = static_cast<std::string>(const_cast<X&>(v));
      char* end = nullptr;
      const double d = s.empty() ? 0.0 : std::strtod(s.c_str(), &end);
      if (!s.empty() && *end == '\0' && std::isfinite(d)) out.set(key, d);
      else out.set(key, s);
      return;
    }
    case X::TypeArray: {
      std::vector<double> vec;
      for (int i = 0; i < v.size(); ++i) {
        X e = v[i];
        if (e.getType() == X::TypeInt) vec.push_back(static_cast<int>(e));
        else if (e.getType() == X::TypeDouble) vec.push_back(static_cast<double>(e));
        else throw InputError(out.file, key, "list element " + std::to_string(i) + " is not a number");
      }
      out.set(key, vec);
      return;
    }
    default: throw InputError(out.file, key, "unsupported parameter type");
  }
}

}  // namespace

ParamSource loadParamSource(const ros::NodeHandle& nh, const std::string& group,
                            const std::string& file) {
  ParamSource src;
  src.file = file;
  XmlRpc::XmlRpcValue v;
  const std::string ns = group.empty() ? nh.getNamespace() : nh.resolveName(group);
  if (!nh.getParam(ns, v)) return src;  // nothing set: defaults apply
  if (v.getType() != XmlRpc::XmlRpcValue::TypeStruct)
    throw InputError(file, group, "expected a group of parameters");
  flatten(v, "", src);
  return src;
}

const std::vector<std::string>& nodeKeyPrefixes() {
  static const std::vector<std::string> prefixes = [] {
    std::vector<std::string> p = {"config_file"};  // the file name itself (for messages)
    p.insert(p.end(), kParticipantSections.begin(), kParticipantSections.end());
    return p;
  }();
  return prefixes;
}

ParamSource loadModelParams(const ros::NodeHandle& pnh, const std::string& file) {
  ParamSource src = loadParamSource(pnh, "", file);
  for (auto it = src.values.begin(); it != src.values.end();) {
    bool node_key = false;
    for (const auto& p : nodeKeyPrefixes()) node_key = node_key || it->first.rfind(p, 0) == 0;
    it = node_key ? src.values.erase(it) : std::next(it);
  }
  return src;
}

void applyRosParams(const ros::NodeHandle& pnh, const ParamSet& ps, const std::string& file,
                    std::vector<std::string> ignore_prefixes, const std::vector<std::string>& set_elsewhere) {
  ignore_prefixes.insert(ignore_prefixes.end(), nodeKeyPrefixes().begin(), nodeKeyPrefixes().end());
  const ParamSource src = loadParamSource(pnh, "", file);
  std::size_t model_keys = 0;
  for (const auto& kv : src.values) {
    bool ignored = false;
    for (const auto& p : ignore_prefixes) ignored = ignored || kv.first.rfind(p, 0) == 0;
    model_keys += ignored ? 0 : 1;
  }
  // an empty (or unloaded) file would silently run the model on its built-in defaults
  if (model_keys == 0 && !ps.entries().empty())
    throw InputError(file, "", "sets no parameter of this model (empty file, or not loaded)");
  applyParams(ps, src, ignore_prefixes);
  requireKeys(ps, src, set_elsewhere);  // after: a misspelt key is named as unknown first
}

double scenarioAmbient_K(const ros::NodeHandle& nh) {
  double ambient_c = 25.0;
  nh.param("/scenario/ambient_temperature_c", ambient_c, 25.0);
  if (!(ambient_c > -60.0 && ambient_c < 60.0))
    throw InputError("scenario (launch argument)", "ambient_temperature_c", "must be in (-60, 60) degC");
  return units::celsiusToK(ambient_c);
}

bool scenarioWarmStart(const ros::NodeHandle& nh) {
  std::string start = "cold";
  nh.param<std::string>("/scenario/start", start, "cold");
  if (start != "cold" && start != "warm")
    throw InputError("scenario (launch argument start)", "start", "'" + start + "' is not a start: cold | warm");
  return start == "warm";
}

double scenarioAmbientPressure_Pa(const ros::NodeHandle& nh) {
  double p_Pa = units::kStandardAtmosphere_Pa;
  nh.param("/scenario/ambient_pressure_pa", p_Pa, p_Pa);
  if (!(p_Pa >= 5e4 && p_Pa <= 1.2e5))
    throw InputError("scenario (launch argument pressure)", "ambient_pressure_pa", "must be in [5e4, 1.2e5] Pa");
  return p_Pa;
}

std::string scenarioConfigFile(const ros::NodeHandle& nh, const std::string& relative) {
  std::string dir;
  if (!nh.getParam("/scenario/config_dir", dir) || dir.empty()) dir = resolvePackagePath(nh, "config");
  return dir + "/" + relative;
}

std::string scenarioEngineModel(const ros::NodeHandle& nh) {
  std::string model;
  if (!nh.getParam("/scenario/engine_model", model))
    throw InputError("scenario (launch argument engine)", "engine_model", "missing or not a string: map | 1d");
  return model;
}

std::string resolvePackagePath(const ros::NodeHandle& nh, const std::string& path) {
  if (path.empty() || path[0] == '/') return path;
  std::string pkg;
  nh.param<std::string>("/scenario/package_dir", pkg, ".");
  return pkg + "/" + path;
}

}  // namespace hbt::cosim
