#include "cosim/bag_writer.hpp"

#include <stdexcept>

namespace hbt::cosim {

AsyncBagWriter::AsyncBagWriter(const std::string& file, std::size_t max_queued)
    : file_(file), max_queued_(max_queued > 0 ? max_queued : 1) {
  bag_.open(file, rosbag::bagmode::Write);
  thread_ = std::thread(&AsyncBagWriter::run, this);
}

AsyncBagWriter::~AsyncBagWriter() {
  try {
    close();
  } catch (...) {  // a destructor must not throw: close() was the place to see the error
  }
}

void AsyncBagWriter::push(Job job) {
  std::unique_lock<std::mutex> lk(m_);
  cv_space_.wait(lk, [this] { return queue_.size() < max_queued_ || !error_.empty() || stop_; });
  if (!error_.empty()) throw std::runtime_error("writing " + file_ + ": " + error_);
  if (stop_) throw std::runtime_error("writing " + file_ + ": the bag is closed");
  queue_.push_back(std::move(job));
  lk.unlock();
  cv_work_.notify_one();
}

void AsyncBagWriter::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock<std::mutex> lk(m_);
      cv_work_.wait(lk, [this] { return !queue_.empty() || stop_; });
      if (queue_.empty()) return;  // stop_ and drained
      job = std::move(queue_.front());
      queue_.pop_front();
    }
    cv_space_.notify_one();
    try {
      job(bag_);
      std::lock_guard<std::mutex> lk(m_);
      ++written_;
    } catch (const std::exception& e) {
      std::lock_guard<std::mutex> lk(m_);
      if (error_.empty()) error_ = e.what();
      queue_.clear();
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
  bag_.close();
  throwIfFailed();
}

std::size_t AsyncBagWriter::written() const {
  std::lock_guard<std::mutex> lk(m_);
  return written_;
}

void AsyncBagWriter::throwIfFailed() {
  std::lock_guard<std::mutex> lk(m_);
  if (!error_.empty()) throw std::runtime_error("writing " + file_ + ": " + error_);
}

}  // namespace hbt::cosim
