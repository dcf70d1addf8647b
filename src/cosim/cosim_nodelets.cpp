// Nodelet forms of the stepper, the recorder and the protocol probe (mode:=nodelets).
#include "cosim/participant_main.hpp"
#include "cosim/probe_participant.hpp"
#include "cosim/recorder.hpp"
#include "cosim/stepper.hpp"

HBT_PARTICIPANT_NODELET(hbt::cosim::Recorder, RecorderNodelet)
HBT_PARTICIPANT_NODELET(hbt::cosim::ProbeParticipant, ProbeNodelet)

namespace hbt::nodelets {
class StepperNodelet : public nodelet::Nodelet {
  static constexpr const char* kStepperThread = "stepper";
  void onInit() override {
    // a thread of its own: a participant stuck in its step on the lock-step thread does not
    // stop the stepper's timeout (cosim/core/step_watch.hpp)
    queue_ = hbt::cosim::LockstepQueue::acquire(kStepperThread);
    stepper_ = std::make_unique<hbt::cosim::Stepper>(queue_->bind(getNodeHandle()),
                                                     queue_->bind(getPrivateNodeHandle()));
    stepper_->endProcessIfStuck(true);
    stepper_->start();
  }
  std::shared_ptr<hbt::cosim::LockstepQueue> queue_;  // declared first: outlives the stepper
  std::unique_ptr<hbt::cosim::Stepper> stepper_;

 public:
  ~StepperNodelet() override {
    if (queue_) queue_->stopThread();  // first: no timer or status callback beside its destructor
    stepper_.reset();
  }
};
}  // namespace hbt::nodelets
PLUGINLIB_EXPORT_CLASS(hbt::nodelets::StepperNodelet, nodelet::Nodelet)
