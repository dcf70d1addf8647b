// Per-topic input buffer of a lock-step participant: messages are kept by header.stamp so that a
// step uses exactly the message its held-value rule names (core::HeldRule, set at START from the
// producer's macro step and group), never "whatever arrived last". A typed input is served
// in-process when its producer runs in the same process (local_bus.hpp), else by roscpp.
#pragma once
#include <ros/callback_queue.h>
#include <ros/ros.h>

#include <functional>
#include <map>
#include <string>

#include "cosim/core/participant_core.hpp"
#include "cosim/local_bus.hpp"

namespace hbt::cosim {

inline ros::Time fromNanos(core::Nanos ns) {
  ros::Time t;
  t.fromNSec(static_cast<uint64_t>(ns));
  return t;
}

class InputBase : public core::InputPort {
 public:
  explicit InputBase(std::string topic) : topic_(std::move(topic)) {}
  const std::string& topic() const { return topic_; }
  /// True if the message stamped exactly t is buffered.
  virtual bool has(const ros::Time& t) const = 0;
  virtual void dropBefore(const ros::Time& t) = 0;
  virtual uint32_t numPublishers() const = 0;
  /// Stamp of the message read for a step starting at t (t itself until START; see participant.hpp).
  ros::Time heldStamp(const ros::Time& t) const { return fromNanos(stampFor(t.toNSec())); }

  std::string resolvedTopic() const override { return topic_; }
  bool hasStamp(core::Nanos s) const override { return has(fromNanos(s)); }
  void dropStampsBefore(core::Nanos s) override { dropBefore(fromNanos(s)); }

 protected:
  std::string topic_;
};

template <class M>
class Input : public InputBase, public LocalSink {
 public:
  using Ptr = typename M::ConstPtr;
  /// Reads `topic`; `subscribe_to` (if not empty) is the ROS topic its messages come from (the
  /// recorder: the producer's observer lane, output.hpp) -- the input is still `topic`'s.
  Input(ros::NodeHandle& nh, const std::string& topic, std::function<void()> on_arrival,
        const std::string& subscribe_to = "")
      : InputBase(topic), resolved_(nh.resolveName(topic)), on_arrival_(std::move(on_arrival)) {
    const std::string source = subscribe_to.empty() ? topic : subscribe_to;
    local_ = LocalBus::topic(nh.resolveName(source));
    ros::CallbackQueueInterface* queue = nh.getCallbackQueue();
    local_->addConsumer(this, ros::message_traits::datatype<M>(), queue ? queue : ros::getGlobalCallbackQueue());
    sub_ = nh.subscribe<M>(source, 1000, &Input::callback, this, ros::TransportHints().tcpNoDelay());
  }
  ~Input() override {
    sub_.shutdown();
    local_->removeConsumer(this);
  }
  bool has(const ros::Time& t) const override { return buf_.count(t) > 0; }
  /// The input of the step starting at t: the message stamped heldStamp(t) (present once the
  /// participant's step(t, dt) is called).
  const M& at(const ros::Time& t) const { return *buf_.at(heldStamp(t)); }
  void dropBefore(const ros::Time& t) override { buf_.erase(buf_.begin(), buf_.lower_bound(t)); }
  uint32_t numPublishers() const override { return sub_.getNumPublishers(); }
  std::string resolvedTopic() const override { return resolved_; }
  void deliverLocal(const boost::shared_ptr<const void>& msg) override {
    store(boost::static_pointer_cast<const M>(msg));
  }

 private:
  void callback(const Ptr& msg) {
    if (local_->servedLocally(ros::message_traits::datatype<M>())) return;  // arrives by deliverLocal
    store(msg);
  }
  void store(const Ptr& msg) {
    buf_[msg->header.stamp] = msg;
    on_arrival_();
  }
  std::string resolved_;
  std::shared_ptr<LocalTopic> local_;
  ros::Subscriber sub_;
  std::map<ros::Time, Ptr> buf_;
  std::function<void()> on_arrival_;
};

}  // namespace hbt::cosim
