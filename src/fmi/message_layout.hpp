// The fields of one of the twin's flat ROS messages (msg/*.msg: a std_msgs/Header and scalars,
// ProbeSignal's float64[] values), read from the message definition text, and the SI unit of
// each field as its name says (the naming rule of the package: a unit suffix, SI inside):
//     value_SI = factor * value_field + offset
// e.g. power_w -> W (factor 1), charge_throughput_ah -> A.s (factor 3600), grade_percent -> 1
// (factor 0.01), ambient_temperature_c -> K (offset 273.15), soc (no unit suffix) -> 1.
// ROS-free: the text is what ros::message_traits::definition<M>() returns or the .msg file holds.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "fmi/units.hpp"

namespace hbt::fmi {

/// How a field is stored: float64, bool, an integer type, a float64[] array, or anything the
/// FMU participant cannot map (string, other arrays, float32).
enum class FieldKind { kFloat64, kBool, kInteger, kFloat64Array, kUnsupported };
const char* name(FieldKind k);

/// The SI unit of a field and the conversion of its values: value_SI = factor * value + offset.
struct FieldUnit {
  SiUnit si;
  double factor = 1.0;
  double offset = 0.0;
  double toSi(double v) const { return factor * v + offset; }
  double fromSi(double v_si) const { return (v_si - offset) / factor; }
};

/// The unit a field (or scenario parameter) name states by its suffix (the longest match of the
/// table in message_layout.cpp); a name without a unit suffix is dimensionless.
FieldUnit unitOfName(const std::string& field_name);
/// The unit called `si_name` ("K", "W", "J", "s", "A", "V", "N.m", "kg", "Pa", "mol", "m",
/// "rad", "rad/s", "m/s", "m/s2", "kg/s", "m3/s", "W/K", "1"); nullopt if it is none of these.
std::optional<FieldUnit> unitNamed(const std::string& si_name);

struct FieldInfo {
  std::string name;
  std::string type;  // as the definition writes it: "float64", "bool", "int32", "float64[]"
  FieldKind kind = FieldKind::kUnsupported;
};

/// The fields of one message type, in the order of its definition (the header excluded).
class MessageLayout {
 public:
  /// Parses the definition text of `datatype` ("hybrid_bus_twin/BatteryState"): the lines up to
  /// the first "===" line (the embedded definitions of nested types); comments and constants
  /// skipped; the std_msgs/Header field is not a field here.
  static MessageLayout parse(const std::string& datatype, const std::string& definition);

  const std::string& datatype() const { return datatype_; }
  const std::vector<FieldInfo>& fields() const { return fields_; }
  /// Index of the field called name in fields(); nullopt if there is none.
  std::optional<std::size_t> find(const std::string& name) const;
  /// True when the definition has a std_msgs/Header (every lock-step message must).
  bool hasHeader() const { return has_header_; }

 private:
  std::string datatype_;
  std::vector<FieldInfo> fields_;
  bool has_header_ = false;
};

}  // namespace hbt::fmi
