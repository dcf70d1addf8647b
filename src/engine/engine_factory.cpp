#include "engine/engine_factory.hpp"

#include "common/errors.hpp"
#include "engine_1d/engine_1d_model.hpp"
#include "engine_map/map_engine_model.hpp"

namespace hbt::engine {
namespace {

std::unique_ptr<EngineModel> makeMap(const ParamSource& params, const std::string& pkg) {
  engine_map::MapEngineParams p;
  ParamSet ps;
  p.declare(ps);
  applyParams(ps, params);
  requireKeys(ps, params);  // after: a misspelt key is named as unknown first
  return std::make_unique<engine_map::MapEngineModel>(p, pkg);
}

std::unique_ptr<EngineModel> make1D(const ParamSource& params, const std::string& file, const std::string& pkg,
                                    const std::string& solver) {
  engine_1d::Engine1DParams p = engine_1d::Engine1DParams::load(params, file);
  if (!solver.empty()) {
    p.engine.solver = solver;
    p.validate();
  }
  return std::make_unique<engine_1d::Engine1DModel>(p, pkg);
}

}  // namespace

void checkEngineModelName(const std::string& name, const std::string& where, const std::string& key) {
  if (name != "map" && name != "1d")
    throw InputError(where, key, "'" + name + "' is not an engine model: map | 1d");
}

std::unique_ptr<EngineModel> makeEngineModel(const std::string& model, const ParamSource& params,
                                             const std::string& file, const std::string& package_dir,
                                             const std::string& solver) {
  checkEngineModelName(model, "scenario (launch argument engine)", "engine_model");
  // an empty (or unloaded) file would silently run the model on its built-in defaults
  if (params.values.empty()) throw InputError(file, "", "sets no parameter of the " + model + " engine (empty file, or not loaded)");
  if (model == "map") return makeMap(params, package_dir);
  return make1D(params, file, package_dir, solver);
}

}  // namespace hbt::engine
