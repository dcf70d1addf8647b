// Fuel-fired water heater of city-bus size (Webasto Thermo 300 class): an on/off burner in the
// heating circuit ahead of the convectors, switched on the water temperature at its own sensor:
// the water reaching it (waterAtHeater: the engine outlet while the loop takes its flow from the
// engine, else the heating loop's own water). ROS-free.
//
// Controller: on while heat is demanded and the water is below T_on; off once the water is
// above T_off or no heat is demanded (hysteresis T_on < T_off; between them it keeps its state).
// When on: Q̇ = Q̇_rated into the water [W], fuel ṁ_f = Q̇/(η LHV) [kg/s] (diesel LHV,
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
  /// water_T_K: the water at its sensor [K].
  const AuxHeaterState& step(double dt_s, double heater_water_T_K, bool heat_demanded);
  /// The water reaching the heater [K]: the engine outlet T_c while the heating loop takes its
  /// flow from the engine (valve open, loop flowing), else the loop's own water T_v (the loop
  /// circulating in itself). The heater sits at the loop's inlet, ahead of the convectors.
  static double waterAtHeater(double engine_outlet_T_K, double loop_T_K, bool loop_fed_by_engine) {
    return loop_fed_by_engine ? engine_outlet_T_K : loop_T_K;
  }
  const AuxHeaterState& state() const { return s_; }

 private:
  AuxHeaterParams p_;
  AuxHeaterState s_;
};

}  // namespace hbt::hvac
