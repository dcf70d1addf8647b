// AsyncBagWriter (src/cosim/bag_writer.hpp): the bag written on the writer thread is byte for byte
// the bag an inline rosbag::Bag::write gives for the same calls (order and content: run.bag stays
// deterministic); a small queue forces the producer to wait (back-pressure) without losing or
// reordering anything; a bag that cannot be opened, or a write after close, is an error.
#include <gtest/gtest.h>
#include <rosbag/view.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>

#include <boost/make_shared.hpp>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "cosim/bag_writer.hpp"

namespace {

std::string tmpFile(const std::string& name) {
  return (testing::TempDir().empty() ? std::string("/tmp/") : testing::TempDir()) + "hbt_bag_writer_" + name;
}

std::vector<char> bytes(const std::string& file) {
  std::ifstream f(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// the same sequence of two topics (the twin writes a few topics per record stamp)
template <class Sink>
void writeSequence(Sink&& sink, int n) {
  for (int i = 0; i < n; ++i) {
    ros::Time t;
    t.fromNSec(1 + 10000000ull * static_cast<uint64_t>(i));  // 10 ms records
    std_msgs::Float64 x;
    x.data = 0.5 * i;
    std_msgs::String s;
    s.data = "step " + std::to_string(i);
    sink("/a/state", t, x);
    sink("/b/state", t, s);
  }
}

TEST(AsyncBagWriter, SameBytesAsInlineWrite) {
  const std::string inline_file = tmpFile("inline.bag"), async_file = tmpFile("async.bag");
  const int n = 5000;
  {
    rosbag::Bag bag(inline_file, rosbag::bagmode::Write);
    writeSequence([&](const std::string& topic, const ros::Time& t, const auto& m) { bag.write(topic, t, m); }, n);
  }
  // the default budget, and 1 byte: one message at a time, the producer waits for each
  for (std::size_t max_queued : {hbt::cosim::AsyncBagWriter::kDefaultMaxQueued_bytes, std::size_t(1)}) {
    hbt::cosim::AsyncBagWriter w(async_file, max_queued);
    writeSequence([&](const std::string& topic, const ros::Time& t, const auto& m) {
      using M = std::decay_t<decltype(m)>;
      w.write(topic, t, std::make_shared<const M>(m));
    }, n);
    w.close();
    EXPECT_EQ(w.written(), std::size_t(2 * n));
    const auto a = bytes(inline_file), b = bytes(async_file);
    ASSERT_GT(a.size(), std::size_t(2 * n * 8));
    EXPECT_TRUE(a == b) << "queue " << max_queued << ": " << a.size() << " vs " << b.size() << " bytes";
  }
  // and it reads back in order, every message intact
  rosbag::Bag in(async_file, rosbag::bagmode::Read);
  int i = 0;
  for (const rosbag::MessageInstance& m : rosbag::View(in, rosbag::TopicQuery(std::vector<std::string>{"/a/state"}))) {
    auto x = m.instantiate<std_msgs::Float64>();
    ASSERT_TRUE(x);
    ASSERT_EQ(x->data, 0.5 * i);
    ++i;
  }
  EXPECT_EQ(i, n);
}

// The budget bounds what the queue holds: never more bytes than the budget (a job is counted as
// its serialised message + topic + kJobOverhead_bytes), and a budget below one job's size queues
// one message at a time; the high-water marks say what it held at most.
TEST(AsyncBagWriter, QueueBudgetBoundsTheMemory) {
  using hbt::cosim::AsyncBagWriter;
  const std::size_t float_job_bytes = 8 + std::string("/a/state").size() + AsyncBagWriter::kJobOverhead_bytes;
  const std::size_t budget = 10 * float_job_bytes;
  for (std::size_t max_queued : {std::size_t(1), budget}) {
    AsyncBagWriter w(tmpFile("budget.bag"), max_queued);
    for (int i = 0; i < 20000; ++i)
      w.write("/a/state", ros::Time(1 + i, 0), std::make_shared<const std_msgs::Float64>());
    const hbt::cosim::BagQueueStats s = w.queueStats();
    w.close();
    EXPECT_EQ(w.written(), std::size_t(20000));
    EXPECT_GE(s.high_water_messages, std::size_t(1));
    EXPECT_EQ(s.high_water_bytes, s.high_water_messages * float_job_bytes);  // one kind of job
    if (max_queued == 1)
      EXPECT_EQ(s.high_water_messages, std::size_t(1));
    else
      EXPECT_LE(s.high_water_bytes, budget);
  }
}

TEST(AsyncBagWriter, ErrorsAreNotSilent) {
  EXPECT_ANY_THROW(hbt::cosim::AsyncBagWriter("/nonexistent_dir_hbt/run.bag"));
  hbt::cosim::AsyncBagWriter w(tmpFile("closed.bag"));
  w.write("/a", ros::Time(1, 0), boost::make_shared<const std_msgs::Float64>());
  w.close();
  EXPECT_EQ(w.written(), 1u);
  EXPECT_THROW(w.write("/a", ros::Time(2, 0), boost::make_shared<const std_msgs::Float64>()), std::runtime_error);
}

}  // namespace
