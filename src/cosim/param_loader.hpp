// rosparam (XmlRpc) -> hbt::ParamSource: the bridge between the ROS parameter server and the
// ROS-free parameter binding of the model libraries (common/params.hpp).
#pragma once
#include <ros/ros.h>

#include <string>
#include <vector>

#include "common/params.hpp"

namespace hbt::cosim {

/// Flattens the parameters under `nh`'s namespace + `group` into "a/b/c" keys (relative to the
/// group). `file` names the YAML the parameters came from (for error messages); numbers (int or
/// double) become double, lists of numbers become std::vector<double>. Throws hbt::InputError for
/// values of unsupported type (naming the key).
ParamSource loadParamSource(const ros::NodeHandle& nh, const std::string& group,
                            const std::string& file);

/// The keys of a participant's private namespace that are not its model's: `config_file`, the
/// protocol keys `cosim/...` (e.g. cosim/macro_step_s, read by cosim::Participant) and the warning
/// thresholds `diagnostics/...` (read with the participant's diagnostics).
const std::vector<std::string>& nodeKeyPrefixes();
/// The model's parameters in `pnh` (loadParamSource of the whole namespace without the keys of
/// nodeKeyPrefixes()), for a ROS-free model factory.
ParamSource loadModelParams(const ros::NodeHandle& pnh, const std::string& file);

/// Applies the private parameters of a participant (`pnh`) to a model's ParamSet: the one call a
/// node makes. `file` = the YAML they came from; the node's own keys (nodeKeyPrefixes()) and any key starting
/// with one of `ignore_prefixes` are not reported as unknown. Every declared key must be there
/// (hbt::requireKeys) but an intended default and those under `set_elsewhere` (another file's or
/// the scenario's). Throws hbt::InputError, also when the namespace holds no model key at all
/// (an empty or unloaded file: defaults, unseen).
void applyRosParams(const ros::NodeHandle& pnh, const ParamSet& ps, const std::string& file,
                    std::vector<std::string> ignore_prefixes = {},
                    const std::vector<std::string>& set_elsewhere = {});

/// /scenario/ambient_temperature_c [degC] (default 25) as K; outside (-60, 60) degC: InputError
/// naming the launch argument.
double scenarioAmbient_K(const ros::NodeHandle& nh);
/// /scenario/ambient_pressure_pa [Pa] (launch argument pressure:= in kPa; default the standard
/// atmosphere): the one ambient pressure of a run (air density, intake, tailpipe, radiator air);
/// outside [5e4, 1.2e5] Pa: InputError.
double scenarioAmbientPressure_Pa(const ros::NodeHandle& nh);
/// /scenario/start (launch argument start): "cold" (default: every thermal state at ambient) or
/// "warm" (each participant at the warm state of its config's warm_start/ keys: a bus mid-shift);
/// true for warm. Any other value: InputError naming the launch argument.
bool scenarioWarmStart(const ros::NodeHandle& nh);

/// Resolves a data path given in a config file: absolute paths stay, relative paths are taken
/// against the package root (scenario parameter /scenario/package_dir).
std::string resolvePackagePath(const ros::NodeHandle& nh, const std::string& path);

/// A file of the scenario's config folder: /scenario/config_dir (launch argument config; absent:
/// the package's config/) + "/" + `relative` (e.g. "engine_map.yaml", "aux/vecto_p1_example.yaml").
/// For the files a participant reads beside its own YAML.
std::string scenarioConfigFile(const ros::NodeHandle& nh, const std::string& relative);
/// /scenario/engine_model (launch argument engine): the engine model of the run, map | 1d
/// (checked by the engine participant). Missing: InputError naming the launch argument.
std::string scenarioEngineModel(const ros::NodeHandle& nh);

}  // namespace hbt::cosim
