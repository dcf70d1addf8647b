// Aftertreatment participant as a process (mode:=nodes).
#include "aftertreatment/node/aftertreatment_participant.hpp"
#include "cosim/participant_main.hpp"

int main(int argc, char** argv) {
  return hbt::cosim::runNode<hbt::aftertreatment::AftertreatmentParticipant>(argc, argv,
                                                                             "aftertreatment");
}
