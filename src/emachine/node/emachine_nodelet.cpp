// E-machine participant as a nodelet (mode:=nodelets).
#include "cosim/participant_main.hpp"
#include "emachine/node/emachine_participant.hpp"

HBT_PARTICIPANT_NODELET(hbt::emachine::EMachineParticipant, EMachineNodelet)
