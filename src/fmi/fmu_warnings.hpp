// The warnings an FMU raises for the participant it serves (README.md, naming convention of the
// project's FMUs): a Boolean output `<participant>.warning.<name>` is the participant's warning
// <name>, raised while the variable is true. The FMU holds the thresholds and the persistence
// itself; the FMU participant declares each such warning with no on-delay, so it is raised at the
// first state time the FMU reports it true, and cleared when it reports it false. ROS-free.
#pragma once
#include <string>
#include <vector>

#include "fmi/model_description.hpp"

namespace hbt::fmi {

struct WarningOutput {
  std::string name;      // the warning: boost_limited
  std::string variable;  // the FMU output: engine.warning.boost_limited
};

/// The FMU's Boolean outputs named `<participant>.warning.<name>`, in declaration order. A
/// variable of that name that is not a Boolean output is an FmuError naming the FMU and variable.
std::vector<WarningOutput> warningOutputs(const ModelDescription& md, const std::string& participant);

/// The message of a raised warning: the FMU file and variable, and the FMU's log message of the
/// step that raised it (last_log; "" = it logged none).
std::string warningMessage(const std::string& fmu_file, const WarningOutput& w, const std::string& last_log);

}  // namespace hbt::fmi
