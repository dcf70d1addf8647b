// Cooling participant as a nodelet (mode:=nodelets).
#include "cooling/node/cooling_participant.hpp"
#include "cosim/participant_main.hpp"

HBT_PARTICIPANT_NODELET(hbt::cooling::CoolingParticipant, CoolingNodelet)
