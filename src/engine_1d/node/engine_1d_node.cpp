// 1D engine participant as a process (mode:=nodes).
#include "cosim/participant_main.hpp"
#include "engine_1d/node/engine_1d_participant.hpp"

int main(int argc, char** argv) {
  return hbt::cosim::runNode<hbt::engine1d::Engine1DParticipant>(argc, argv, "engine");
}
