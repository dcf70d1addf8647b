// Parameters of the cooling system (HT engine circuit, LT e-drive circuit, radiators, fan,
// pumps, thermostat, cabin heater). SI units. Keys (group/key) = config/cooling.yaml, where
// every value and its source is documented.
#pragma once
#include <string>

#include "common/params.hpp"
#include "common/units.hpp"

namespace hbt::cooling {

/// High-temperature (engine) circuit: thermal masses, metal-coolant coupling, pump.
struct HtCircuitParams {
  double metal_mass_kg = 350.0;            // wetted block + head + liners (cast iron), of ~650 kg dry
  double metal_cp_J_kgK = 480.0;           // grey/compacted-graphite iron
  double oil_mass_kg = 26.0;               // ~30 L sump: the oil node
  double oil_cp_J_kgK = 2100.0;
  double oil_cooler_UA_W_K = 1000.0;       // engine oil cooler, oil -> engine-loop coolant
  double oil_to_metal_UA_W_K = 300.0;      // oil <-> crankcase, block, pistons (spray, drain, splash)
  double engine_loop_volume_m3 = 0.010;    // jacket, pump, thermostat housing, bypass, short pipes
  double radiator_volume_m3 = 0.015;       // radiator core, tanks and its pipes
  double coolant_density_kg_m3 = 1050.0;   // 50/50 ethylene glycol/water at ~80 °C
  double coolant_cp_J_kgK = 3550.0;
  double metal_to_coolant_UA_W_K = 5000.0; // water-jacket conductance
  double surface_loss_UA_W_K = 30.0;       // engine outer surface -> ambient (under-floor bay)
  double pump_rated_speed_rad_s = units::rpmToRadps(2200.0);  // pump shaft = crank (1:1)
  double pump_rated_flow_m3_s = 4.0e-3;    // 240 L/min at rated speed
  double pump_rated_head_Pa = 1.5e5;       // circuit pressure drop at rated flow
  double pump_efficiency = 0.5;
};

struct ThermostatParams {
  double opening_start_K = units::celsiusToK(83.0);
  double full_open_K = units::celsiusToK(95.0);
  double hysteresis_K = 3.0;               // width of the play band (heating vs cooling curves)
  double wax_time_constant_s = 15.0;       // wax element lag behind the coolant
  double leak_fraction = 0.0;              // radiator share of the pump flow when closed
};

/// Radiator sized by a rated point (ε-NTU inverted for UA_ref) and flow scaling of UA.
struct RadiatorParams {
  double rated_heat_W = 120e3;
  double rated_coolant_in_K = units::celsiusToK(100.0);
  double rated_air_in_K = units::celsiusToK(40.0);
  double rated_air_mass_flow_kg_s = 4.5;
  double rated_coolant_mass_flow_kg_s = 4.2;
  double air_side_resistance_fraction = 0.75;  // share of 1/UA on the air side at the rated point
  double air_flow_exponent = 0.6;          // h_air ∝ ṁ_air^n (fin j-factor ∝ Re^-0.4)
  double coolant_flow_exponent = 0.8;      // h_cool ∝ ṁ_cool^0.8 (Dittus-Boelter)
};

/// Air path: fan (linear curve in flow coefficient), ram air, system resistance.
struct FanParams {
  double rated_speed_rad_s = units::rpmToRadps(2400.0);
  double rated_flow_m3_s = 4.0;            // at rated speed, standstill (no ram)
  double rated_power_W = 12000.0;          // shaft power at the rated point
  double efficiency = 0.45;                // total-to-static fan efficiency at that point
  double rated_air_density_kg_m3 = 1.2;    // air density of the rated point
  double free_delivery_ratio = 1.6;        // V̇ at Δp_fan = 0 / rated V̇ (same speed)
  double drive_ratio = 1.2;                // clutch input shaft / crank speed
  double min_speed_ratio = 0.3;            // disengaged viscous clutch: fan/input speed
  double max_speed_ratio = 0.92;           // fully engaged (residual slip)
  double engage_start_K = units::celsiusToK(92.0);
  double engage_full_K = units::celsiusToK(100.0);
  double clutch_time_constant_s = 20.0;
  double grille_area_m2 = 0.9;             // radiator face / grille area
  double ram_recovery = 0.1;               // ram flow = recovery * v * A with the fan at rest
};

struct HeaterParams {
  double balance_temperature_K = units::celsiusToK(15.0);  // no heating above this ambient
  double cabin_UA_W_K = 800.0;             // demand = UA (T_balance - T_amb)
  double conductance_W_K = 400.0;          // heater cores: max heat = G (T_cool - T_amb)
  double min_coolant_K = units::celsiusToK(40.0);  // heater valve opens at this coolant T
  double lockout_hysteresis_K = 5.0;       // ... and closes again this much lower
  double loop_volume_m3 = 0.025;           // heater-loop pipes + passenger-compartment convectors
  double loop_flow_fraction = 0.25;        // heater-loop share of the HT pump flow, valve open
  double electric_pump_flow_m3_s = 1.0e-3; // 24 V circulation pump: heater-loop flow, engine stopped
  double electric_pump_power_W = 110.0;    // ... its electric power while it runs
};

/// Low-temperature (e-machine + power electronics) circuit with its radiator ahead of the HT one.
struct LtCircuitParams {
  double coolant_volume_m3 = 0.015;
  double component_heat_capacity_J_K = 20e3; // wetted e-machine / inverter housings
  double pump_idle_speed_rad_s = units::rpmToRadps(200.0);
  double pump_max_speed_rad_s = units::rpmToRadps(600.0);
  double pump_rule_low_K = units::celsiusToK(40.0);   // idle speed below
  double pump_rule_high_K = units::celsiusToK(60.0);  // max speed above
  double pump_time_constant_s = 5.0;                  // viscous clutch response
  double pump_drive_ratio = 1.0;                      // clutch input / crank speed
  double pump_rated_flow_m3_s = 0.6e-3;               // 36 L/min at max speed
  double pump_rated_head_Pa = 0.6e5;
  double pump_efficiency = 0.35;
  double radiator_rated_heat_W = 15e3;
  double radiator_rated_coolant_in_K = units::celsiusToK(65.0);
  double radiator_rated_air_in_K = units::celsiusToK(40.0);
  double radiator_rated_air_mass_flow_kg_s = 4.5;     // same air stream as the HT radiator
};

struct AirParams {
  double R_J_kgK = 287.05;
  double cp_J_kgK = 1007.0;
};

struct NumericsParams {
  double max_substep_s = 0.1;              // coefficients frozen over a substep
  double min_temperature_K = 200.0;        // state outside [min, max] = divergence
  double max_temperature_K = 450.0;
};

/// The warm start (launch argument start:=warm): a bus mid-shift, its engine at the regulated
/// temperature. Temperatures in K.
struct WarmStartParams {
  double metal_K = 359.15;                   // engine metal [K]
  double oil_K = 359.15;                     // engine oil [K]
  double coolant_ht_K = 356.15;              // HT coolant [K]
  double coolant_lt_above_ambient_K = 3.0;   // LT (e-drive) coolant above ambient [K]
};

struct CoolingParams {
  HtCircuitParams ht;
  ThermostatParams thermostat;
  RadiatorParams radiator;
  FanParams fan;
  HeaterParams heater;
  LtCircuitParams lt;
  AirParams air;
  NumericsParams numerics;
  WarmStartParams warm_start;
  /// Registers every parameter as "<group>/<key>" (groups ht, thermostat, radiator, fan, heater,
  /// lt, air, numerics, warm_start) = config/cooling.yaml.
  void declare(ParamSet& ps);
  /// Cross-field checks (ordering of temperatures, feasible rated radiator points). Throws
  /// InputError(file, key).
  void validate(const std::string& file = "(cooling parameters)") const;
};

}  // namespace hbt::cooling
