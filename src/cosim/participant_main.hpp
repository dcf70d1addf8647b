// Entry points shared by every participant: a process main() and a nodelet class, so that the
// same participant runs as a node (mode:=nodes) or inside one nodelet manager (mode:=nodelets).
//
//   int main(int argc, char** argv) { return hbt::cosim::runNode<MyParticipant>(argc, argv, "my"); }
//   HBT_PARTICIPANT_NODELET(hbt::MyParticipant, MyNodelet)   // in one .cpp of the nodelet library
//
// Nodelets (mode:=nodelets) do not use the manager's worker pool: the twin's nodelets in a
// manager process share callback queues, each served by one thread (LockstepQueue), named by the
// participant's `cosim/thread` key (default "lockstep": everyone on one thread). A tight
// exchange (the 10 ms torque loop: vehicle <-> engine, EMS, e-machine, battery) is a chain of
// short callbacks; in one thread a delivery between its participants only appends to the thread's
// own FIFO (local_bus.hpp), while the manager's pool moved every callback through its manager
// thread to a worker (two thread switches per message: measured 40-57 % of the manager's CPU in
// the kernel's context switch). A participant that exchanges rarely (the 0.1 s thermal nodes) can
// compute on a thread of its own beside the torque loop (the scenario's thermal_thread,
// urban.launch) -- stepping is data-driven, so which thread runs what changes no result, only the
// wall time.
#pragma once
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/callback_queue.h>
#include <ros/poll_manager.h>
#include <ros/ros.h>

#include <atomic>
#include <chrono>
#include <cctype>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "cosim/local_bus.hpp"

namespace hbt::cosim {

/// A callback queue + thread shared by the twin's nodelets of one `cosim/thread` name in this
/// process. Held by each nodelet (shared_ptr): the thread starts with the first and stops with
/// the last.
/// poll_s = 0: the thread sleeps on the queue and every callback added wakes it (a futex wake
/// and a thread switch each time it was idle). poll_s > 0 (the recorder's thread, a participant
/// with a static kThreadPoll_s): it runs what is queued, then sleeps poll_s [s] instead of
/// waiting to be woken -- for a thread that receives many small messages and must not hold the
/// others up (its lag, at most poll_s, stays below the grant window).
class LockstepQueue {
 public:
  static constexpr const char* kDefault = "lockstep";
  /// poll_s applies when this call creates the queue (the first nodelet of the name).
  static std::shared_ptr<LockstepQueue> acquire(const std::string& name = kDefault, double poll_s = 0.0) {
    static std::mutex m;
    static std::map<std::string, std::weak_ptr<LockstepQueue>> shared;
    std::lock_guard<std::mutex> lock(m);
    auto q = shared[name].lock();
    if (!q) {
      q = std::shared_ptr<LockstepQueue>(new LockstepQueue(poll_s));
      shared[name] = q;
    }
    return q;
  }
  /// The thread name a participant's private `cosim/thread` asks for; the default when it is
  /// absent or not a valid name (the participant itself then fails naming the key).
  static std::string threadName(const ros::NodeHandle& pnh) {
    std::string name;
    if (!pnh.getParam("cosim/thread", name) || !validThreadName(name)) return kDefault;
    return name;
  }
  static bool validThreadName(const std::string& name) {
    if (name.empty() || name.size() > 64) return false;
    for (char c : name)
      if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
    return true;
  }
  ~LockstepQueue() {
    stopThread();
    LocalBus::unserveThread(&queue_);
  }
  /// No callback of this queue runs after this returns (the one in progress is waited for):
  /// called by a nodelet before its participant is destroyed, since a nodelet unloads from the
  /// manager's thread while the queue's thread may still be delivering to it. At shutdown only:
  /// the other nodelets of the queue get no callback from then on either.
  void stopThread() {
    stop_ = true;
    if (thread_.get_id() == std::this_thread::get_id()) thread_.detach();
    else if (thread_.joinable()) thread_.join();
  }
  ros::CallbackQueue* queue() { return &queue_; }
  /// A copy of nh whose callbacks (subscriptions, timers) run on the shared thread.
  ros::NodeHandle bind(const ros::NodeHandle& nh) {
    ros::NodeHandle h(nh);
    h.setCallbackQueue(&queue_);
    return h;
  }

