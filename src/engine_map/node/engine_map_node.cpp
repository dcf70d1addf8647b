// Map-based engine participant as a process (mode:=nodes).
#include "cosim/participant_main.hpp"
#include "engine_map/node/engine_map_participant.hpp"

int main(int argc, char** argv) {
  return hbt::cosim::runNode<hbt::engine_map::EngineMapParticipant>(argc, argv, "engine");
}
