// Entry points shared by every participant: a process main() and a nodelet class, so that the
// same participant runs as a node (mode:=nodes) or inside one nodelet manager (mode:=nodelets).
//
//   int main(int argc, char** argv) { return hbt::cosim::runNode<MyParticipant>(argc, argv, "my"); }
//   HBT_PARTICIPANT_NODELET(hbt::MyParticipant, MyNodelet)   // in one .cpp of the nodelet library
#pragma once
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>
#include <ros/ros.h>

#include <memory>

namespace hbt::cosim {

template <class P>
int runNode(int argc, char** argv, const char* default_name) {
  ros::init(argc, argv, default_name);
  ros::NodeHandle nh, pnh("~");
  P participant(nh, pnh);
  participant.start();
  ros::spin();
  return participant.failed() ? 1 : 0;
}

template <class P>
class ParticipantNodelet : public nodelet::Nodelet {
 protected:
  void onInit() override {
    participant_ = std::make_unique<P>(getNodeHandle(), getPrivateNodeHandle());
    participant_->start();
  }
  std::unique_ptr<P> participant_;
};

}  // namespace hbt::cosim

#define HBT_PARTICIPANT_NODELET(ParticipantClass, NodeletName)                      \
  namespace hbt::nodelets {                                                         \
  class NodeletName : public hbt::cosim::ParticipantNodelet<ParticipantClass> {};  \
  }                                                                                 \
  PLUGINLIB_EXPORT_CLASS(hbt::nodelets::NodeletName, nodelet::Nodelet)
