// Parameters of the bus HVAC (cabin heat balance, climate controller, fuel-fired auxiliary
// heater, A/C unit). SI units. Keys (group/key) = config/hvac.yaml, where every value and its
// source is documented (VECTO BusAuxiliaries HVAC steady-state model, heater data sheet, ...).
#pragma once
#include <string>
#include <vector>

#include "common/params.hpp"
#include "common/units.hpp"

namespace hbt::hvac {

/// The passenger compartment: envelope, air and interior thermal mass, fresh air, windows.
struct CabinParams {
  double length_m = 12.0;                   // envelope of the body (transmission area)
  double width_m = 2.55;
  double height_m = 3.0;
  double u_value_W_m2K = 3.0;               // whole-body heat transfer coefficient
  double air_volume_m3 = 60.0;              // interior air volume (fresh-air exchange, air mass)
  double interior_heat_capacity_J_K = 6e5;  // seats, panels, floor, frame taking part [J/K]
  double fresh_air_changes_per_h = 8.0;     // outside air exchanged per hour [1/h]
  double window_area_per_length_m2_m = 1.5; // side glazing per metre of bus length
  double front_rear_window_area_m2 = 5.0;
  double g_factor = 1.0;                    // solar transmittance of the glazing [-]
  double solar_orientation_factor = 0.25;   // share of the glazing facing the sun [-]
};

/// Passengers (sensible heat) and the sun.
struct GainParams {
  double mass_per_passenger_kg = 68.0;      // payload -> passengers
  double crew = 1.0;                        // the driver
  double heat_per_person_cold_W = 50.0;     // sensible heat below the boundary ambient
  double heat_per_person_warm_W = 80.0;     // at or above it
  double person_boundary_ambient_K = units::celsiusToK(17.0);
  double clouding_cold = 0.65;              // solar clouding below the boundary ambient [-]
  double clouding_warm = 0.8;
  std::vector<double> solar_ambient_K{253.15, 268.15, 275.15, 299.15, 306.15};
  std::vector<double> solar_irradiance_W_m2{10.0, 30.0, 30.0, 150.0, 150.0};
};

/// Doors open while the bus stands: two-way buoyancy exchange through each opening.
struct DoorParams {
  double count = 3.0;
  double width_m = 1.2;
  double height_m = 2.0;
  double discharge_coefficient = 0.6;
  double open_below_speed_m_s = 0.5 / 3.6;  // = mission.yaml stop_service/standstill_speed_m_s
};

/// Climate controller: heating below, cooling above, a dead band between the set points.
struct ControllerParams {
  double heating_setpoint_K = units::celsiusToK(20.0);
  double cooling_setpoint_K = units::celsiusToK(24.0);
  double gain_W_K = 3000.0;                 // proportional gain on top of the feed-forward
  double max_heating_W = 40000.0;           // convector + blower capacity
  // The belt-driven A/C asks the engine to keep (or start) running at a standstill while the
  // cabin is more than this above the cooling set point (hybrid stop-start) [K].
  double engine_run_above_K = 2.0;
};

/// Fuel-fired coolant heater (Webasto Thermo 300 class).
struct AuxHeaterParams {
  double heat_output_W = 30000.0;
  double efficiency = 0.82;                 // heat into the coolant / fuel LHV energy
  double electric_power_W = 110.0;          // burner fan, fuel pump, control [W]
  double on_below_K = units::celsiusToK(70.0);   // starts when the coolant is below this ...
  double off_above_K = units::celsiusToK(80.0);  // ... and stops above this (or without demand)
};

/// A/C: belt-driven compressor, COP from a Carnot fraction at the ambient.
struct AcParams {
  double cooling_capacity_W = 18000.0;
  double evaporating_K = units::celsiusToK(5.0);
  double condenser_approach_K = 15.0;       // condensing temperature - ambient
  double carnot_fraction = 0.35;            // COP / COP_Carnot
  double max_cop = 6.0;                     // cap at mild ambients
  double fans_electric_W = 1200.0;          // evaporator blowers + condenser fans at full load
};

struct AirParams {
  double R_J_kgK = 287.05;
  double cp_J_kgK = 1007.0;
};

struct HvacParams {
  CabinParams cabin;
  GainParams gains;
  DoorParams doors;
  ControllerParams controller;
  AuxHeaterParams aux_heater;
  AcParams ac;
  AirParams air;
  void declare(ParamSet& ps);
  /// Cross-key consistency (throws InputError naming file and key).
  void validate(const std::string& file = "(hvac parameters)") const;
};

}  // namespace hbt::hvac
