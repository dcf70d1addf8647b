// What an exported FMU declares (src/fmi/export): its variables, read from the model's export
// spec (src/<model>/fmu/<model>_fmu.yaml) and the message definitions msg/*.msg, named by the
// naming convention of the project's FMUs (src/fmi/README.md):
//   input  <producer>.<key>.<field>     a field the participant reads from /<producer>/<key>;
//          <a>|<b>.<key>.<field>        ... from the first of the alternative producers a, b that runs
//   output <participant>.<key>.<field>  every field of the message it publishes on /<participant>/<key>
//   output <participant>.warning.<name> Boolean, true while its warning <name> is raised (spec `warnings`)
//   parameter scenario.<name>           a scenario value /scenario/<name> it reads
// Units: the field's, as its name suffix states (unitOfName, message_layout.hpp); descriptions:
// the comment of the field's line in its .msg; value references 0.. in declaration order.
// From the description: modelDescription.xml (FMI 2.0 Co-Simulation) with a deterministic GUID
// (FNV-1a 64 of the text written without it), and the C++ header of the binary's variables (one
// member per variable, the member names = the message's field names, so that the model's
// conversion templates work on them as on the ROS messages).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "fmi/message_layout.hpp"

namespace hbt::fmi::exported {

struct ExportedVariable {
  std::string name;         // e.g. battery.state.soc
  std::string group;        // C++ member of the generated Variables: battery_state, scenario
  std::string member;       // the field: soc
  FieldKind kind = FieldKind::kFloat64;
  std::string causality;    // input | output | parameter
  FieldUnit unit;
  std::string description;
  double start = 0.0;       // inputs and parameters
  std::optional<double> min, max;
};

struct FmuDescription {
  std::string model_identifier;
  std::string description;
  std::string config_file;                 // package-relative: -> resources/<basename>
  std::vector<std::string> config_files;   // further YAMLs the model reads (spec `configs`): -> resources/<basename>
  std::vector<std::string> data_files;     // package-relative paths named by the configs: -> resources/<basename>
  double step_size_s = 0.0;  // the participant's macro step: cosim/macro_step_s of its config, else the spec's step_size_s
  std::vector<ExportedVariable> variables;

  /// Reads the spec file and the message definitions of `msg_dir`; package-relative paths
  /// against `package_root`. Throws hbt::InputError naming the file and key.
  static FmuDescription read(const std::string& spec_file, const std::string& msg_dir, const std::string& package_root);
  /// modelDescription.xml, with its GUID.
  std::string modelDescriptionXml() const;
  std::string guid() const;
  /// The header of the binary's variables (namespace hbt::fmi::exported::generated).
  std::string variablesHeader() const;
};

/// The FMI unit name of a field unit ("W", "degC", "A.h", "%"), "" for dimensionless factor 1.
std::string fmiUnitName(const FieldUnit& u);

}  // namespace hbt::fmi::exported
