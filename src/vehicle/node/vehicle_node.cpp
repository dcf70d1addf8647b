// Vehicle participant as a process (mode:=nodes).
#include "cosim/participant_main.hpp"
#include "vehicle/node/vehicle_participant.hpp"

int main(int argc, char** argv) {
  return hbt::cosim::runNode<hbt::vehicle::VehicleParticipant>(argc, argv, "vehicle");
}
