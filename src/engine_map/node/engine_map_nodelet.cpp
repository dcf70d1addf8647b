// Map-based engine participant as a nodelet (mode:=nodelets).
#include "cosim/participant_main.hpp"
#include "engine_map/node/engine_map_participant.hpp"

HBT_PARTICIPANT_NODELET(hbt::engine_map::EngineMapParticipant, EngineMapNodelet)
