// Field-by-field access to the twin's messages for a participant that learns its message types
// at run time (the FMU participant): one typed publisher or subscriber per topic (so nodelets
// still hand the message object itself to typed subscribers, and the recorder records it like
// any other), with every field reached by its index in the type's MessageLayout.
//
// One definition of every field: the layout (names, types) is parsed from the type's own
// definition text (ros::message_traits::definition<M>(), i.e. msg/*.msg), the storage of each
// field is found by running the type's generated serialiser (Serializer<M>::allInOne, which
// visits every field in definition order) over a visitor that records each field's offset and
// C++ type; the two are checked against each other once per type. Every message type of the
// package is available (the list is generated from msg/ by src/fmi/node/CMakeLists.txt).
#pragma once
#include <ros/ros.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "cosim/participant.hpp"
#include "fmi/message_layout.hpp"

namespace hbt::fmi {

class FmuParticipant;

/// How one field is stored in the C++ message: its C++ type and byte offset (found once per
/// type by the serialiser's visit), and the element of a float64[] field (-1: a scalar).
enum class Store { kDouble, kFloat, kU8, kI8, kU16, kI16, kU32, kI32, kU64, kI64, kVecDouble, kOther };
struct FieldSlot {
  Store store = Store::kOther;
  std::size_t offset = 0;
  int element = -1;
};

/// The field at s of the message at msg as a double (bool: 0/1); an element beyond a float64[]
/// field's length throws hbt::ModelDivergence naming `topic`.
inline double readField(const void* msg, const FieldSlot& s, const std::string& topic);
/// Sets the field at s of the message at msg to v (bool: v != 0 as 1/0; integer types: v rounded).
inline void writeField(void* msg, const FieldSlot& s, double v);

/// A message this participant publishes: fields set by index, then published stamped t.
class OutPort {
 public:
  virtual ~OutPort() = default;
  virtual const MessageLayout& layout() const = 0;
  /// Sets field `field` (element `element` of a float64[] field, else -1) to v (bool: v != 0;
  /// integer types: v rounded).
  virtual void set(std::size_t field, int element, double v) = 0;
  /// Where field `field` (element `element`) is stored, for writeField() on message().
  virtual FieldSlot slot(std::size_t field, int element) const = 0;
  /// The message the next publish() sends (a copy of it, stamped): its fields are written here.
  virtual void* message() = 0;
  /// Sizes the float64[] field `field` to n elements.
  virtual void resize(std::size_t field, std::size_t n) = 0;
  virtual void publish(const ros::Time& t) = 0;
};

/// A message this participant reads: the message held for its step at t, field by field.
class InPort {
 public:
  virtual ~InPort() = default;
  virtual const MessageLayout& layout() const = 0;
  /// Where field `field` (element `element`) is stored, for readField() on message(t).
  virtual FieldSlot slot(std::size_t field, int element) const = 0;
  /// The message held for the step at t (the lock-step's held-value rule): one lookup, then
  /// any number of fields read from it with readField().
  virtual const void* message(const ros::Time& t) const = 0;
  virtual const std::string& topic() const = 0;
};

/// Makes ports of message type `datatype` ("hybrid_bus_twin/BatteryState") through the
/// participant's own addInput/addOutput (the lock-step's held-value rule and output lanes).
class PortFactory {
 public:
  /// The layout of datatype; hbt::InputError naming `where` and `key` when the package has no such type.
  static MessageLayout layoutOf(const std::string& datatype, const std::string& where, const std::string& key);
  /// True when the package defines datatype.
  static bool known(const std::string& datatype);
  /// The ports, made through p's typed addOutput<M> / addInput<M>; datatype must be known().
  static std::unique_ptr<OutPort> output(const std::string& datatype, FmuParticipant& p, const std::string& topic);
  static std::unique_ptr<InPort> input(const std::string& datatype, FmuParticipant& p, const std::string& topic);
};

}  // namespace hbt::fmi

namespace hbt::fmi {

namespace detail {
template <class T>
T& fieldAt(void* msg, const FieldSlot& s) {
  return *reinterpret_cast<T*>(static_cast<char*>(msg) + s.offset);
}
template <class T>
const T& fieldAt(const void* msg, const FieldSlot& s) {
  return *reinterpret_cast<const T*>(static_cast<const char*>(msg) + s.offset);
}
}  // namespace detail

inline void writeField(void* msg, const FieldSlot& s, double v) {
  using detail::fieldAt;
  switch (s.store) {
    case Store::kDouble: fieldAt<double>(msg, s) = v; break;
    case Store::kU8: fieldAt<uint8_t>(msg, s) = static_cast<uint8_t>(std::lround(v)); break;
    case Store::kI8: fieldAt<int8_t>(msg, s) = static_cast<int8_t>(std::lround(v)); break;
    case Store::kU16: fieldAt<uint16_t>(msg, s) = static_cast<uint16_t>(std::lround(v)); break;
    case Store::kI16: fieldAt<int16_t>(msg, s) = static_cast<int16_t>(std::lround(v)); break;
    case Store::kU32: fieldAt<uint32_t>(msg, s) = static_cast<uint32_t>(std::llround(v)); break;
    case Store::kI32: fieldAt<int32_t>(msg, s) = static_cast<int32_t>(std::lround(v)); break;
    case Store::kU64: fieldAt<uint64_t>(msg, s) = static_cast<uint64_t>(std::llround(v)); break;
    case Store::kI64: fieldAt<int64_t>(msg, s) = static_cast<int64_t>(std::llround(v)); break;
    case Store::kVecDouble: fieldAt<std::vector<double>>(msg, s).at(static_cast<std::size_t>(s.element)) = v; break;
    default: throw std::logic_error("field not writable");
  }
}

inline double readField(const void* msg, const FieldSlot& s, const std::string& topic) {
  using detail::fieldAt;
  switch (s.store) {
    case Store::kDouble: return fieldAt<double>(msg, s);
    case Store::kU8: return fieldAt<uint8_t>(msg, s);
    case Store::kI8: return fieldAt<int8_t>(msg, s);
    case Store::kU16: return fieldAt<uint16_t>(msg, s);
    case Store::kI16: return fieldAt<int16_t>(msg, s);
    case Store::kU32: return fieldAt<uint32_t>(msg, s);
    case Store::kI32: return fieldAt<int32_t>(msg, s);
    case Store::kU64: return static_cast<double>(fieldAt<uint64_t>(msg, s));
    case Store::kI64: return static_cast<double>(fieldAt<int64_t>(msg, s));
    case Store::kVecDouble: {
      const auto& vec = fieldAt<std::vector<double>>(msg, s);
      if (s.element < 0 || static_cast<std::size_t>(s.element) >= vec.size())
        throw ModelDivergence(topic, "element " + std::to_string(s.element),
                              "the message has " + std::to_string(vec.size()) + " elements");
      return vec[static_cast<std::size_t>(s.element)];
    }
    default: throw std::logic_error("field not readable");
  }
}

}  // namespace hbt::fmi
