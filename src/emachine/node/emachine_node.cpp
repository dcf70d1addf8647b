// E-machine participant as a process (mode:=nodes).
#include "cosim/participant_main.hpp"
#include "emachine/node/emachine_participant.hpp"

int main(int argc, char** argv) {
  return hbt::cosim::runNode<hbt::emachine::EMachineParticipant>(argc, argv, "emachine");
}
