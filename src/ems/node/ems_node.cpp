// Energy-manager participant as a process (mode:=nodes).
#include "cosim/participant_main.hpp"
#include "ems/node/ems_participant.hpp"

int main(int argc, char** argv) {
  return hbt::cosim::runNode<hbt::ems::EmsParticipant>(argc, argv, "ems");
}
