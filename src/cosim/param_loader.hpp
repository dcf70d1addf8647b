// rosparam (XmlRpc) -> hbt::ParamSource: the bridge between the ROS parameter server and the
// ROS-free parameter binding of the model libraries (common/params.hpp).
#pragma once
#include <ros/ros.h>

#include <string>

#include "common/params.hpp"

namespace hbt::cosim {

/// Flattens the parameters under `nh`'s namespace + `group` into "a/b/c" keys (relative to the
/// group). `file` names the YAML the parameters came from (for error messages); numbers (int or
/// double) become double, lists of numbers become std::vector<double>. Throws hbt::InputError for
/// values of unsupported type (naming the key).
ParamSource loadParamSource(const ros::NodeHandle& nh, const std::string& group,
                            const std::string& file);

}  // namespace hbt::cosim
