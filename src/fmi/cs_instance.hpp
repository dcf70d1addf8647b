// One instance of an FMI 2.0 Co-Simulation FMU (FMI 2.0 chapter 4): the common life of
// Fmi2Instance (instantiate, setupExperiment, initialisation, variables, terminate and free)
// plus the communication step fmi2DoStep. Synchronous (no asynchronous doStep), deterministic.
#pragma once
#include "fmi/fmi2_instance.hpp"

namespace hbt::fmi {

class CsInstance : public Fmi2Instance {
 public:
  /// FmuError if fmu was not loaded as Co-Simulation or fmi2Instantiate returns NULL.
  CsInstance(std::shared_ptr<const LoadedFmu> fmu, const std::string& instance_name, LogSink sink);

  /// fmi2DoStep from time() over h_s [s] > 0; time() advances by h_s. A step beyond the stop
  /// time given to setupExperiment throws before calling the FMU.
  void doStep(double h_s);
};

}  // namespace hbt::fmi
