#include "engine/node/engine_model_factory.hpp"

#include "common/errors.hpp"
#include "cosim/param_loader.hpp"
#include "engine_1d/engine_1d_model.hpp"
#include "engine_map/map_engine_model.hpp"

namespace hbt::engine {
namespace {

std::unique_ptr<EngineModel> makeMap(const ros::NodeHandle& pnh, const std::string& file,
                                     const std::string& pkg) {
  engine_map::MapEngineParams p;
  ParamSet ps;
  p.declare(ps);
  cosim::applyRosParams(pnh, ps, file, {"model"});
  return std::make_unique<engine_map::MapEngineModel>(p, pkg);
}

std::unique_ptr<EngineModel> make1D(const ros::NodeHandle& pnh, const std::string& file,
                                    const std::string& pkg) {
  ParamSource own = cosim::loadParamSource(pnh, "", file);
  for (auto it = own.values.begin(); it != own.values.end();) {
    const std::string& k = it->first;
    const bool node_key = k == "config_file" || k == "model" || k == "solver" ||
                          k.rfind("loops/", 0) == 0 || k.rfind("cosim/", 0) == 0;
    it = node_key ? own.values.erase(it) : std::next(it);
  }
  if (own.values.empty()) throw InputError(file, "engine_1d", "no parameters: the file is empty or was not loaded");
  engine_1d::Engine1DParams p = engine_1d::Engine1DParams::load(own, file);
  std::string solver;
  if (pnh.getParam("solver", solver) && !solver.empty()) {
    p.engine.solver = solver;
    p.validate();
  }
  return std::make_unique<engine_1d::Engine1DModel>(p, pkg);
}

}  // namespace

std::unique_ptr<EngineModel> makeEngineModel(const std::string& model, const ros::NodeHandle& nh,
                                             const ros::NodeHandle& pnh, const std::string& file) {
  std::string pkg;
  nh.param<std::string>("/scenario/package_dir", pkg, ".");
  if (model == "map") return makeMap(pnh, file, pkg);
  if (model == "1d") return make1D(pnh, file, pkg);
  checkEngineModelName(model, pnh.getNamespace() + " (private parameters)", "model");
  return nullptr;  // not reached: the check throws
}

}  // namespace hbt::engine
