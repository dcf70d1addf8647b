// A model of the twin exported as an FMI 2.0 Co-Simulation FMU (src/fmi/export): what the
// generic fmi2 functions of fmu_component.cpp ask of it. The variables live in the model's
// generated base class (<model>_fmu_variables.hpp, written by hbt_fmu_describe from the model's
// export spec and msg/*.msg), one C++ member per FMU variable, addressed by value reference.
// ROS-free; one instance per fmi2Instantiate.
#pragma once
#include <memory>
#include <string>

namespace hbt::fmi::exported {

enum class Causality { kInput, kOutput, kParameter };

class ExportedModel {
 public:
  virtual ~ExportedModel() = default;
  /// The storage of Real / Boolean / Integer variable vr; nullptr when vr is no variable of that type.
  virtual double* real(unsigned vr) = 0;
  virtual bool* boolean(unsigned vr) = 0;
  virtual long* integer(unsigned vr) = 0;
  /// Causality of variable vr (vr must exist).
  virtual Causality causality(unsigned vr) const = 0;
  /// End of initialisation: parameters are set; the model starts its state and writes its outputs.
  virtual void initialize() = 0;
  /// One communication step of h_s [s]: inputs -> model step -> outputs. Throws on failure.
  virtual void doStep(double h_s) = 0;
};

/// Defined once per exported model (its <model>_fmu.cpp): the model built from the files in
/// `resources_dir` (the FMU's extracted resources/). Throws (hbt::InputError naming the file and
/// key) when a file is missing or invalid.
std::unique_ptr<ExportedModel> makeExportedModel(const std::string& resources_dir);

/// The GUID and model identifier of the description the binary was built with (generated).
extern const char* const kGuid;
extern const char* const kModelIdentifier;

}  // namespace hbt::fmi::exported
