// Test support: loads config/engine_1d_cylinder.yaml into the cylinder (and rig) parameters.
#pragma once
#include <cmath>
#include <cstdlib>
#include <string>

#include "common/params.hpp"
#include "cylinder/cylinder_params.hpp"
#include "cylinder/rig.hpp"
#include "common/yaml_params.hpp"

namespace hbt::cylinder::test {

inline std::string sourceDir() {
  const char* s = std::getenv("HBT_SOURCE_DIR");
  return s ? s : ".";
}

inline CylinderParams loadParams(RigParams* rig = nullptr) {
  const ParamSource src = readYamlParams(sourceDir() + "/config/engine_1d_cylinder.yaml");
  CylinderParams cp;
  ParamSet ps;
  cp.declare(ps);
  if (rig) rig->declare(ps);
  applyParams(ps, src, rig ? std::vector<std::string>{} : std::vector<std::string>{"cylinder_rig/"});
  cp.finalize(src.file);
  return cp;
}

/// d ln(NOx)/dT_intake [1/K] of the rig (its shipped operating point: fixed intake pressure,
/// fuel and injection) between intake temperatures of 310 and 330 K, run to a periodic cycle
/// with the given cylinder parameters; nox_mid_kg: the geometric mean NOx per cycle [kg NO2].
inline double rigNoxSensitivityToIntake(const CylinderParams& cp, const RigParams& rp,
                                        double& nox_mid_kg) {
  auto nox = [&](double T_K) {
    RigParams r = rp;
    r.T_intake_K = T_K;
    SingleCylinderRig rig(cp, r);
    return rig.runToPeriodic(8, 2e-3).nox_no2eq_kg;
  };
  const double lo = nox(310.0), hi = nox(330.0);
  nox_mid_kg = std::sqrt(lo * hi);
  return std::log(hi / lo) / 20.0;
}

}  // namespace hbt::cylinder::test
