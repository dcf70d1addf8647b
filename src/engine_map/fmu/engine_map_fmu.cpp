// The map engine as an FMI 2.0 Co-Simulation FMU (src/fmi/export): MapEngineModel
// (../map_engine_model.hpp) behind the engine participant's FMU side (src/engine/engine_fmu.hpp,
// the conversion engine_interface/engine_io.hpp the node uses). The parameters come from
// resources/engine_map.yaml with the node's checks (the factory's makeMap); its full-load, fuel,
// PT1 and NOx map files are read from resources/ under their own file names; the warning thresholds
// from its diagnostics: section.
#include <memory>
#include <string>
#include <utility>

#include "engine_map_fmu_variables.hpp"  // first: generated::VariablesModel, EngineFmu's base
#include "engine/engine_fmu.hpp"
#include "engine_map/map_engine_model.hpp"
#include "fmi/export/resource_params.hpp"

namespace hbt::fmi::exported {

std::unique_ptr<ExportedModel> makeExportedModel(const std::string& resources_dir) {
  auto p = readResourceParams<engine_map::MapEngineParams>(resources_dir + "/engine_map.yaml");
  for (std::string* file : {&p.full_load_file, &p.fuel_map_file, &p.pt1_file, &p.nox_map_file})
    if (!file->empty()) *file = resourceFile(resources_dir, *file);  // nox_map_file "": the constant index
  auto model = std::make_unique<engine_map::MapEngineModel>(p, resources_dir);
  const auto warnings = readResourceWarnings<engine::EngineWarnings>(resources_dir + "/engine_map.yaml", std::string(model->name()));
  return std::make_unique<EngineFmu>(std::move(model), warnings);
}

}  // namespace hbt::fmi::exported
