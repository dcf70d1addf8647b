// A rosbag written by a thread of its own. The recorder's lock-step thread only copies the
// message held at t and queues it; serialisation and the file write (~19 µs per message on this
// machine, 12 s of a 62 s full-mission nodelets run when done inline) run on the writer thread,
// i.e. on the second core while the participants compute the next steps.
// Order: jobs are written strictly in the order they were queued (one FIFO, one writer), so the
// bag is byte-for-byte the one an inline writer gives (determinism is unchanged).
// Memory: at most `max_queued` messages wait; a producer that gets ahead blocks until the writer
// catches up (back-pressure instead of unbounded growth).
// Errors: a failed write (disk full, ...) is remembered; the next write() or close() throws it
// as std::runtime_error naming the file, so the run stops instead of losing data silently.
#pragma once
#include <rosbag/bag.h>

#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace hbt::cosim {

/// "writing <file>: <what>", and the cause where the file system tells it: "no space left on the
/// device (0 bytes free)" when the device holding `file` is full (rosbag says only "Error
/// writing" or "Error seeking").
std::string describeWriteFailure(const std::string& file, const std::string& what);

class AsyncBagWriter {
 public:
  /// Opens `file` for writing (throws rosbag::BagException) and starts the writer thread.
  explicit AsyncBagWriter(const std::string& file, std::size_t max_queued = 100000);
  ~AsyncBagWriter();
  AsyncBagWriter(const AsyncBagWriter&) = delete;
  AsyncBagWriter& operator=(const AsyncBagWriter&) = delete;

  /// Queues the message behind `m` (a std:: or boost:: shared pointer the writer keeps until it
  /// is written: the caller must not change the message) for `topic` at bag time `t`.
  template <class Ptr>
  void write(const std::string& topic, const ros::Time& t, Ptr m) {
    push([topic, t, m](rosbag::Bag& bag) { bag.write(topic, t, *m); });
  }
  /// Writes everything queued, stops the thread and closes the bag; throws a write error.
  void close();
  /// Messages written so far (for tests and diagnostics).
  std::size_t written() const;

 private:
  using Job = std::function<void(rosbag::Bag&)>;
  void push(Job job);
  void run();
  void throwIfFailed();

  std::string file_;
  std::size_t max_queued_;
  // rosbag's destructor closes again and would throw (terminate) after a failed close: a bag whose
  // close failed is released, its descriptor left to the process end (an error path only)
  std::unique_ptr<rosbag::Bag> bag_ = std::make_unique<rosbag::Bag>();
  mutable std::mutex m_;
  std::condition_variable cv_work_, cv_space_;
  std::deque<Job> queue_;
  bool stop_ = false, closed_ = false;
  std::string error_;
  std::size_t written_ = 0;
  std::thread thread_;
};

}  // namespace hbt::cosim
