// Fuel-fired coolant heater of city-bus size (Webasto Thermo 300 class): an on/off burner that
// heats the engine's HT coolant circuit. ROS-free.
//
// Controller: on while heat is demanded and the coolant is below T_on; off once the coolant is
// above T_off or no heat is demanded (hysteresis T_on < T_off; between them it keeps its state).
// When on: Q̇ = Q̇_rated into the coolant [W], fuel ṁ_f = Q̇/(η LHV) [kg/s] (diesel LHV,
// common/units.hpp), electric draw P_el [W]. Cumulatives are booked exactly:
// m_f LHV η = Q (the test's energy balance).
#pragma once
#include "hvac/hvac_params.hpp"

namespace hbt::hvac {

struct AuxHeaterState {
  bool on = false;
  double heat_W = 0.0, fuel_kg_s = 0.0, electric_W = 0.0;
  double heat_J = 0.0, fuel_kg = 0.0, electric_J = 0.0;  // cumulative since reset
};

class AuxHeater {
 public:
  explicit AuxHeater(const AuxHeaterParams& p) : p_(p) {}
  void reset() { s_ = AuxHeaterState{}; }
  /// Decides on/off at the step's start and books the step [dt_s].
  const AuxHeaterState& step(double dt_s, double coolant_T_K, bool heat_demanded);
  const AuxHeaterState& state() const { return s_; }

 private:
  AuxHeaterParams p_;
  AuxHeaterState s_;
};

}  // namespace hbt::hvac
