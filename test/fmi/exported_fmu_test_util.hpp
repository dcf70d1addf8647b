// Helpers of the tests of the twin's exported FMUs (test_<model>_fmu, src/fmi/export): the FMU
// the build made, loaded with src/fmi into a fresh directory, its outputs, its initialisation at an ambient, and the check that it refuses
// fmi2Instantiate, its log naming the file, when a file of its resources/ is missing.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

#include "fmi/cs_instance.hpp"
#include "fmi/export/resource_params.hpp"
#include "fmi/fmu_error.hpp"

namespace hbt::fmi::testing {

/// A participant's warning rule written out by hand, independently of cosim::core::Warning (the
/// code under test): raised at the first state time where the condition has held since its onset
/// for duration_s, cleared at the first one without it. Counts the raises and keeps the first and
/// last raised times.
struct WarningOracle {
  double duration_s;           ///< persistence [s]
  double onset_s = -1.0;       ///< start of the condition's current run [s]; -1: not holding
  double first_raise_s = -1.0; ///< [s]; -1: never raised
  double last_raised_s = -1.0; ///< [s]; -1: never raised
  int raises = 0;
  int raised_states = 0;
  bool raised = false;

  /// The expected warning state at t_s with the condition `holds`.
  bool update(double t_s, bool holds) {
    onset_s = holds ? (onset_s < 0.0 ? t_s : onset_s) : -1.0;
    const bool now = holds && t_s - onset_s >= duration_s - 1e-9;
    if (now && first_raise_s < 0.0) first_raise_s = t_s;
    if (now) last_raised_s = t_s;
    raises += now && !raised ? 1 : 0;
    raised_states += now ? 1 : 0;
    raised = now;
    return now;
  }
};

/// The paths made in this process, removed after the last test.
class ExportTestPaths : public ::testing::Environment {
 public:
  static std::vector<std::filesystem::path>& made() {
    static std::vector<std::filesystem::path> paths;
    return paths;
  }
  void TearDown() override {
    for (const auto& p : made()) std::filesystem::remove_all(p);
  }
};
inline ::testing::Environment* const kExportTestPaths = ::testing::AddGlobalTestEnvironment(new ExportTestPaths);

/// A fresh directory below the system's temporary directory, unique per model, tag and process.
inline std::string freshExportDir(const std::string& model, const std::string& tag) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
      ("hbt_" + model + "_fmu_" + std::to_string(::getpid()) + "_" + tag);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  ExportTestPaths::made().push_back(dir);
  return dir.string();
}

/// <build>/fmus/<model>.fmu (HBT_FMU_DIR), extracted and loaded as Co-Simulation.
inline std::shared_ptr<const LoadedFmu> loadExported(const std::string& model, const std::string& tag) {
  return LoadedFmu::load(std::string(HBT_FMU_DIR) + "/" + model + ".fmu", freshExportDir(model, tag),
                         InterfaceType::kCoSimulation);
}

/// The instance set up from t = 0 with scenario.ambient_temperature_c [degC] and initialised.
inline void initializeAtAmbient(CsInstance& inst, double ambient_c, double stop_s = 100.0) {
  inst.setupExperiment(1e-6, 0.0, stop_s);
  inst.setReal(inst.settable("scenario.ambient_temperature_c", VarType::kReal), ambient_c);
  inst.enterInitializationMode();
  inst.exitInitializationMode();
}

/// Every output variable of the instance's FMU (of type `only`, when given), resolved by name
/// from its modelDescription.xml.
inline std::vector<VariableRef> outputRefs(const CsInstance& inst, const LoadedFmu& fmu,
                                           std::optional<VarType> only = std::nullopt) {
  std::vector<VariableRef> out;
  for (const auto& var : fmu.modelDescription().variables())
    if (var.causality == Causality::kOutput && (!only || var.type == *only)) out.push_back(inst.gettable(var.name, var.type));
  return out;
}

/// Removes the resources whose file name contains `resource`, then expects fmi2Instantiate to
/// return NULL (FmuError) with one log message naming the file.
inline void expectInstantiationRefusedWithout(const std::string& model, const std::string& resource) {
  auto loaded = loadExported(model, "without_" + std::to_string(std::hash<std::string>{}(resource)));
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(loaded->directory()) / "resources"))
    if (e.path().filename().string().find(resource) != std::string::npos) std::filesystem::remove(e.path());
  std::vector<std::string> log;
  try {
    CsInstance inst(loaded, model, [&](const std::string&, fmi2Status, const std::string&, const std::string& m) {
      log.push_back(m);
    });
    ADD_FAILURE() << "instantiated without " << resource;
  } catch (const FmuError& e) {
    EXPECT_NE(std::string(e.what()).find("returned NULL"), std::string::npos) << e.what();
  }
  ASSERT_EQ(log.size(), 1u);
  EXPECT_NE(log[0].find(resource), std::string::npos) << log[0];
}

}  // namespace hbt::fmi::testing
