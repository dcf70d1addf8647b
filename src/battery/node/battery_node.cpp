// Battery participant as a process (mode:=nodes).
#include "battery/node/battery_participant.hpp"
#include "cosim/participant_main.hpp"

int main(int argc, char** argv) {
  return hbt::cosim::runNode<hbt::battery::BatteryParticipant>(argc, argv, "battery");
}
