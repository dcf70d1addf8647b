#include "fmi/cs_instance.hpp"

#include "fmi/fmu_error.hpp"

namespace hbt::fmi {

namespace {
std::shared_ptr<const LoadedFmu> requireCs(std::shared_ptr<const LoadedFmu> fmu) {
  if (fmu->interfaceType() != InterfaceType::kCoSimulation) {
    throw FmuError(fmu->file(), "loaded as ModelExchange, not CoSimulation");
  }
  return fmu;
}
}  // namespace

CsInstance::CsInstance(std::shared_ptr<const LoadedFmu> fmu, const std::string& instance_name, LogSink sink)
    : Fmi2Instance(requireCs(std::move(fmu)), instance_name, std::move(sink)) {}

void CsInstance::doStep(double h_s) {
  checkStep("fmi2DoStep", h_s);
  check(f_.doStep(c_, time_s_, h_s, fmi2True), "fmi2DoStep");
  time_s_ += h_s;
}

}  // namespace hbt::fmi
