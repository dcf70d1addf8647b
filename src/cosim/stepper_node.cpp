// Master stepper as a process (mode:=nodes).
#include <ros/ros.h>

#include "cosim/stepper.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "stepper");
  ros::NodeHandle nh, pnh("~");
  hbt::cosim::Stepper stepper(nh, pnh);
  const bool ok = stepper.start();
  if (ok) ros::spin();
  return ok ? 0 : 1;
}
