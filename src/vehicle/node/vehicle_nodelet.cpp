// Vehicle participant as a nodelet (mode:=nodelets).
#include "cosim/participant_main.hpp"
#include "vehicle/node/vehicle_participant.hpp"

HBT_PARTICIPANT_NODELET(hbt::vehicle::VehicleParticipant, VehicleNodelet)
