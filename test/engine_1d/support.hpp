// Shared helpers of the engine_1d tests: repository root, parameters from config/engine_1d.yaml,
// and a constant-speed run of the Engine1D model.
#pragma once
#include <cmath>
#include <cstdlib>
#include <string>

#include "engine_1d/engine_1d.hpp"

namespace hbt::engine_1d::test {

inline std::string repoRoot() {
  const char* d = std::getenv("HBT_SOURCE_DIR");
  return d ? std::string(d) : std::string(".");
}

inline const Engine1DParams& defaultParams() {
  static const Engine1DParams p = Engine1DParams::load(repoRoot());
  return p;
}

constexpr double kRpm = M_PI / 30.0;

/// Runs `seconds` at constant speed [rpm] and torque request [Nm] with macro steps dt [s].
inline const Engine1DOutputs& run(Engine1D& e, double rpm, double torque, double seconds,
                                  double T_amb = 298.15, bool fuel = true, double dt = 0.01) {
  Engine1DInputs in;
  in.speed_rad_s = rpm * kRpm;
  in.torque_request_Nm = torque;
  in.ambient_T_K = T_amb;
  in.fuel_enabled = fuel;
  const int n = static_cast<int>(std::lround(seconds / dt));
  for (int i = 0; i < n - 1; ++i) e.step(dt, in);
  return e.step(dt, in);
}

/// BSFC [g/kWh] from fuel flow [kg/s], torque [Nm], speed [rad/s].
inline double bsfc(double fuel_kg_s, double torque, double w) {
  return fuel_kg_s / (torque * w) * 3.6e9;
}

}  // namespace hbt::engine_1d::test
