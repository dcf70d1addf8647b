// Master stepper as a process (mode:=nodes): its callbacks run on roscpp's poll thread, as the
// participants' (PollThreadCallbacks, participant_main.hpp).
#include <ros/ros.h>

#include "cosim/participant_main.hpp"
#include "cosim/stepper.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "stepper");
  ros::NodeHandle nh, pnh("~");
  ros::start();
  hbt::cosim::PollThreadCallbacks callbacks;
  hbt::cosim::Stepper stepper(callbacks.bind(nh), callbacks.bind(pnh));
  const bool ok = stepper.start();
  if (ok) ros::waitForShutdown();
  return ok ? 0 : 1;
}
