// Cooling participant as a process (mode:=nodes).
#include "cooling/node/cooling_participant.hpp"
#include "cosim/participant_main.hpp"

int main(int argc, char** argv) {
  return hbt::cosim::runNode<hbt::cooling::CoolingParticipant>(argc, argv, "cooling");
}
