// A rosbag written by a thread of its own. The recorder's lock-step thread only copies the
// message held at t and queues it; serialisation and the file write (BagFileWriter, bag_file.hpp)
// run on the writer thread, i.e. on the second core while the participants compute the next steps.
// Order: jobs are written strictly in the order they were queued (one FIFO, one writer), so the
// bag is byte-for-byte the one an inline writer gives (determinism is unchanged).
// Memory: the queued jobs hold at most `max_queued_bytes` (each counted as its message's serialised
// length + kJobOverhead_bytes); a producer that gets ahead blocks until the writer catches up
// (back-pressure instead of growth). A job is always accepted into an empty queue, so one message
// larger than the budget still passes. queueStats() gives the high-water mark: the memory the
// queue held at most, which the process's heap keeps after the queue drains (glibc returns freed
// small chunks to its arena, not to the system) -- the soak bench compares the manager's memory
// rise within a mission with it.
// Wake-ups: the writer drains the queue and then sleeps kPoll_s; a producer wakes it only when
// the queue holds 1/kWakeFraction of its budget (or at close). A wake-up per message (a futex
// call each, ~730,000 in a mission) cost the recorder more than the write itself once that got
// cheap.
// Errors: a failed write (disk full, ...) is remembered; the next write() or close() throws it
// as std::runtime_error naming the file, so the run stops instead of losing data silently.
#pragma once
#include "cosim/bag_file.hpp"

#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace hbt::cosim {

/// "writing <file>: <what>", and the cause where the file system tells it: "no space left on the
/// device (0 bytes free)" when the device holding `file` is full.
std::string describeWriteFailure(const std::string& file, const std::string& what);

/// The queue's high-water marks and how often the producer had to wait for the writer.
struct BagQueueStats {
  std::size_t high_water_bytes = 0;     // [B] most bytes queued at once (kJobOverhead_bytes included)
  std::size_t high_water_messages = 0;  // most messages queued at once
  std::size_t producer_waits = 0;       // writes that waited for space (back-pressure)
};

class AsyncBagWriter {
 public:
  /// [B] Queue budget of run.bag's writer: 4 MiB is ~10^4 of the twin's messages (~300 B each with
  /// the job), about 1.5 s of simulated time of a mission -- it absorbs the writer thread being
  /// descheduled for a while, and bounds what a starved writer makes the process hold.
  static constexpr std::size_t kDefaultMaxQueued_bytes = 4u << 20;
  /// [B] Memory of one queued job beside its message: the std::function with its captures (topic
  /// string, time, shared pointer) on the heap, the deque slot, the message's own allocation header.
  static constexpr std::size_t kJobOverhead_bytes = 160;
  /// [s] The writer's sleep when the queue is empty (a queue that fills faster wakes it earlier).
  static constexpr double kPoll_s = 2e-3;
  /// A producer wakes the writer once the queue holds max_queued_bytes / kWakeFraction.
  static constexpr std::size_t kWakeFraction = 4;

  /// Opens `file` for writing (throws std::runtime_error naming it) and starts the writer thread.
  explicit AsyncBagWriter(const std::string& file, std::size_t max_queued_bytes = kDefaultMaxQueued_bytes);
  ~AsyncBagWriter();
  AsyncBagWriter(const AsyncBagWriter&) = delete;
  AsyncBagWriter& operator=(const AsyncBagWriter&) = delete;

  /// Queues the message behind `m` (a std:: or boost:: shared pointer the writer keeps until it
  /// is written: the caller must not change the message) for `topic` at bag time `t`.
  template <class Ptr>
  void write(const std::string& topic, const ros::Time& t, Ptr m) {
    const std::size_t bytes = ros::serialization::serializationLength(*m) + topic.size() + kJobOverhead_bytes;
    push([topic, t, m](BagFileWriter& bag) { bag.write(topic, t, *m); }, bytes);
  }
  /// Writes everything queued, stops the thread and closes the bag; throws a write error.
  void close();
  /// Messages written so far (for tests and diagnostics).
  std::size_t written() const;
  /// The queue's high-water marks so far (diagnostics of the recorder).
  BagQueueStats queueStats() const;

 private:
  using Job = std::function<void(BagFileWriter&)>;
  struct Queued {
    Job job;
    std::size_t bytes;  // [B] counted against the budget
  };
  void push(Job job, std::size_t bytes);
  void run();
  void throwIfFailed();

  std::string file_;
  std::size_t max_queued_bytes_;
  std::unique_ptr<BagFileWriter> bag_;
  mutable std::mutex m_;
  std::condition_variable cv_work_, cv_space_;
  std::deque<Queued> queue_;
  std::size_t queued_bytes_ = 0;  // [B] sum of queue_'s bytes
  BagQueueStats stats_;
  bool stop_ = false, closed_ = false;
  std::string error_;
  std::size_t written_ = 0;
  std::thread thread_;
};

}  // namespace hbt::cosim
