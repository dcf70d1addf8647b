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
//    through roscpp too whenever the topic has such subscribers. roscpp counts all subscribers
//    inside one process as one link (they share one subscription), so that is: more roscpp
//    subscriber links than the one of the direct consumers, or an in-process roscpp-only
//    consumer registered here (addRosConsumer: the recorder's type-erased inputs). Checked every
//    kRecheckPublishes publishes, so a tool that connects mid-run is served from then on.
//    A subscriber inside the nodelet manager that is neither a participant's input nor
//    registered here (a nodelet of one's own subscribing with roscpp) shares that one link and
//    is not seen: it receives the topic only while something else makes roscpp publish it. Run
//    such a subscriber in a process of its own, or as a participant.
// The roscpp subscriptions stay in place for all inputs: the link check before START, the
// master's graph (rqt_graph, rosnode info) and remote producers are unchanged.
#pragma once
#include <ros/callback_queue_interface.h>

#include <boost/shared_ptr.hpp>
#include <deque>
#include <thread>
#include <utility>
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

/// The deliveries a thread makes to consumers on its own queue (a LockstepQueue's thread: the
/// torque loop's participants publish to each other): a plain FIFO the thread drains between
/// its queue's callbacks, without the callback queue's locks and an allocation per message.
/// Used only by its owner thread (post, drain), or while that thread is stopped (remove).
class LocalThreadQueue {
 public:
  void post(LocalSink* sink, boost::shared_ptr<const void> msg) { items_.push_back({sink, std::move(msg)}); }
  /// Delivers everything posted, also what is posted meanwhile; false if there was nothing.
  bool drain();
  bool empty() const { return items_.empty(); }
  /// Drops what is pending for `sink`.
  void remove(const LocalSink* sink);

 private:
  struct Item {
    LocalSink* sink;
    boost::shared_ptr<const void> msg;
  };
  std::deque<Item> items_;
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

  /// An in-process consumer served by roscpp only (a type-erased input): the producer always
  /// publishes through roscpp while one is registered.
  void addRosConsumer();
  void removeRosConsumer();

  /// What deliver() did: direct consumers served, and whether an in-process consumer needs roscpp.
  struct Delivered {
    std::size_t direct = 0;
    bool ros_consumer = false;  // a roscpp-only or other-typed consumer in this process
  };
  /// Delivers `msg` (of `datatype`) to the direct consumers.
  Delivered deliver(const boost::shared_ptr<const void>& msg, const std::string& datatype);

 private:
  struct Consumer {
    LocalSink* sink;
    std::string datatype;
    ros::CallbackQueueInterface* queue;
    LocalThreadQueue* own_thread_queue;  // the queue's thread's FIFO (LocalBus::serveThread), or null
    std::thread::id owner;               // that thread
  };
  std::string name_;
  mutable std::mutex m_;
  std::string producer_datatype_;  // empty: no producer in this process
  std::vector<Consumer> consumers_;
  std::size_t ros_consumers_ = 0;
};

/// The process's topics (one registry per process: every nodelet of the manager shares it).
class LocalBus {
 public:
  static std::shared_ptr<LocalTopic> topic(const std::string& resolved_name);
  /// `queue`'s callbacks run on thread `owner`, which also drains `fifo`: a consumer on `queue`
  /// gets what that same thread publishes through `fifo` (registered before the consumers).
  static void serveThread(ros::CallbackQueueInterface* queue, LocalThreadQueue* fifo, std::thread::id owner);
  static void unserveThread(ros::CallbackQueueInterface* queue);
  /// The FIFO and owner registered for `queue` ({null, id()} if none).
  static std::pair<LocalThreadQueue*, std::thread::id> threadOf(ros::CallbackQueueInterface* queue);
};

/// The producer's side: delivers in-process and decides whether roscpp must publish too.
class LocalPublisher {
 public:
  LocalPublisher(std::shared_ptr<LocalTopic> topic, std::string datatype);
  ~LocalPublisher();  // the topic has no local producer from then on
  LocalPublisher(const LocalPublisher&) = delete;
  LocalPublisher& operator=(const LocalPublisher&) = delete;
  /// Delivers `msg` to the direct consumers; true when roscpp must publish it as well
  /// (`ros_subscriber_links`: roscpp's Publisher::getNumSubscribers(), read only every
  /// kRecheckPublishes calls; the process's own subscribers are one link of it).
  template <class CountRosSubscriberLinks>
  bool deliver(const boost::shared_ptr<const void>& msg, CountRosSubscriberLinks&& ros_subscriber_links) {
    const LocalTopic::Delivered d = topic_->deliver(msg, datatype_);
    if (publishes_++ % LocalTopic::kRecheckPublishes == 0) {
      const std::size_t own_link = d.direct > 0 ? 1 : 0;
      ros_needed_ = d.ros_consumer || static_cast<std::size_t>(ros_subscriber_links()) > own_link;
    }
    return ros_needed_ || d.ros_consumer;
  }

 private:
  std::shared_ptr<LocalTopic> topic_;
  std::string datatype_;
  unsigned publishes_ = 0;
  bool ros_needed_ = true;
};

}  // namespace hbt::cosim
