#include "hvac/ac_unit.hpp"

#include <algorithm>

namespace hbt::hvac {

double AcUnit::cop(double T_a) const {
  const double lift_K = T_a + p_.condenser_approach_K - p_.evaporating_K;
  if (!(lift_K > 0.0)) return p_.max_cop;
  return std::min(p_.max_cop, p_.carnot_fraction * p_.evaporating_K / lift_K);
}

AcOperation AcUnit::operate(double demand_W, double T_a, bool compressor_turns) const {
  AcOperation op;
  op.cop = cop(T_a);
  if (!compressor_turns || !(p_.cooling_capacity_W > 0.0)) return op;
  op.cooling_W = std::clamp(demand_W, 0.0, p_.cooling_capacity_W);
  op.shaft_W = op.cooling_W / op.cop;
  op.electric_W = p_.fans_electric_W * op.cooling_W / p_.cooling_capacity_W;
  return op;
}

}  // namespace hbt::hvac
