// In-process delivery of the lock-step topics (mode:=nodelets): a message a participant publishes
// reaches the inputs of the participants in the same process as one callback on each input's
// queue (its `cosim/thread`), with the same shared message -- not through roscpp's intra-process
// transport, whose publish takes the topic manager's, the publication's, the subscription's and
// the subscription queue's locks, allocates a deserializer per message and wakes the receiving
// thread through each of them (perf of the map baseline's manager: ~80 % of its CPU was that
// messaging for the ~1.6 million messages of a mission).
//
// Only the path changes, never what is delivered or when it may be used: an input still buffers
// the message by its stamp and the held-value rule picks the one a step reads (input_buffer.hpp),
// so results do not depend on it (runs stay bit-identical, nodes = nodelets).
//
// Who gets what:
//  - A topic's producer and its typed consumers (Input<M> of the same message type) in one
//    process: delivered here. Such an input ignores what roscpp delivers on that topic (the same
//    messages, if roscpp also publishes them).
//  - Every other subscriber -- another process (mode:=nodes, other hosts), a tool (rostopic,
//    rviz), the recorder's type-erased inputs -- is served by roscpp: the producer publishes
//    through roscpp too whenever the topic has more roscpp subscribers than direct consumers
//    (checked every kRecheckPublishes publishes, so a tool that connects mid-run is served
//    from then on).
// The roscpp subscriptions stay in place for all inputs: the link check before START, the
// master's graph (rqt_graph, rosnode info) and remote producers are unchanged.
#pragma once
#include <ros/callback_queue_interface.h>

#include <boost/shared_ptr.hpp>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace hbt::cosim {

/// An input served in-process: the message arrives as deliver() on the input's own queue.
class LocalSink {
 public:
  virtual ~LocalSink() = default;
  /// On the sink's queue (its thread): `msg` points to a message of the sink's datatype.
  virtual void deliverLocal(const boost::shared_ptr<const void>& msg) = 0;
};

/// One topic (resolved name) of this process: its local producer (if any) and direct consumers.
class LocalTopic {
 public:
  /// Every this many publishes the producer checks again whether roscpp subscribers beyond the
  /// direct consumers exist (a tool connected mid-run); the first publish always checks.
  static constexpr unsigned kRecheckPublishes = 64;

  explicit LocalTopic(std::string name) : name_(std::move(name)) {}
  const std::string& name() const { return name_; }

  /// A producer of `datatype` in this process publishes this topic (its Output).
  void setProducer(const std::string& datatype);
  /// True when a producer of `datatype` in this process publishes it: its consumer of that type
  /// ignores roscpp's deliveries (it gets each message here).
  bool servedLocally(const std::string& datatype) const;

  /// A consumer of `datatype` whose callbacks run on `queue` (unregister before it is destroyed:
  /// its pending deliveries are removed from the queue).
  void addConsumer(LocalSink* sink, const std::string& datatype, ros::CallbackQueueInterface* queue);
  void removeConsumer(LocalSink* sink);

  /// Delivers `msg` (of `datatype`) to the direct consumers; returns how many got it.
  std::size_t deliver(const boost::shared_ptr<const void>& msg, const std::string& datatype);

 private:
  struct Consumer {
    LocalSink* sink;
    std::string datatype;
    ros::CallbackQueueInterface* queue;
  };
  std::string name_;
  mutable std::mutex m_;
  std::string producer_datatype_;  // empty: no producer in this process
  std::vector<Consumer> consumers_;
};

/// The process's topics (one registry per process: every nodelet of the manager shares it).
class LocalBus {
 public:
  static std::shared_ptr<LocalTopic> topic(const std::string& resolved_name);
};

/// The producer's side: delivers in-process and decides whether roscpp must publish too.
class LocalPublisher {
 public:
  LocalPublisher(std::shared_ptr<LocalTopic> topic, std::string datatype);
  ~LocalPublisher();  // the topic has no local producer from then on
  LocalPublisher(const LocalPublisher&) = delete;
  LocalPublisher& operator=(const LocalPublisher&) = delete;
  /// Delivers `msg` to the direct consumers; true when roscpp must publish it as well
  /// (`ros_subscribers`: roscpp's count, read only every kRecheckPublishes calls).
  template <class CountRosSubscribers>
  bool deliver(const boost::shared_ptr<const void>& msg, CountRosSubscribers&& ros_subscribers) {
    const std::size_t direct = topic_->deliver(msg, datatype_);
    if (publishes_++ % LocalTopic::kRecheckPublishes == 0) ros_needed_ = ros_subscribers() > direct;
    return ros_needed_;
  }

 private:
  std::shared_ptr<LocalTopic> topic_;
  std::string datatype_;
  unsigned publishes_ = 0;
  bool ros_needed_ = true;
};

}  // namespace hbt::cosim
