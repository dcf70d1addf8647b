// Lock-step bag recorder as a process (mode:=nodes).
#include "cosim/participant_main.hpp"
#include "cosim/recorder.hpp"

int main(int argc, char** argv) { return hbt::cosim::runNode<hbt::cosim::Recorder>(argc, argv, "recorder"); }
