// One topic the recorder writes: its lock-step input (held-value rule, input_buffer.hpp) and how
// to write the message held at t into the bag. Typed for the twin's own messages: an
// intra-process subscriber of the publisher's own type (nodelets) gets the published object
// itself, never serialised, and the publisher never wakes roscpp's poll thread for it (a
// type-erased topic_tools::ShapeShifter subscriber forces both at every publish: 8-12 topics at
// every base step). The message is serialised only when it is written (record_period), on the
// bag writer's thread (bag_writer.hpp).
// Any other type is recorded type-erased (ShapeShifter): the recorder still records anything.
#pragma once
#include <ros/ros.h>

#include <functional>
#include <memory>
#include <string>

#include "cosim/bag_writer.hpp"
#include "cosim/input_buffer.hpp"

namespace hbt::cosim {

class RecordedTopic {
 public:
  virtual ~RecordedTopic() = default;
  /// The lock-step input (owned by the participant base class once handed over).
  virtual InputBase* input() = 0;
  /// Queues the message held at t for the bag, with bag time bag_t.
  virtual void write(AsyncBagWriter& bag, const ros::Time& bag_t, const ros::Time& t) const = 0;
  const std::string& topic() { return input()->topic(); }
};

/// `datatype` as the master reports it (e.g. "hybrid_bus_twin/EngineState"; "" = unknown): a
/// typed topic for the twin's messages, else type-erased. `subscribe_to`: the ROS topic the
/// messages of `topic` come from ("" = `topic`; a participant's output: its observer lane,
/// output.hpp). The returned object's input() must be handed to Participant::addCustomInput
/// (ownership), the RecordedTopic kept by the recorder.
std::unique_ptr<RecordedTopic> makeRecordedTopic(const std::string& datatype, ros::NodeHandle& nh,
                                                 const std::string& topic, std::function<void()> on_arrival,
                                                 const std::string& subscribe_to,
                                                 std::unique_ptr<InputBase>& input_out);

}  // namespace hbt::cosim
