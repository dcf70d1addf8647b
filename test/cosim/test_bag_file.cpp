// BagFileWriter (src/cosim/bag_file.hpp) against rosbag::Bag, the reference implementation of the
// format: for the same write() calls the two files are equal byte for byte -- several chunks,
// messages of several types, a type known only at run time (topic_tools::ShapeShifter, as the
// recorder's raw topics), times out of order within a chunk, a message larger than the write
// block and than a chunk -- and rosbag reads every message back. A bag never closed is the
// unindexed bag `rosbag reindex` repairs; a failed write (a full device) throws, not lost silently.
#include <gtest/gtest.h>
#include <rosbag/bag.h>
#include <rosbag/view.h>
#include <std_msgs/Float64.h>
#include <std_msgs/String.h>
#include <topic_tools/shape_shifter.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cosim/bag_file.hpp"

namespace {

using hbt::cosim::BagFileWriter;

std::string tmpFile(const std::string& name) {
  return (testing::TempDir().empty() ? std::string("/tmp/") : testing::TempDir()) + "hbt_bag_file_" + name;
}

std::vector<char> bytes(const std::string& file) {
  std::ifstream f(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

/// A std_msgs/Float64 as a ShapeShifter: the type, md5sum and definition known only at run time.
topic_tools::ShapeShifter shapeShifted(double x) {
  std_msgs::Float64 m;
  m.data = x;
  std::vector<uint8_t> buf(ros::serialization::serializationLength(m));
  ros::serialization::OStream out(buf.data(), buf.size());
  ros::serialization::serialize(out, m);
  topic_tools::ShapeShifter s;
  s.morph(ros::message_traits::md5sum(m), ros::message_traits::datatype(m), ros::message_traits::definition(m), "");
  ros::serialization::IStream in(buf.data(), buf.size());
  ros::serialization::deserialize(in, s);
  return s;
}

// The same calls to either writer: n records of three topics (a float, a string growing with i,
// a run-time-typed float), every 7th record's string written out of time order, and one
// message larger than a chunk in the middle.
template <class Sink>
void writeSequence(Sink&& sink, int n) {
  for (int i = 0; i < n; ++i) {
    ros::Time t;
    t.fromNSec(1 + 100000000ull * static_cast<uint64_t>(i));  // 0.1 s records
    std_msgs::Float64 x;
    x.data = 0.25 * i;
    std_msgs::String s;
    s.data = std::string(static_cast<std::size_t>(i % 50), 'a') + std::to_string(i);
    if (i == n / 2) s.data.assign(BagFileWriter::kChunkThreshold_bytes + 12345, 'z');
    sink("/a/state", t, x);
    sink("/b/text", i % 7 == 3 ? t - ros::Duration(0.05) : t, s);
    sink("/c/raw", t, shapeShifted(-0.5 * i));
  }
}

TEST(BagFileWriter, SameBytesAsRosbag) {
  const std::string ref = tmpFile("rosbag.bag"), own = tmpFile("own.bag");
  const int n = 40000;  // ~2.5 MB: several chunks
  {
    rosbag::Bag bag(ref, rosbag::bagmode::Write);
    writeSequence([&](const std::string& topic, const ros::Time& t, const auto& m) { bag.write(topic, t, m); }, n);
  }
  BagFileWriter w(own);
  writeSequence([&](const std::string& topic, const ros::Time& t, const auto& m) { w.write(topic, t, m); }, n);
  w.close();
  EXPECT_EQ(w.messages(), std::size_t(3 * n));
  const auto a = bytes(ref), b = bytes(own);
  ASSERT_GT(a.size(), std::size_t(2 * BagFileWriter::kChunkThreshold_bytes));
  ASSERT_EQ(a.size(), b.size());
  std::size_t first_diff = 0;
  while (first_diff < a.size() && a[first_diff] == b[first_diff]) ++first_diff;
  EXPECT_EQ(first_diff, a.size()) << "first differing byte at " << first_diff;

  // rosbag reads every message back, in order, intact
  rosbag::Bag in(own, rosbag::bagmode::Read);
  int i = 0, raw = 0, big = 0;
  for (const rosbag::MessageInstance& m : rosbag::View(in)) {
    if (m.getTopic() == "/a/state") {
      auto x = m.instantiate<std_msgs::Float64>();
      ASSERT_TRUE(x);
      EXPECT_EQ(x->data, 0.25 * i++);
    } else if (m.getTopic() == "/c/raw") {
      EXPECT_EQ(m.getDataType(), "std_msgs/Float64");
      EXPECT_EQ(m.instantiate<std_msgs::Float64>()->data, -0.5 * raw++);
    } else if (m.instantiate<std_msgs::String>()->data.size() > BagFileWriter::kChunkThreshold_bytes) {
      ++big;
    }
  }
  EXPECT_EQ(i, n);
  EXPECT_EQ(raw, n);
  EXPECT_EQ(big, 1);
}

TEST(BagFileWriter, EmptyBagIsTheSameAsRosbags) {
  const std::string ref = tmpFile("empty_rosbag.bag"), own = tmpFile("empty_own.bag");
  { rosbag::Bag bag(ref, rosbag::bagmode::Write); }
  { BagFileWriter w(own); }  // closed by its destructor
  EXPECT_EQ(bytes(ref), bytes(own));
  EXPECT_EQ(bytes(own).size(), std::size_t(13 + 4 + 4096 + 4));  // version line + padded file header
}

// A writer killed before close() (the process dies) leaves the unindexed bag rosbag reports as
// such (`rosbag reindex` rebuilds its index from the chunks written).
TEST(BagFileWriter, KilledWriterLeavesAnUnindexedBag) {
  const std::string file = tmpFile("killed.bag");
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    BagFileWriter w(file);
    writeSequence([&](const std::string& topic, const ros::Time& t, const auto& m) { w.write(topic, t, m); }, 20000);
    _exit(0);  // no close, no destructor
  }
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_GT(bytes(file).size(), std::size_t(BagFileWriter::kChunkThreshold_bytes));
  EXPECT_THROW(rosbag::Bag(file, rosbag::bagmode::Read), rosbag::BagUnindexedException);
}

TEST(BagFileWriter, FailedWritesThrow) {
  EXPECT_THROW(BagFileWriter("/nonexistent_dir_hbt/run.bag"), std::runtime_error);
  // /dev/full: every write fails with ENOSPC, as on a full disk
  BagFileWriter w("/dev/full");
  std_msgs::String s;
  s.data.assign(BagFileWriter::kWriteBlock_bytes, 'x');  // fills the write block: a write is due
  try {
    w.write("/a", ros::Time(1, 0), s);
    w.write("/a", ros::Time(2, 0), s);
    w.close();
    FAIL() << "no error writing to /dev/full";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos) << e.what();
  }
  EXPECT_THROW(w.write("/a", ros::Time(3, 0), s), std::runtime_error);  // and after it, again
  EXPECT_THROW(w.close(), std::runtime_error);
}

}  // namespace
