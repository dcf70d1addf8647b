// Aftertreatment participant as a nodelet (mode:=nodelets).
#include "aftertreatment/node/aftertreatment_participant.hpp"
#include "cosim/participant_main.hpp"

HBT_PARTICIPANT_NODELET(hbt::aftertreatment::AftertreatmentParticipant, AftertreatmentNodelet)
