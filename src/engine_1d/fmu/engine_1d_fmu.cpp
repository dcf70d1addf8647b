// The 1D engine as an FMI 2.0 Co-Simulation FMU (src/fmi/export): Engine1DModel
// (../engine_1d_model.hpp) behind the engine participant's FMU side (src/engine/engine_fmu.hpp,
// the conversion engine_interface/engine_io.hpp the node uses). The parameters come from
// resources/engine_1d.yaml and the three files its files/ section names, read as the factory's
// make1D reads them (Engine1DParams::load, every key checked and required), each from resources/
// under its own file name; so are the reference map engine's curves and the turbocharger's maps.
// The warning thresholds: its diagnostics: section. The pipe solver is the file's engine_1d/solver (the launch argument solver is the node's).
#include <filesystem>
#include <memory>
#include <string>
#include <utility>

#include "engine_1d_fmu_variables.hpp"  // first: generated::VariablesModel, EngineFmu's base
#include "engine/engine_fmu.hpp"
#include "engine_1d/engine_1d_model.hpp"
#include "fmi/export/resource_params.hpp"

namespace hbt::fmi::exported {
namespace {

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

engine_1d::Engine1DParams readParams(const std::string& dir) {
  const std::string file = dir + "/engine_1d.yaml";
  ParamSource src = readResourceSource(file);
  for (const char* key : {"engine_1d/files/cylinder", "engine_1d/files/turbo", "engine_1d/files/reference"}) {
    const auto it = src.values.find(key);
    if (it != src.values.end() && std::holds_alternative<std::string>(it->second))
      it->second = fileName(std::get<std::string>(it->second));  // beside engine_1d.yaml in resources/
  }
  engine_1d::Engine1DParams p = engine_1d::Engine1DParams::load(src, file);
  for (std::string* f : {&p.reference.full_load_file, &p.reference.fuel_map_file, &p.reference.pt1_file})
    *f = resourceFile(dir, *f);
  p.reference.nox_map_file.clear();  // not used by the 1D engine (Engine1D clears it too)
  p.turbo.data_dir = dir;
  p.turbo.compressor_map_file = fileName(p.turbo.compressor_map_file);
  p.turbo.turbine_map_file = fileName(p.turbo.turbine_map_file);
  return p;
}

}  // namespace

std::unique_ptr<ExportedModel> makeExportedModel(const std::string& resources_dir) {
  auto model = std::make_unique<engine_1d::Engine1DModel>(readParams(resources_dir), resources_dir);
  const auto warnings = readResourceWarnings<engine::EngineWarnings>(resources_dir + "/engine_1d.yaml", std::string(model->name()));
  return std::make_unique<EngineFmu>(std::move(model), warnings);
}

}  // namespace hbt::fmi::exported
