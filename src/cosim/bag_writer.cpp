#include "cosim/bag_writer.hpp"

#include <sys/statvfs.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <stdexcept>

namespace hbt::cosim {

std::string describeWriteFailure(const std::string& file, const std::string& what) {
  std::string msg = "writing " + file + ": " + what;
  const std::string::size_type slash = file.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : (slash == 0 ? "/" : file.substr(0, slash));
  struct statvfs fs {};
  if (::statvfs(dir.c_str(), &fs) == 0) {
    const std::uint64_t free_bytes = static_cast<std::uint64_t>(fs.f_bavail) * fs.f_frsize;
    constexpr std::uint64_t kNearlyFull_bytes = 1 << 20;  // less than a bag chunk left
    if (free_bytes < kNearlyFull_bytes)
      msg += ": no space left on the device holding it (" + std::to_string(free_bytes) + " bytes free)";
  }
  return msg;
}

AsyncBagWriter::AsyncBagWriter(const std::string& file, std::size_t max_queued_bytes)
    : file_(file), max_queued_bytes_(max_queued_bytes), bag_(std::make_unique<BagFileWriter>(file)) {
  thread_ = std::thread(&AsyncBagWriter::run, this);
}

AsyncBagWriter::~AsyncBagWriter() {
  try {
    close();
  } catch (...) {  // a destructor must not throw: close() was the place to see the error
  }
}

void AsyncBagWriter::push(Job job, std::size_t bytes) {
  std::unique_lock<std::mutex> lk(m_);
  const auto has_space = [&] {
    return queue_.empty() || queued_bytes_ + bytes <= max_queued_bytes_ || !error_.empty() || stop_;
  };
  if (!has_space()) {
    ++stats_.producer_waits;
    cv_space_.wait(lk, has_space);
  }
  if (!error_.empty()) throw std::runtime_error(error_);
  if (stop_) throw std::runtime_error("writing " + file_ + ": the bag is closed");
  queue_.push_back({std::move(job), bytes});
  queued_bytes_ += bytes;
  stats_.high_water_bytes = std::max(stats_.high_water_bytes, queued_bytes_);
  stats_.high_water_messages = std::max(stats_.high_water_messages, queue_.size());
  const bool wake = queued_bytes_ >= max_queued_bytes_ / kWakeFraction;  // else it polls
  lk.unlock();
  if (wake) cv_work_.notify_one();
}

void AsyncBagWriter::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock<std::mutex> lk(m_);
      cv_work_.wait_for(lk, std::chrono::duration<double>(kPoll_s), [this] { return !queue_.empty() || stop_; });
      if (queue_.empty()) {
        if (stop_) return;  // stopped and drained
        continue;           // nothing queued within the poll period
      }
      job = std::move(queue_.front().job);
      queued_bytes_ -= queue_.front().bytes;
      queue_.pop_front();
    }
    cv_space_.notify_one();
    try {
      job(*bag_);
      std::lock_guard<std::mutex> lk(m_);
      ++written_;
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lk(m_);
      if (error_.empty()) error_ = describeWriteFailure(file_, e.what());
      queue_.clear();
      queued_bytes_ = 0;
      cv_space_.notify_all();
      return;
    }
  }
}

void AsyncBagWriter::close() {
  {
    std::lock_guard<std::mutex> lk(m_);
    if (closed_) return;
    closed_ = true;
    stop_ = true;
  }
  cv_work_.notify_all();
  cv_space_.notify_all();
  if (thread_.joinable()) thread_.join();
  try {
    bag_->close();  // writes the index: the first to fail when the disk filled at the very end
  } catch (const std::exception& e) {
    std::lock_guard<std::mutex> lk(m_);
    if (error_.empty()) error_ = describeWriteFailure(file_, e.what());
  }
  throwIfFailed();
}

std::size_t AsyncBagWriter::written() const {
  std::lock_guard<std::mutex> lk(m_);
  return written_;
}

BagQueueStats AsyncBagWriter::queueStats() const {
  std::lock_guard<std::mutex> lk(m_);
  return stats_;
}

void AsyncBagWriter::throwIfFailed() {
  std::lock_guard<std::mutex> lk(m_);
  if (!error_.empty()) throw std::runtime_error(error_);
}

}  // namespace hbt::cosim
