#include "fmi/fmu_warnings.hpp"

#include "fmi/fmu_error.hpp"

namespace hbt::fmi {

std::vector<WarningOutput> warningOutputs(const ModelDescription& md, const std::string& participant) {
  const std::string prefix = participant + ".warning.";
  std::vector<WarningOutput> out;
  for (const auto& v : md.variables()) {
    if (v.name.size() <= prefix.size() || v.name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string name = v.name.substr(prefix.size());
    if (v.causality != Causality::kOutput || v.type != VarType::kBoolean)
      throw FmuError(md.fmuFile(), "variable " + v.name + " names a warning of " + participant +
                                       " (<participant>.warning.<name>) but is not a Boolean output");
    if (name.find('.') != std::string::npos)
      throw FmuError(md.fmuFile(), "variable " + v.name + ": a warning name has no '.'");
    out.push_back({name, v.name});
  }
  return out;
}

std::string warningMessage(const std::string& fmu_file, const WarningOutput& w, const std::string& last_log) {
  std::string m = "raised by FMU " + fmu_file + " (output " + w.variable + " true)";
  if (!last_log.empty()) m += "; its log: " + last_log;
  return m;
}

}  // namespace hbt::fmi
