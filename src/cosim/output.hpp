// An output topic of a lock-step participant (Participant::addOutput<M>). publish() hands the
// message to core::ParticipantCore::publish: it is sent only if some participant of the run reads
// its stamp (the START table's readers: a consumer stepping every 100 ms, the recorder at its
// record period), else kept back until the run's end is known, since the observers read every
// topic at t_end. So a 10 ms producer read only by 100 ms consumers sends every tenth state:
// over TCP (mode:=nodes) each message sent is a write, a wake-up and a read per subscriber.
// Tools that are not participants (rostopic echo, rviz) see the stamps the run reads.
// Observer lane: each output also has a second topic, observerLane(topic), that only the
// observers subscribe to (the recorder): it carries the stamps they read (the record period) and
// the state at t_end, so a 10 ms topic read by another participant at every step no longer
// reaches the recorder at every step too (mode:=nodes: a TCP delivery each).
//
// Every floating-point field must be finite (finite_check.hpp): a NaN or inf fails the step.
//
// Publish a boost::shared_ptr (boost::make_shared<M>(msg)), not the message by value: roscpp
// then hands intra-process subscribers (nodelets) the same object without serialising it and
// skips its poll-thread wake-up (a pipe write + thread switch per publish).
#pragma once
#include <boost/make_shared.hpp>
#include <ros/ros.h>

#include <string>

#include "cosim/core/participant_core.hpp"
#include "cosim/finite_check.hpp"
#include "cosim/local_bus.hpp"

namespace hbt::cosim {

/// The observer lane of an output topic (resolved name): "/twin/observe" + topic.
inline std::string observerLane(const std::string& resolved_topic) { return "/twin/observe" + resolved_topic; }

class Output {
 public:
  Output() = default;
  /// `datatype`: the message type's name (ros::message_traits::datatype<M>()).
  Output(ros::Publisher pub, ros::Publisher lane, core::ParticipantCore* core, std::size_t index,
         const std::string& datatype)
      : pub_(std::move(pub)),
        lane_(std::move(lane)),
        local_(std::make_shared<LocalPublisher>(LocalBus::topic(pub_.getTopic()), datatype)),
        local_lane_(std::make_shared<LocalPublisher>(LocalBus::topic(lane_.getTopic()), datatype)),
        core_(core),
        index_(index) {}

  /// Throws ModelDivergence (topic, field, value, stamp) if a floating-point field of `m` is not
  /// finite (finite_check.hpp): the step fails and the run stops there.
  template <class M>
  void publish(const boost::shared_ptr<M>& m) const {
    const std::string bad = nonFiniteField(*m);
    if (!bad.empty()) throwNotFinite(bad, m->header.stamp.toSec());
    core_->publish(index_, static_cast<core::Nanos>(m->header.stamp.toNSec()), sender(pub_, local_, m),
                   sender(lane_, local_lane_, m));
  }
  template <class M>
  void publish(const M& m) const {
    publish(boost::make_shared<M>(m));
  }
  std::string getTopic() const { return pub_.getTopic(); }
  explicit operator bool() const { return core_ != nullptr; }

 private:
  [[noreturn]] void throwNotFinite(const std::string& field_value, double stamp_s) const;
  /// Sends m to the in-process consumers, and through roscpp when others subscribe too.
  template <class M>
  static std::function<void()> sender(const ros::Publisher& p, const std::shared_ptr<LocalPublisher>& local,
                                      const boost::shared_ptr<M>& m) {
    return [p, local, m] {
      if (local->deliver(m, [&p] { return p.getNumSubscribers(); })) p.publish(m);
    };
  }
  ros::Publisher pub_, lane_;
  std::shared_ptr<LocalPublisher> local_, local_lane_;  // shared by the copies of this Output
  core::ParticipantCore* core_ = nullptr;
  std::size_t index_ = 0;
};

}  // namespace hbt::cosim
