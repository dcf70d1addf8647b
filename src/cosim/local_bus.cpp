#include "cosim/local_bus.hpp"

#include <ros/callback_queue_interface.h>

#include <algorithm>
#include <boost/make_shared.hpp>
#include <map>

namespace hbt::cosim {

namespace {

/// One message for one consumer, called on the consumer's queue.
class Delivery : public ros::CallbackInterface {
 public:
  Delivery(LocalSink* sink, boost::shared_ptr<const void> msg) : sink_(sink), msg_(std::move(msg)) {}
  CallResult call() override {
    sink_->deliverLocal(msg_);
    return Success;
  }

 private:
  LocalSink* sink_;
  boost::shared_ptr<const void> msg_;
};

uint64_t removalId(const LocalSink* sink) { return reinterpret_cast<uint64_t>(sink); }

}  // namespace

void LocalTopic::setProducer(const std::string& datatype) {
  std::lock_guard<std::mutex> lk(m_);
  producer_datatype_ = datatype;
}

bool LocalTopic::servedLocally(const std::string& datatype) const {
  std::lock_guard<std::mutex> lk(m_);
  return !producer_datatype_.empty() && producer_datatype_ == datatype;
}

void LocalTopic::addConsumer(LocalSink* sink, const std::string& datatype, ros::CallbackQueueInterface* queue) {
  const auto thread = LocalBus::threadOf(queue);
  std::lock_guard<std::mutex> lk(m_);
  consumers_.push_back({sink, datatype, queue, thread.first, thread.second});
}

void LocalTopic::removeConsumer(LocalSink* sink) {
  ros::CallbackQueueInterface* queue = nullptr;
  LocalThreadQueue* fifo = nullptr;
  {
    std::lock_guard<std::mutex> lk(m_);
    const auto it = std::find_if(consumers_.begin(), consumers_.end(), [&](const Consumer& c) { return c.sink == sink; });
    if (it == consumers_.end()) return;
    queue = it->queue;
    fifo = it->own_thread_queue;
    consumers_.erase(it);
  }
  if (queue) queue->removeByID(removalId(sink));  // nothing of it is called after this
  if (fifo) fifo->remove(sink);                    // (its thread is stopped: nodelet unload)
}

void LocalTopic::addRosConsumer() {
  std::lock_guard<std::mutex> lk(m_);
  ++ros_consumers_;
}

void LocalTopic::removeRosConsumer() {
  std::lock_guard<std::mutex> lk(m_);
  if (ros_consumers_ > 0) --ros_consumers_;
}

LocalTopic::Delivered LocalTopic::deliver(const boost::shared_ptr<const void>& msg, const std::string& datatype) {
  std::lock_guard<std::mutex> lk(m_);
  Delivered d;
  d.ros_consumer = ros_consumers_ > 0;
  for (const Consumer& c : consumers_) {
    if (c.datatype != datatype || !c.queue) {
      d.ros_consumer = true;  // another type on this topic: roscpp's business (and its error)
      continue;
    }
    if (c.own_thread_queue && c.owner == std::this_thread::get_id())
      c.own_thread_queue->post(c.sink, msg);  // published on the consumer's own thread
    else
      c.queue->addCallback(boost::make_shared<Delivery>(c.sink, msg), removalId(c.sink));
    ++d.direct;
  }
  return d;
}

bool LocalThreadQueue::drain() {
  if (items_.empty()) return false;
  while (!items_.empty()) {
    Item item = std::move(items_.front());
    items_.pop_front();
    item.sink->deliverLocal(item.msg);  // may post more: delivered in this same loop
  }
  return true;
}

void LocalThreadQueue::remove(const LocalSink* sink) {
  items_.erase(std::remove_if(items_.begin(), items_.end(), [&](const Item& i) { return i.sink == sink; }),
               items_.end());
}

namespace {
std::mutex threads_mutex;
std::map<ros::CallbackQueueInterface*, std::pair<LocalThreadQueue*, std::thread::id>>& threads() {
  static std::map<ros::CallbackQueueInterface*, std::pair<LocalThreadQueue*, std::thread::id>> t;
  return t;
}
}  // namespace

void LocalBus::serveThread(ros::CallbackQueueInterface* queue, LocalThreadQueue* fifo, std::thread::id owner) {
  std::lock_guard<std::mutex> lk(threads_mutex);
  threads()[queue] = {fifo, owner};
}

void LocalBus::unserveThread(ros::CallbackQueueInterface* queue) {
  std::lock_guard<std::mutex> lk(threads_mutex);
  threads().erase(queue);
}

std::pair<LocalThreadQueue*, std::thread::id> LocalBus::threadOf(ros::CallbackQueueInterface* queue) {
  std::lock_guard<std::mutex> lk(threads_mutex);
  const auto it = threads().find(queue);
  return it == threads().end() ? std::pair<LocalThreadQueue*, std::thread::id>{nullptr, {}} : it->second;
}

std::shared_ptr<LocalTopic> LocalBus::topic(const std::string& resolved_name) {
  static std::mutex m;
  static std::map<std::string, std::shared_ptr<LocalTopic>> topics;
  std::lock_guard<std::mutex> lk(m);
  auto& t = topics[resolved_name];
  if (!t) t = std::make_shared<LocalTopic>(resolved_name);
  return t;
}

LocalPublisher::LocalPublisher(std::shared_ptr<LocalTopic> topic, std::string datatype)
    : topic_(std::move(topic)), datatype_(std::move(datatype)) {
  topic_->setProducer(datatype_);
}

LocalPublisher::~LocalPublisher() { topic_->setProducer(""); }

}  // namespace hbt::cosim
