// Cabin climate controller: heating below the heating set point, cooling above the cooling set
// point, neither in the dead band between them. Feed-forward of the cabin's own balance at the
// set point plus a proportional term (T in K, G in W/K, Q̇ in W):
//   heating = clamp(G (T_h - T_a) - Q̇_gain + K (T_h - T), 0, Q̇_h,max)
//   cooling = max(Q̇_gain - G (T_c - T_a) + K (T - T_c), 0)    (the A/C limits it to its capacity)
// G = the cabin's conductance to the ambient at the present state (cabin.hpp), Q̇_gain passengers +
// sun. In a steady state with the demand delivered (C dT/dt = 0: Q̇ = G (T - T_a) - Q̇_gain) the
// cabin sits exactly at the set point: (G + K)(T_h - T) = 0. Heating and cooling are never both
// positive: their sum of arguments is (G + K)(T_h - T_c) < 0. ROS-free.
#pragma once
#include "hvac/hvac_params.hpp"

namespace hbt::hvac {

struct ClimateDemand {
  double heating_W = 0.0;
  double cooling_W = 0.0;
};

class ClimateController {
 public:
  explicit ClimateController(const ControllerParams& p) : p_(p) {}
  ClimateDemand demand(double cabin_T_K, double ambient_T_K, double conductance_W_K, double gain_W) const;
  const ControllerParams& params() const { return p_; }

 private:
  ControllerParams p_;
};

}  // namespace hbt::hvac
