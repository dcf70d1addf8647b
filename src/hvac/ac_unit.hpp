// Air-conditioning unit of the bus: a belt-driven compressor on the crank (vapour-compression
// cycle) with electric evaporator blowers and condenser fans. ROS-free.
//
//   COP(T_a)  = min(COP_max, η_C T_e / (T_a + ΔT_cond - T_e))   (Carnot fraction η_C of the
//               reversed Carnot cycle between the evaporating T_e and condensing T_a + ΔT_cond)
//   Q̇_cool   = min(demand, Q̇_cap) if the compressor turns (engine running), else 0      [W]
//   P_shaft   = Q̇_cool / COP                                                              [W]
//   P_el      = P_fans Q̇_cool / Q̇_cap   (fans and blowers in proportion to the load)      [W]
#pragma once
#include "hvac/hvac_params.hpp"

namespace hbt::hvac {

struct AcOperation {
  double cooling_W = 0.0, shaft_W = 0.0, electric_W = 0.0, cop = 0.0;
};

class AcUnit {
 public:
  explicit AcUnit(const AcParams& p) : p_(p) {}
  double cop(double ambient_T_K) const;
  AcOperation operate(double demand_W, double ambient_T_K, bool compressor_turns) const;

 private:
  AcParams p_;
};

}  // namespace hbt::hvac
