// The mapping between an FMU's variables and the messages of the participant it serves
// (README.md "The FMU participant"): which FMU input each field the participant reads feeds,
// which FMU output each field it publishes comes from, the fields it does not provide (with the
// value they are published as), the FMU parameters it sets, with every unit conversion:
//     field -> FMU:  value_FMU = fmu.fromSi(field.toSi(value_field))
//     FMU -> field:  value_field = field.fromSi(fmu.toSi(value_FMU))
// (no arithmetic when the FMU declares the field's own unit: the value is passed as it is).
// (fmu: the FMU variable's declared unit, field: the unit its name states, message_layout.hpp).
//
// Naming convention (an FMU exported by this project needs no mapping file):
//   - FMU input  `<producer>.<key>.<field>`: the field of /<producer>/<key> (another participant);
//     `<a>|<b>.<key>.<field>`: the same of the first of the alternative producers a, b that
//     publishes /<producer>/<key> in the scenario (the engine's command: ems|vehicle);
//   - FMU output `<participant>.<key>.<field>`: the field of /<participant>/<key> it publishes;
//   - FMU parameter `scenario.<name>`: set from /scenario/<name> (unit as the name says).
// Explicit entries of the mapping file take precedence. ROS-free: the node reads the mapping
// file (rosparams) into a MappingSpec and the message definitions into MessageLayouts.
// Rejections: an FmuError naming the FMU file (a variable missing, of the wrong causality,
// variability, type or unit) or an InputError naming the mapping file and key.
#pragma once
#include <functional>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "fmi/fmu_archive.hpp"
#include "fmi/message_layout.hpp"

namespace hbt::fmi {

/// What the mapping file says (all optional; no file = the naming convention alone).
struct MappingSpec {
  std::string file = "(no mapping file: the naming convention)";  // for messages
  std::optional<InterfaceType> interface;  // absent: CoSimulation if the FMU has it, else ModelExchange
  std::optional<double> me_rtol, me_atol;  // Model Exchange: CVODE tolerances [-], [state units]
  std::optional<long> me_max_steps;        // CVODE internal steps per segment between events
  /// field "<participant>.<key>.<field>" (an array element "<...>.values[i]") <-> FMU variable;
  /// unit: the SI unit of an array element (unitNamed), empty for scalar fields.
  struct Link {
    std::string field, variable, unit;
  };
  std::vector<Link> inputs, outputs;
  /// An output field the FMU does not provide: published as `value` (field units), and why.
  struct Fixed {
    std::string field;
    double value = 0.0;
    std::string reason;
  };
  std::vector<Fixed> not_provided;
  /// An FMU parameter set before initialisation: value in SI (converted to the variable's
  /// declared unit), or an Integer / Boolean.
  struct Param {
    std::string variable;
    double value = 0.0;
    VarType type = VarType::kReal;  // the YAML value's type: kReal (a number), kInteger, kBoolean
  };
  std::vector<Param> parameters;
};

/// What the participant knows of its scenario when the mapping is resolved.
struct MappingContext {
  std::string participant;
  /// key -> the message it publishes under /<participant>/<key> (its topics.yaml).
  std::map<std::string, MessageLayout> publishes;
  /// The message /<producer>/<key> carries; nullopt when the producer does not run or does not
  /// declare key (the node asks src/cosim/wiring).
  std::function<std::optional<MessageLayout>(const std::string& producer, const std::string& key)> produced;
  /// The numeric values under /scenario/ (name -> value in the unit its name states).
  std::map<std::string, double> scenario;
};

/// One field <-> one FMU variable.
struct Binding {
  std::string participant, key;  // the topic /<participant>/<key>
  std::size_t field = 0;         // index in its MessageLayout::fields()
  int element = -1;              // array element (ProbeSignal values[i]); -1 = scalar
  std::string field_name;        // "<participant>.<key>.<field>" as written
  std::string variable;
  VarType type = VarType::kReal;
  std::string fmu_unit;          // as the FMU declares it ("" = none)
  UnitConversion fmu;            // FMU unit -> SI
  FieldUnit unit;                // the field's unit
  /// The FMU declares the field's own unit (same factor and offset to SI, e.g. A.h for a field
  /// _ah): the value passes unchanged, bit for bit (3600 v / 3600 may differ from v in the last bit).
  bool sameUnit() const { return fmu.factor == unit.factor && fmu.offset == unit.offset; }
  double fieldFromFmu(double v) const { return sameUnit() ? v : unit.fromSi(fmu.toSi(v)); }
  double fmuFromField(double v) const { return sameUnit() ? v : fmu.fromSi(unit.toSi(v)); }
};

struct FixedOutput {
  std::string key;
  std::size_t field = 0;
  std::string field_name, reason;
  double value = 0.0;
};

struct ParamSetting {
  std::string variable;
  VarType type = VarType::kReal;
  double value_fmu = 0.0;  // in the FMU's declared unit
  std::string source;      // "mapping file" or "/scenario/<name>"
};

struct ResolvedMapping {
  InterfaceType interface = InterfaceType::kCoSimulation;
  double me_rtol = 0.0, me_atol = 0.0;
  long me_max_steps = 0;
  std::vector<Binding> inputs, outputs;
  std::vector<FixedOutput> not_provided;
  std::vector<ParamSetting> parameters;
  /// Output key -> number of elements of its float64[] field (0: no array field).
  std::map<std::string, std::size_t> array_sizes;

  /// The resolved mapping as CSV (direction, field, variable, units, factors, value, source).
  void writeCsv(std::ostream& os, const std::string& fmu_file) const;
};

/// Resolves spec against the FMU's description and the scenario; every check of the header
/// comment, before step 0.
ResolvedMapping resolveMapping(const MappingSpec& spec, const ModelDescription& md, const MappingContext& ctx);

}  // namespace hbt::fmi
