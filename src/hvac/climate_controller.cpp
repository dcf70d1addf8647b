#include "hvac/climate_controller.hpp"

#include <algorithm>

namespace hbt::hvac {

ClimateDemand ClimateController::demand(double T, double T_a, double G, double gain_W) const {
  ClimateDemand d;
  const double heat_ff_W = G * (p_.heating_setpoint_K - T_a) - gain_W;
  d.heating_W = std::clamp(heat_ff_W + p_.gain_W_K * (p_.heating_setpoint_K - T), 0.0, p_.max_heating_W);
  const double cool_ff_W = gain_W - G * (p_.cooling_setpoint_K - T_a);
  d.cooling_W = std::max(0.0, cool_ff_W + p_.gain_W_K * (T - p_.cooling_setpoint_K));
  return d;
}

}  // namespace hbt::hvac
