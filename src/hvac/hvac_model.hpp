// HVAC of the bus: the cabin heat balance (cabin.hpp) with its gains (cabin_gains.hpp), the
// climate controller (climate_controller.hpp), the fuel-fired coolant heater (aux_heater.hpp) and
// the A/C unit (ac_unit.hpp), stepped in this order with the inputs held over the step:
//   1. gains Q̇_gain = Q̇_people + Q̇_sun; doors open while the bus stands (v < v_doors)
//   2. demand = controller(T_cabin, T_a, G_cabin, Q̇_gain): heating [W] (asked of the coolant
//      convectors: the cooling participant delivers min(demand, G_h (T_coolant - T_cabin)) once its
//      valve is open) and cooling [W]
//   3. auxiliary heater: on while heating is demanded and the heating loop's water is cold (its
//      own sensor); heat into the heating loop ahead of the convectors, fuel, electric draw
//   4. A/C: cooling delivered while the compressor turns, shaft power = Q̇/COP, fan power; it asks
//      the engine to run (a stop-start engine: no stop, or a restart) while cooling is demanded
//      and the cabin is more than engine_run_above_K above the cooling set point
//   5. cabin: C dT/dt = Q̇_coolant - Q̇_A/C + Q̇_gain - G (T - T_a), Q̇_coolant = what the
//      convectors delivered (mean of the cooling participant's last step)
// Cabin balance, booked exactly (cabin.hpp):
//   Q_coolant + Q_people + Q_sun - Q_A/C - Q_body - Q_fresh - Q_doors - C (T - T_0) = 0.
// SI units; the machines' energies: compressor shaft [J], electric (blowers, condenser fans,
// burner) [J], heater heat [J] and fuel [kg]. ROS-free, deterministic, no allocation in step().
#pragma once
#include <string>

#include "hvac/ac_unit.hpp"
#include "hvac/aux_heater.hpp"
#include "hvac/cabin.hpp"
#include "hvac/cabin_gains.hpp"
#include "hvac/climate_controller.hpp"
#include "hvac/hvac_params.hpp"

namespace hbt::hvac {

struct HvacInputs {
  double ambient_T_K = 298.15;
  double ambient_p_Pa = units::kStandardAtmosphere_Pa;
  double heater_water_T_K = 298.15;   // heating-loop water at the fuel-fired heater's sensor [K]
  double coolant_heat_W = 0.0;        // heat the convectors delivered to the cabin [W]
  double vehicle_speed_m_s = 0.0;
  bool engine_running = true;         // the belt-driven compressor turns
};

struct HvacOutputs {
  double cabin_T_K = 0.0;
  double heating_demand_W = 0.0, cooling_demand_W = 0.0;
  bool doors_open = false, aux_heater_on = false;
  bool engine_run_request = false;    // the A/C needs the engine (cabin > T_c + engine_run_above_K)
  double aux_heater_heat_W = 0.0, aux_heater_fuel_kg_s = 0.0;
  double ac_cooling_W = 0.0, compressor_power_W = 0.0, cop = 0.0;
  double electric_power_W = 0.0;      // blowers, condenser fans, heater burner [W]
  double people_W = 0.0, solar_W = 0.0, body_W = 0.0, fresh_air_W = 0.0, doors_W = 0.0;
  double coolant_heat_W = 0.0;
  // Cumulative since reset [J], [kg].
  double coolant_heat_J = 0.0, people_J = 0.0, solar_J = 0.0, ac_cooling_J = 0.0;
  double body_J = 0.0, fresh_air_J = 0.0, doors_J = 0.0;
  double stored_change_J = 0.0, energy_residual_J = 0.0;
  double aux_heater_heat_J = 0.0, aux_heater_fuel_kg = 0.0;
  double compressor_energy_J = 0.0, electric_energy_J = 0.0;
  double time_s = 0.0;
};

class HvacModel {
 public:
  /// Validates p (InputError naming `file` and the key); payload_kg sets the passengers.
  HvacModel(const HvacParams& p, double payload_kg, const std::string& file = "(hvac parameters)");
  /// Cabin at cabin_T_K, heater off, cumulatives 0.
  void reset(double cabin_T_K);
  /// The cabin temperature of a bus in service at this ambient: the nearest set point [K].
  double inServiceCabin_K(double ambient_T_K) const;
  void step(double dt_s, const HvacInputs& in);
  const HvacOutputs& outputs() const { return out_; }
  const Cabin& cabin() const { return cabin_; }
  const CabinGains& gains() const { return gains_; }
  const AcUnit& ac() const { return ac_; }

 private:
  void checkInputs(double dt_s, const HvacInputs& in) const;
  void book(double dt_s, const CabinFlows& f, const AuxHeaterState& h, const AcOperation& ac);
  HvacParams p_;
  std::string file_;
  Cabin cabin_;
  CabinGains gains_;
  ClimateController controller_;
  AuxHeater heater_;
  AcUnit ac_;
  double T0_K_ = 293.15;
  HvacOutputs out_;
};

}  // namespace hbt::hvac