 private:
  explicit LockstepQueue(double poll_s) : thread_([this, poll_s] {
    const auto poll = std::chrono::duration<double>(poll_s);
    while (!stop_ && ros::ok()) {
      own_.drain();  // what this thread published to its own participants (only it posts there)
      if (poll_s <= 0.0) queue_.callAvailable(ros::WallDuration(0.05));
      else if (queue_.isEmpty()) std::this_thread::sleep_for(poll);
      else queue_.callAvailable(ros::WallDuration(0));
    }
  }) {
    LocalBus::serveThread(&queue_, &own_, thread_.get_id());  // before any participant is made
  }
  ros::CallbackQueue queue_;
  LocalThreadQueue own_;  // in-process deliveries from this thread to its own participants
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

/// mode:=nodes: every callback of the process (commands, inputs, timers) runs on roscpp's poll
/// thread, right after it has read the message from its socket. With ros::spin() the poll thread
/// queued each message and woke the spinner thread: a futex wake, a thread switch and a futex
/// wait per message received, on the lock-step's critical path (vehicle -> engine -> vehicle at
/// every 10 ms step). One thread also keeps the participant single-threaded as before. Timers
/// (announce 100 ms, the stepper's 50 ms watchdog) run at the poll thread's next wake-up, at
/// most 100 ms late while no message arrives.
class PollThreadCallbacks {
 public:
  PollThreadCallbacks()
      : conn_(ros::PollManager::instance()->addPollThreadListener([this] { queue_.callAvailable(); })) {}
  ~PollThreadCallbacks() { ros::PollManager::instance()->removePollThreadListener(conn_); }
  ros::NodeHandle bind(const ros::NodeHandle& nh) {
    ros::NodeHandle h(nh);
    h.setCallbackQueue(&queue_);
    return h;
  }

 private:
  ros::CallbackQueue queue_;
  boost::signals2::connection conn_;
};

template <class P>
int runNode(int argc, char** argv, const char* default_name) {
  ros::init(argc, argv, default_name);
  ros::NodeHandle nh, pnh("~");
  ros::start();  // the poll thread runs from here
  PollThreadCallbacks callbacks;
  P participant(callbacks.bind(nh), callbacks.bind(pnh));
  participant.start();
  ros::waitForShutdown();
  return participant.failed() ? 1 : 0;
}

/// P::kThreadPoll_s if P declares it (the poll period of its thread, LockstepQueue), else 0.
template <class P>
constexpr auto threadPoll(int) -> decltype(P::kThreadPoll_s) { return P::kThreadPoll_s; }
template <class P>
constexpr double threadPoll(long) { return 0.0; }

template <class P>
class ParticipantNodelet : public nodelet::Nodelet {
 public:
  ~ParticipantNodelet() override {
    if (queue_) queue_->stopThread();  // first: no callback into the participant being destroyed
    participant_.reset();
  }

 protected:
  void onInit() override {
    queue_ = LockstepQueue::acquire(LockstepQueue::threadName(getPrivateNodeHandle()), threadPoll<P>(0));
    participant_ = std::make_unique<P>(queue_->bind(getNodeHandle()), queue_->bind(getPrivateNodeHandle()));
    participant_->start();
  }
  std::shared_ptr<LockstepQueue> queue_;  // declared first: outlives the participant
  std::unique_ptr<P> participant_;
};

}  // namespace hbt::cosim

#define HBT_PARTICIPANT_NODELET(ParticipantClass, NodeletName)                      \
  namespace hbt::nodelets {                                                         \
  class NodeletName : public hbt::cosim::ParticipantNodelet<ParticipantClass> {};  \
  }                                                                                 \
  PLUGINLIB_EXPORT_CLASS(hbt::nodelets::NodeletName, nodelet::Nodelet)
