// Per-topic input buffer of a lock-step participant: messages are kept by header.stamp so that a
// step uses exactly the inputs stamped for it, never "whatever arrived last".
#pragma once
#include <ros/ros.h>

#include <map>
#include <string>

namespace hbt::cosim {

class InputBase {
 public:
  explicit InputBase(std::string topic) : topic_(std::move(topic)) {}
  virtual ~InputBase() = default;
  const std::string& topic() const { return topic_; }
  virtual bool has(const ros::Time& t) const = 0;
  virtual void dropBefore(const ros::Time& t) = 0;
  virtual uint32_t numPublishers() const = 0;

 protected:
  std::string topic_;
};

template <class M>
class Input : public InputBase {
 public:
  using Ptr = typename M::ConstPtr;
  Input(ros::NodeHandle& nh, const std::string& topic, std::function<void()> on_arrival)
      : InputBase(topic), on_arrival_(std::move(on_arrival)) {
    sub_ = nh.subscribe<M>(topic, 1000, &Input::callback, this, ros::TransportHints().tcpNoDelay());
  }
  bool has(const ros::Time& t) const override { return buf_.count(t) > 0; }
  /// The message stamped exactly t (must be present: check has(t) first).
  const M& at(const ros::Time& t) const { return *buf_.at(t); }
  void dropBefore(const ros::Time& t) override { buf_.erase(buf_.begin(), buf_.lower_bound(t)); }
  uint32_t numPublishers() const override { return sub_.getNumPublishers(); }

 private:
  void callback(const Ptr& msg) {
    buf_[msg->header.stamp] = msg;
    on_arrival_();
  }
  ros::Subscriber sub_;
  std::map<ros::Time, Ptr> buf_;
  std::function<void()> on_arrival_;
};

}  // namespace hbt::cosim
