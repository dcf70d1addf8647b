// Probe participant as a process (mode nodes of scripts/twin bench cosim).
#include "cosim/participant_main.hpp"
#include "cosim/probe_participant.hpp"

int main(int argc, char** argv) {
  return hbt::cosim::runNode<hbt::cosim::ProbeParticipant>(argc, argv, "probe");
}
