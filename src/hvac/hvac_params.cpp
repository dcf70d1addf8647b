#include "hvac/hvac_params.hpp"

#include "common/errors.hpp"
#include "common/table1d.hpp"

namespace hbt::hvac {

void HvacParams::declare(ParamSet& ps) {
  CabinParams& c = cabin;
  ps.setPrefix("cabin/");
  ps.add("length_m", c.length_m, "m", 4.0, 25.0, "body envelope length");
  ps.add("width_m", c.width_m, "m", 1.5, 3.0, "body envelope width");
  ps.add("height_m", c.height_m, "m", 1.5, 5.0, "body envelope height");
  ps.add("u_value_W_m2K", c.u_value_W_m2K, "W/(m^2 K)", 0.1, 20.0, "body heat transfer coefficient");
  ps.add("air_volume_m3", c.air_volume_m3, "m^3", 5.0, 300.0, "interior air volume");
  ps.add("interior_heat_capacity_J_K", c.interior_heat_capacity_J_K, "J/K", 0.0, 1e8,
         "interior thermal mass lumped with the air");
  ps.add("fresh_air_changes_per_h", c.fresh_air_changes_per_h, "1/h", 0.0, 100.0, "outside-air exchange rate");
  ps.add("window_area_per_length_m2_m", c.window_area_per_length_m2_m, "m^2/m", 0.0, 5.0, "side glazing per metre");
  ps.add("front_rear_window_area_m2", c.front_rear_window_area_m2, "m^2", 0.0, 30.0, "front + rear glazing");
  ps.add("g_factor", c.g_factor, "-", 0.0, 1.0, "solar transmittance of the glazing");
  ps.add("solar_orientation_factor", c.solar_orientation_factor, "-", 0.0, 1.0, "share of glazing facing the sun");

  GainParams& g = gains;
  ps.setPrefix("gains/");
  ps.add("mass_per_passenger_kg", g.mass_per_passenger_kg, "kg", 30.0, 150.0, "payload per passenger");
  ps.add("crew", g.crew, "-", 0.0, 10.0, "persons on board besides the passengers");
  ps.add("heat_per_person_cold_W", g.heat_per_person_cold_W, "W", 0.0, 300.0, "sensible heat per person, cold ambient");
  ps.add("heat_per_person_warm_W", g.heat_per_person_warm_W, "W", 0.0, 300.0, "sensible heat per person, warm ambient");
  ps.add("person_boundary_ambient_K", g.person_boundary_ambient_K, "K", 250.0, 320.0, "cold/warm boundary ambient");
  ps.add("clouding_cold", g.clouding_cold, "-", 0.0, 1.0, "solar clouding factor, cold ambient");
  ps.add("clouding_warm", g.clouding_warm, "-", 0.0, 1.0, "solar clouding factor, warm ambient");
  ps.add("solar_ambient_K", g.solar_ambient_K, "K", 200.0, 350.0, "ambient breakpoints of the irradiance");
  ps.add("solar_irradiance_W_m2", g.solar_irradiance_W_m2, "W/m^2", 0.0, 1400.0, "solar irradiance at them");

  DoorParams& d = doors;
  ps.setPrefix("doors/");
  ps.add("count", d.count, "-", 0.0, 6.0, "service doors opened at a stop");
  ps.add("width_m", d.width_m, "m", 0.0, 3.0, "clear width of one door");
  ps.add("height_m", d.height_m, "m", 0.0, 3.0, "clear height of one door");
  ps.add("discharge_coefficient", d.discharge_coefficient, "-", 0.0, 1.0, "opening discharge coefficient");
  ps.add("open_below_speed_m_s", d.open_below_speed_m_s, "m/s", 0.0, 2.0, "doors open while slower than this");

  ControllerParams& k = controller;
  ps.setPrefix("controller/");
  ps.add("heating_setpoint_K", k.heating_setpoint_K, "K", 273.15, 303.15, "heating holds the cabin at this");
  ps.add("cooling_setpoint_K", k.cooling_setpoint_K, "K", 283.15, 313.15, "cooling holds the cabin at this");
  ps.add("gain_W_K", k.gain_W_K, "W/K", 0.0, 1e6, "proportional gain beyond the feed-forward");
  ps.add("max_heating_W", k.max_heating_W, "W", 0.0, 2e5, "heating demand limit");
  ps.add("engine_run_above_K", k.engine_run_above_K, "K", 0.0, 20.0,
         "engine run request while the cabin is this far above the cooling set point");

  AuxHeaterParams& h = aux_heater;
  ps.setPrefix("aux_heater/");
  ps.add("heat_output_W", h.heat_output_W, "W", 0.0, 1e5, "burner heat into the coolant when on (0 = none fitted)");
  ps.add("efficiency", h.efficiency, "-", 0.3, 1.0, "heat / fuel LHV energy");
  ps.add("electric_power_W", h.electric_power_W, "W", 0.0, 2000.0, "electric draw when on");
  ps.add("on_below_K", h.on_below_K, "K", 273.15, 373.15, "starts below this coolant temperature");
  ps.add("off_above_K", h.off_above_K, "K", 273.15, 383.15, "stops above this coolant temperature");

  AcParams& a = ac;
  ps.setPrefix("ac/");
  ps.add("cooling_capacity_W", a.cooling_capacity_W, "W", 0.0, 1e5, "evaporator capacity (0 = no A/C)");
  ps.add("evaporating_K", a.evaporating_K, "K", 250.0, 300.0, "evaporating temperature");
  ps.add("condenser_approach_K", a.condenser_approach_K, "K", 1.0, 40.0, "condensing - ambient temperature");
  ps.add("carnot_fraction", a.carnot_fraction, "-", 0.05, 1.0, "COP / Carnot COP");
  ps.add("max_cop", a.max_cop, "-", 1.0, 20.0, "COP limit at mild ambients");
  ps.add("fans_electric_W", a.fans_electric_W, "W", 0.0, 1e4, "blowers + condenser fans at full load");

  ps.setPrefix("air/");
  ps.add("R_J_kgK", air.R_J_kgK, "J/(kg K)", 280.0, 295.0, "gas constant of air");
  ps.add("cp_J_kgK", air.cp_J_kgK, "J/(kg K)", 950.0, 1100.0, "air specific heat");
  ps.setPrefix("");
}

void HvacParams::validate(const std::string& file) const {
  if (!(controller.cooling_setpoint_K > controller.heating_setpoint_K))
    throw InputError(file, "controller/cooling_setpoint_K", "must be above heating_setpoint_K (the dead band)");
  if (!(aux_heater.off_above_K > aux_heater.on_below_K))
    throw InputError(file, "aux_heater/off_above_K", "must be above on_below_K");
  if (!(ac.evaporating_K < 273.15 + 30.0))
    throw InputError(file, "ac/evaporating_K", "must be below 30 degC");
  if (!(cabin.air_volume_m3 > 0.0 && cabin.interior_heat_capacity_J_K >= 0.0))
    throw InputError(file, "cabin/air_volume_m3", "must be > 0");
  Table1D(gains.solar_ambient_K, gains.solar_irradiance_W_m2, file, "gains/solar_ambient_K");
}

}  // namespace hbt::hvac
