// 1D engine participant as a nodelet (mode:=nodelets).
#include "cosim/participant_main.hpp"
#include "engine_1d/node/engine_1d_participant.hpp"

HBT_PARTICIPANT_NODELET(hbt::engine1d::Engine1DParticipant, Engine1DNodelet)
