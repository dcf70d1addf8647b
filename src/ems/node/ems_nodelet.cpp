// Energy-manager participant as a nodelet (mode:=nodelets).
#include "cosim/participant_main.hpp"
#include "ems/node/ems_participant.hpp"

HBT_PARTICIPANT_NODELET(hbt::ems::EmsParticipant, EmsNodelet)
