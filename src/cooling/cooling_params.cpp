#include "cooling/cooling_params.hpp"

#include "common/errors.hpp"

namespace hbt::cooling {

void CoolingParams::declare(ParamSet& ps) {
  HtCircuitParams& h = ht;
  ps.setPrefix("ht/");
  ps.add("metal_mass_kg", h.metal_mass_kg, "kg", 10.0, 3000.0, "engine metal taking part in warm-up");
  ps.add("metal_cp_J_kgK", h.metal_cp_J_kgK, "J/(kg K)", 300.0, 1000.0, "metal specific heat");
  ps.add("oil_mass_kg", h.oil_mass_kg, "kg", 1.0, 200.0, "engine oil (the oil node)");
  ps.add("oil_cp_J_kgK", h.oil_cp_J_kgK, "J/(kg K)", 1500.0, 2800.0, "oil specific heat");
  ps.add("oil_cooler_UA_W_K", h.oil_cooler_UA_W_K, "W/K", 10.0, 1e5, "engine oil cooler, oil to engine-loop coolant");
  ps.add("oil_to_metal_UA_W_K", h.oil_to_metal_UA_W_K, "W/K", 0.0, 1e5, "oil to crankcase, block and pistons");
  ps.add("engine_loop_volume_m3", h.engine_loop_volume_m3, "m^3", 0.001, 0.2,
         "HT coolant of the engine loop (jacket, pump, thermostat housing, bypass)");
  ps.add("radiator_volume_m3", h.radiator_volume_m3, "m^3", 0.001, 0.2, "HT coolant in the radiator and its pipes");
  ps.add("coolant_density_kg_m3", h.coolant_density_kg_m3, "kg/m^3", 900.0, 1200.0, "coolant density");
  ps.add("coolant_cp_J_kgK", h.coolant_cp_J_kgK, "J/(kg K)", 2000.0, 4300.0, "coolant specific heat");
  ps.add("metal_to_coolant_UA_W_K", h.metal_to_coolant_UA_W_K, "W/K", 100.0, 1e5, "water-jacket conductance");
  ps.add("surface_loss_UA_W_K", h.surface_loss_UA_W_K, "W/K", 0.0, 1000.0, "engine surface to ambient");
  ps.add("pump_rated_speed_rad_s", h.pump_rated_speed_rad_s, "rad/s", 50.0, 600.0, "pump shaft speed of the rated point");
  ps.add("pump_rated_flow_m3_s", h.pump_rated_flow_m3_s, "m^3/s", 1e-4, 0.05, "pump flow at rated speed");
  ps.add("pump_rated_head_Pa", h.pump_rated_head_Pa, "Pa", 1e3, 1e6, "pump pressure rise at rated speed");
  ps.add("pump_efficiency", h.pump_efficiency, "-", 0.05, 1.0, "pump hydraulic efficiency");

  ThermostatParams& t = thermostat;
  ps.setPrefix("thermostat/");
  ps.add("opening_start_K", t.opening_start_K, "K", 300.0, 400.0, "opening starts (heating)");
  ps.add("full_open_K", t.full_open_K, "K", 300.0, 420.0, "fully open (heating)");
  ps.add("hysteresis_K", t.hysteresis_K, "K", 0.0, 15.0, "play band: cooling curve shifted down by this");
  ps.add("wax_time_constant_s", t.wax_time_constant_s, "s", 0.0, 600.0, "first-order wax lag (0 = none)");
  ps.add("leak_fraction", t.leak_fraction, "-", 0.0, 0.2, "radiator flow share when closed");

  RadiatorParams& r = radiator;
  ps.setPrefix("radiator/");
  ps.add("rated_heat_W", r.rated_heat_W, "W", 1e3, 1e6, "heat rejection at the rated point");
  ps.add("rated_coolant_in_K", r.rated_coolant_in_K, "K", 300.0, 420.0, "rated coolant inlet");
  ps.add("rated_air_in_K", r.rated_air_in_K, "K", 230.0, 350.0, "rated air inlet");
  ps.add("rated_air_mass_flow_kg_s", r.rated_air_mass_flow_kg_s, "kg/s", 0.1, 50.0, "rated air flow");
  ps.add("rated_coolant_mass_flow_kg_s", r.rated_coolant_mass_flow_kg_s, "kg/s", 0.05, 50.0, "rated coolant flow");
  ps.add("air_side_resistance_fraction", r.air_side_resistance_fraction, "-", 0.05, 0.95, "air-side share of 1/UA");
  ps.add("air_flow_exponent", r.air_flow_exponent, "-", 0.3, 1.0, "h_air ~ m_air^n");
  ps.add("coolant_flow_exponent", r.coolant_flow_exponent, "-", 0.3, 1.0, "h_cool ~ m_cool^n");

  FanParams& f = fan;
  ps.setPrefix("fan/");
  ps.add("rated_speed_rad_s", f.rated_speed_rad_s, "rad/s", 50.0, 1000.0, "fan speed of the rated point");
  ps.add("rated_flow_m3_s", f.rated_flow_m3_s, "m^3/s", 0.1, 50.0, "air flow at rated speed, standstill");
  ps.add("rated_power_W", f.rated_power_W, "W", 100.0, 1e5, "shaft power at the rated point");
  ps.add("efficiency", f.efficiency, "-", 0.1, 0.9, "fan efficiency (also as turbine when windmilling)");
  ps.add("rated_air_density_kg_m3", f.rated_air_density_kg_m3, "kg/m^3", 0.5, 1.6, "air density of the rated point");
  ps.add("free_delivery_ratio", f.free_delivery_ratio, "-", 1.05, 5.0, "free-delivery / rated flow");
  ps.add("drive_ratio", f.drive_ratio, "-", 0.2, 5.0, "clutch input / crank speed");
  ps.add("min_speed_ratio", f.min_speed_ratio, "-", 0.0, 1.0, "fan/input speed, clutch disengaged");
  ps.add("max_speed_ratio", f.max_speed_ratio, "-", 0.0, 1.0, "fan/input speed, clutch engaged");
  ps.add("engage_start_K", f.engage_start_K, "K", 300.0, 420.0, "clutch starts engaging");
  ps.add("engage_full_K", f.engage_full_K, "K", 300.0, 430.0, "clutch fully engaged");
  ps.add("clutch_time_constant_s", f.clutch_time_constant_s, "s", 0.0, 300.0, "engagement lag (0 = none)");
  ps.add("grille_area_m2", f.grille_area_m2, "m^2", 0.05, 10.0, "grille / radiator face area");
  ps.add("ram_recovery", f.ram_recovery, "-", 0.0, 1.0, "ram flow / (v A) with the fan at rest");

  HeaterParams& c = heater;
  ps.setPrefix("heater/");
  ps.add("balance_temperature_K", c.balance_temperature_K, "K", 250.0, 310.0, "heating only below this ambient");
  ps.add("cabin_UA_W_K", c.cabin_UA_W_K, "W/K", 0.0, 1e4, "heat demand per K below balance");
  ps.add("conductance_W_K", c.conductance_W_K, "W/K", 0.0, 1e4, "heater-core limit G (T_cool - T_amb)");
  ps.add("min_coolant_K", c.min_coolant_K, "K", 250.0, 380.0, "heater valve opens at this coolant T");
  ps.add("lockout_hysteresis_K", c.lockout_hysteresis_K, "K", 0.0, 30.0, "valve closes this much below min_coolant_K");
  ps.add("loop_volume_m3", c.loop_volume_m3, "m^3", 0.001, 0.3, "HT coolant in the heater loop and convectors");
  ps.add("loop_flow_fraction", c.loop_flow_fraction, "-", 0.01, 1.0, "heater-loop share of the HT pump flow");
  ps.add("electric_pump_flow_m3_s", c.electric_pump_flow_m3_s, "m^3/s", 0.0, 0.01,
         "electric circulation pump flow with the engine stopped (0 = no pump)");
  ps.add("electric_pump_power_W", c.electric_pump_power_W, "W", 0.0, 2000.0, "its electric power while running");

  LtCircuitParams& l = lt;
  ps.setPrefix("lt/");
  ps.add("coolant_volume_m3", l.coolant_volume_m3, "m^3", 0.001, 0.2, "LT coolant volume");
  ps.add("component_heat_capacity_J_K", l.component_heat_capacity_J_K, "J/K", 0.0, 1e6, "wetted e-drive housings");
  ps.add("pump_idle_speed_rad_s", l.pump_idle_speed_rad_s, "rad/s", 0.0, 200.0, "LT pump speed below rule_low");
  ps.add("pump_max_speed_rad_s", l.pump_max_speed_rad_s, "rad/s", 1.0, 500.0, "LT pump speed above rule_high");
  ps.add("pump_rule_low_K", l.pump_rule_low_K, "K", 250.0, 400.0, "rule: idle speed below");
  ps.add("pump_rule_high_K", l.pump_rule_high_K, "K", 250.0, 400.0, "rule: max speed above");
  ps.add("pump_time_constant_s", l.pump_time_constant_s, "s", 0.0, 300.0, "viscous clutch lag (0 = none)");
  ps.add("pump_drive_ratio", l.pump_drive_ratio, "-", 0.1, 5.0, "clutch input / crank speed");
  ps.add("pump_rated_flow_m3_s", l.pump_rated_flow_m3_s, "m^3/s", 1e-5, 0.01, "flow at max speed");
  ps.add("pump_rated_head_Pa", l.pump_rated_head_Pa, "Pa", 1e2, 1e6, "pressure rise at max speed");
  ps.add("pump_efficiency", l.pump_efficiency, "-", 0.05, 1.0, "LT pump hydraulic efficiency");
  ps.add("radiator_rated_heat_W", l.radiator_rated_heat_W, "W", 100.0, 1e6, "LT radiator rated heat");
  ps.add("radiator_rated_coolant_in_K", l.radiator_rated_coolant_in_K, "K", 280.0, 400.0, "rated coolant inlet");
  ps.add("radiator_rated_air_in_K", l.radiator_rated_air_in_K, "K", 230.0, 350.0, "rated air inlet");
  ps.add("radiator_rated_air_mass_flow_kg_s", l.radiator_rated_air_mass_flow_kg_s, "kg/s", 0.1, 50.0, "rated air flow");

  ps.setPrefix("air/");
  ps.add("R_J_kgK", air.R_J_kgK, "J/(kg K)", 280.0, 295.0, "gas constant of air");
  ps.add("cp_J_kgK", air.cp_J_kgK, "J/(kg K)", 950.0, 1100.0, "air specific heat");

  ps.setPrefix("numerics/");
  ps.add("max_substep_s", numerics.max_substep_s, "s", 1e-4, 10.0, "frozen-coefficient substep");
  ps.add("min_temperature_K", numerics.min_temperature_K, "K", 100.0, 300.0, "divergence bound");
  ps.add("max_temperature_K", numerics.max_temperature_K, "K", 350.0, 1000.0, "divergence bound");
  ps.setPrefix("warm_start/");
  ps.add("metal_K", warm_start.metal_K, "K", 300.0, 400.0, "start:=warm: engine metal");
  ps.add("oil_K", warm_start.oil_K, "K", 300.0, 420.0, "start:=warm: engine oil");
  ps.add("coolant_ht_K", warm_start.coolant_ht_K, "K", 300.0, 390.0, "start:=warm: HT coolant");
  ps.add("coolant_lt_above_ambient_K", warm_start.coolant_lt_above_ambient_K, "K", 0.0, 50.0,
         "start:=warm: LT coolant above ambient");
  ps.setPrefix("");
}

void CoolingParams::validate(const std::string& file) const {
  if (!(thermostat.full_open_K > thermostat.opening_start_K))
    throw InputError(file, "thermostat/full_open_K", "must be above opening_start_K");
  if (!(fan.engage_full_K > fan.engage_start_K))
    throw InputError(file, "fan/engage_full_K", "must be above engage_start_K");
  if (!(fan.max_speed_ratio >= fan.min_speed_ratio))
    throw InputError(file, "fan/max_speed_ratio", "must be >= min_speed_ratio");
  if (!(lt.pump_max_speed_rad_s >= lt.pump_idle_speed_rad_s))
    throw InputError(file, "lt/pump_max_speed_rad_s", "must be >= pump_idle_speed_rad_s");
  if (!(lt.pump_rule_high_K > lt.pump_rule_low_K))
    throw InputError(file, "lt/pump_rule_high_K", "must be above pump_rule_low_K");
  if (!(numerics.max_temperature_K > numerics.min_temperature_K))
    throw InputError(file, "numerics/max_temperature_K", "must be above min_temperature_K");
}

}  // namespace hbt::cooling
