// The error of a rejected FMU: the FMU file and what is wrong with it (the XML element or
// attribute, the variable, the missing function). Errors while an instance runs (a bad status,
// a NaN output) are hbt::ModelDivergence naming the FMU, the call or variable and the time.
#pragma once
#include <stdexcept>
#include <string>

namespace hbt::fmi {

class FmuError : public std::runtime_error {
 public:
  FmuError(const std::string& fmu_file, const std::string& what)
      : std::runtime_error("FMU " + fmu_file + ": " + what), file_(fmu_file) {}
  const std::string& file() const { return file_; }

 private:
  std::string file_;
};

}  // namespace hbt::fmi
