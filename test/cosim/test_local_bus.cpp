// LocalTopic / LocalPublisher (src/cosim/local_bus.hpp), without a master: a message reaches each
// direct consumer of its type once, on that consumer's own queue, the shared message itself;
// roscpp must publish exactly when someone else listens -- a second roscpp subscriber link
// beyond the process's own (another process, a tool), an in-process roscpp-only consumer, a
// consumer of another type -- and that is re-checked every kRecheckPublishes publishes; a
// consumer removed gets nothing more, not even what was queued for it. A consumer whose queue is
// served by the publishing thread itself (LocalBus::serveThread) gets the message through that
// thread's FIFO, not its callback queue; from any other thread, through the queue.
#include <gtest/gtest.h>
#include <ros/callback_queue.h>

#include <boost/make_shared.hpp>
#include <thread>
#include <vector>

#include "cosim/local_bus.hpp"

namespace {

using hbt::cosim::LocalBus;
using hbt::cosim::LocalPublisher;
using hbt::cosim::LocalSink;
using hbt::cosim::LocalTopic;

struct Sink : LocalSink {
  std::vector<const void*> got;
  void deliverLocal(const boost::shared_ptr<const void>& msg) override { got.push_back(msg.get()); }
};

/// Two consumers of "pkg/A" on one queue and a producer of the topic `name`; removed at the end.
struct TwoConsumers {
  explicit TwoConsumers(const std::string& name) : topic(LocalBus::topic(name)) {
    topic->addConsumer(&a, "pkg/A", &q);
    topic->addConsumer(&b, "pkg/A", &q);
  }
  ~TwoConsumers() {
    topic->removeConsumer(&a);
    topic->removeConsumer(&b);
  }
  std::shared_ptr<LocalTopic> topic;
  ros::CallbackQueue q;
  Sink a, b;
  LocalPublisher pub{topic, "pkg/A"};
};

TEST(LocalBus, DeliversOnEachConsumersQueue) {
  auto topic = LocalBus::topic("/test_local_bus/a");
  EXPECT_EQ(topic, LocalBus::topic("/test_local_bus/a"));  // one per name in the process
  ros::CallbackQueue q1, q2;
  Sink a, b, other_type;
  topic->addConsumer(&a, "pkg/A", &q1);
  topic->addConsumer(&b, "pkg/A", &q2);
  topic->addConsumer(&other_type, "pkg/B", &q1);
  EXPECT_FALSE(topic->servedLocally("pkg/A"));  // no producer here yet
  auto msg = boost::make_shared<const double>(1.5);
  {
    LocalPublisher pub(topic, "pkg/A");
    EXPECT_TRUE(topic->servedLocally("pkg/A"));
    EXPECT_FALSE(topic->servedLocally("pkg/B"));
    pub.deliver(msg, [] { return 1; });
    EXPECT_TRUE(a.got.empty());  // not called in the publisher's thread: queued
    q1.callAvailable();
    ASSERT_EQ(a.got.size(), 1u);
    EXPECT_EQ(a.got[0], msg.get());  // the shared message, not a copy
    EXPECT_TRUE(b.got.empty());      // b's queue not served yet
    q2.callAvailable();
    EXPECT_EQ(b.got.size(), 1u);
    EXPECT_TRUE(other_type.got.empty());
  }
  EXPECT_FALSE(topic->servedLocally("pkg/A"));  // the producer is gone
  topic->removeConsumer(&a);
  topic->removeConsumer(&b);
  topic->removeConsumer(&other_type);
}

TEST(LocalBus, RoscppPublishesOnlyForOtherListeners) {
  TwoConsumers c("/test_local_bus/b");
  auto& [topic, q, a, b, pub] = c;
  auto msg = boost::make_shared<const int>(3);
  int links = 1;  // roscpp: both in-process consumers share the process's one subscriber link
  int counted = 0;
  auto count = [&] { ++counted; return links; };
  EXPECT_FALSE(pub.deliver(msg, count));
  EXPECT_EQ(counted, 1);  // the first publish asks roscpp
  links = 2;              // a tool (or another host) subscribes
  for (unsigned i = 1; i < LocalTopic::kRecheckPublishes; ++i) EXPECT_FALSE(pub.deliver(msg, count));
  EXPECT_EQ(counted, 1);  // ... noticed at the next check
  EXPECT_TRUE(pub.deliver(msg, count));
  EXPECT_EQ(counted, 2);
  links = 1;
  for (unsigned i = 0; i < LocalTopic::kRecheckPublishes; ++i) pub.deliver(msg, count);
  EXPECT_FALSE(pub.deliver(msg, count));
  // an in-process roscpp-only consumer (a type-erased input): roscpp at once, every publish
  topic->addRosConsumer();
  EXPECT_TRUE(pub.deliver(msg, count));
  topic->removeRosConsumer();
  q.callAvailable();
  EXPECT_EQ(a.got.size(), 3u + 2 * LocalTopic::kRecheckPublishes);  // every publish, roscpp or not
  EXPECT_EQ(b.got.size(), a.got.size());
}

TEST(LocalBus, NoDirectConsumerMeansRoscppForAnySubscriber) {
  auto topic = LocalBus::topic("/test_local_bus/c");
  LocalPublisher pub(topic, "pkg/A");
  auto msg = boost::make_shared<const int>(4);
  EXPECT_TRUE(pub.deliver(msg, [] { return 1; }));   // the one link is someone else's
  LocalPublisher pub2(LocalBus::topic("/test_local_bus/c2"), "pkg/A");
  EXPECT_FALSE(pub2.deliver(msg, [] { return 0; }));  // nobody listens
}

TEST(LocalBus, RemovedConsumerGetsNothingQueued) {
  TwoConsumers c("/test_local_bus/d");
  auto& [topic, q, a, b, pub] = c;
  pub.deliver(boost::make_shared<const int>(5), [] { return 1; });
  topic->removeConsumer(&a);  // its queued delivery goes with it
  q.callAvailable();
  EXPECT_TRUE(a.got.empty());
  EXPECT_EQ(b.got.size(), 1u);
  pub.deliver(boost::make_shared<const int>(6), [] { return 1; });
  q.callAvailable();
  EXPECT_TRUE(a.got.empty());
  EXPECT_EQ(b.got.size(), 2u);
}

TEST(LocalBus, OwnThreadDeliversThroughItsFifo) {
  ros::CallbackQueue q;
  hbt::cosim::LocalThreadQueue fifo;
  LocalBus::serveThread(&q, &fifo, std::this_thread::get_id());
  auto topic = LocalBus::topic("/test_local_bus/e");
  Sink a;
  topic->addConsumer(&a, "pkg/A", &q);
  LocalPublisher pub(topic, "pkg/A");
  auto msg = boost::make_shared<const int>(7);
  pub.deliver(msg, [] { return 1; });
  EXPECT_TRUE(q.isEmpty());  // not through the callback queue
  EXPECT_FALSE(fifo.empty());
  EXPECT_TRUE(fifo.drain());
  ASSERT_EQ(a.got.size(), 1u);
  EXPECT_EQ(a.got[0], msg.get());
  EXPECT_FALSE(fifo.drain());
  std::thread other([&] { pub.deliver(msg, [] { return 1; }); });  // another thread: the queue
  other.join();
  EXPECT_TRUE(fifo.empty());
  EXPECT_FALSE(q.isEmpty());
  q.callAvailable();
  EXPECT_EQ(a.got.size(), 2u);
  pub.deliver(msg, [] { return 1; });
  topic->removeConsumer(&a);  // what is pending in the FIFO goes too
  EXPECT_TRUE(fifo.empty());
  LocalBus::unserveThread(&q);
}

}  // namespace
