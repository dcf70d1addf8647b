// Battery participant as a nodelet (mode:=nodelets).
#include "battery/node/battery_participant.hpp"
#include "cosim/participant_main.hpp"

HBT_PARTICIPANT_NODELET(hbt::battery::BatteryParticipant, BatteryNodelet)
