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

#include <memory>
#include <string>

#include "cosim/participant.hpp"
#include "fmi/message_layout.hpp"

namespace hbt::fmi {

class FmuParticipant;

/// A message this participant publishes: fields set by index, then published stamped t.
class OutPort {
 public:
  virtual ~OutPort() = default;
  virtual const MessageLayout& layout() const = 0;
  /// Sets field `field` (element `element` of a float64[] field, else -1) to v (bool: v != 0;
  /// integer types: v rounded).
  virtual void set(std::size_t field, int element, double v) = 0;
  /// Sizes the float64[] field `field` to n elements.
  virtual void resize(std::size_t field, std::size_t n) = 0;
  virtual void publish(const ros::Time& t) = 0;
};

/// A message this participant reads: the message held for its step at t, field by field.
class InPort {
 public:
  virtual ~InPort() = default;
  virtual const MessageLayout& layout() const = 0;
  /// Field `field` (element `element` of a float64[] field) of the message held at t, as a
  /// double; an element beyond the array's length throws hbt::ModelDivergence.
  virtual double get(const ros::Time& t, std::size_t field, int element) const = 0;
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
