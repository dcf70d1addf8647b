#include "battery/battery_params.hpp"

#include <sstream>

#include "common/errors.hpp"

namespace hbt::battery {

void BatteryParams::declarePackSet(ParamSet& ps) {
  ps.setPrefix("pack/");
  ps.add("cells_in_series", pack.cells_in_series, "-", 1, 20, "Ns, cells in series");
  ps.add("cells_in_parallel", pack.cells_in_parallel, "-", 1, 100, "Np, parallel strings");
  ps.add("initial_soc", pack.initial_soc, "-", 0.0, 1.0, "state of charge at reset");
  ps.setPrefix("housing/");
  ps.add("area_m2", housing.area_m2, "m^2", 0.01, 20.0, "housing surface, inside = outside");
  ps.add("mass_kg", housing.mass_kg, "kg", 0.1, 500.0, "housing wall mass");
  ps.add("flow_length_m", housing.flow_length_m, "m", 0.05, 5.0, "housing length along the air flow");
  ps.add("cell_gap_resistance_Pa_s_m3", housing.cell_gap_resistance_Pa_s_m3, "Pa s/m^3", 0.0, 1e5,
         "ventilation: laminar pressure drop of the cell gaps per volume flow");
  ps.setPrefix("");
}

void BatteryParams::declare(ParamSet& ps) {
  declarePackSet(ps);

  CellParams& c = cell;
  ps.setPrefix("cell/");
  ps.add("table_file", c.table_file, "1-RC table CSV: SOC, T, OCV, R0, R1, tau1");
  ps.add("capacity_Ah", c.capacity_Ah, "Ah", 0.1, 1000.0, "cell capacity (coulomb counting)");
  ps.add("max_voltage_V", c.max_voltage_V, "V", 3.0, 4.5, "cell terminal voltage limit, charging");
  ps.add("min_voltage_V", c.min_voltage_V, "V", 1.0, 3.6, "cell terminal voltage limit, discharging");
  ps.add("max_discharge_current_A", c.max_discharge_current_A, "A", 0.1, 5000.0, "cell discharge current limit");
  ps.add("max_charge_current_A", c.max_charge_current_A, "A", 0.1, 5000.0, "cell charge current limit");
  ps.add("mass_kg", c.mass_kg, "kg", 0.01, 10.0, "cell mass");
  ps.add("cp_J_kgK", c.cp_J_kgK, "J/(kg K)", 500.0, 1500.0, "cell specific heat");
  ps.add("cooled_area_m2", c.cooled_area_m2, "m^2", 0.0, 2.0, "cell surface in the enclosure air");

  LimitParams& l = limits;
  ps.setPrefix("limits/");
  ps.add("soc_min", l.soc_min, "-", 0.0, 1.0, "discharge limit 0 at and below");
  ps.add("soc_max", l.soc_max, "-", 0.0, 1.0, "charge limit 0 at and above");
  ps.add("soc_taper", l.soc_taper, "-", 1e-4, 0.5, "limits ramp over this SOC band inside the window");
  ps.add("charge_zero_K", l.charge_zero_K, "K", 200.0, 320.0, "charge current 0 at and below");
  ps.add("charge_full_K", l.charge_full_K, "K", 200.0, 330.0, "full charge current at and above");
  ps.add("hot_derate_start_K", l.hot_derate_start_K, "K", 280.0, 360.0, "both limits derate above");
  ps.add("max_temperature_K", l.max_temperature_K, "K", 290.0, 370.0, "both limits 0 at and above");
  ps.add("horizon_s", l.horizon_s, "s", 1e-4, 100.0, "step length of the published power limits");

  EnclosureParams& e = enclosure;
  ps.setPrefix("enclosure/");
  ps.add("housing_cp_J_kgK", e.housing_cp_J_kgK, "J/(kg K)", 300.0, 2000.0, "housing material specific heat");
  ps.add("h_cells_natural_W_m2K", e.h_cells_natural_W_m2K, "W/(m^2 K)", 0.1, 100.0, "cells -> enclosure air, fan off");
  ps.add("h_cells_fan_W_m2K", e.h_cells_fan_W_m2K, "W/(m^2 K)", 0.1, 300.0, "cells -> enclosure air, fan on");
  ps.add("h_wall_inside_natural_W_m2K", e.h_wall_inside_natural_W_m2K, "W/(m^2 K)", 0.1, 100.0,
         "enclosure air -> housing, fan off");
  ps.add("h_wall_inside_fan_W_m2K", e.h_wall_inside_fan_W_m2K, "W/(m^2 K)", 0.1, 300.0,
         "enclosure air -> housing, fan on");
  ps.add("h_outside_natural_W_m2K", e.h_outside_natural_W_m2K, "W/(m^2 K)", 0.1, 100.0,
         "housing -> ambient air, free convection");
  ps.add("emissivity_cells", e.emissivity_cells, "-", 0.01, 1.0, "cell surfaces facing the housing");
  ps.add("emissivity_housing", e.emissivity_housing, "-", 0.01, 1.0, "housing surfaces, inside and outside");
  ps.add("radiation_mean_temperature_K", e.radiation_mean_temperature_K, "K", 200.0, 400.0,
         "temperature of the linearised radiation coefficients");
  ps.add("air_conductivity_W_mK", e.air_conductivity_W_mK, "W/(m K)", 0.01, 0.05, "ambient air");
  ps.add("air_viscosity_m2_s", e.air_viscosity_m2_s, "m^2/s", 5e-6, 5e-5, "ambient air, kinematic");
  ps.add("air_prandtl", e.air_prandtl, "-", 0.5, 1.0, "ambient air");
  ps.setPrefix("fan/");
  ps.add("rated_power_W", fan.rated_power_W, "W", 0.0, 2000.0, "fan electric power when on");
  ps.add("on_K", fan.on_K, "K", 250.0, 350.0, "fan on at and above this cell temperature");
  ps.add("off_K", fan.off_K, "K", 250.0, 350.0, "fan off at and below this cell temperature");
  VentilationParams& v = ventilation;
  ps.setPrefix("ventilation/");
  ps.add("fan_free_flow_m3_s", v.fan_free_flow_m3_s, "m^3/s", 1e-4, 1.0, "one fan's free-air flow");
  ps.add("fan_max_pressure_Pa", v.fan_max_pressure_Pa, "Pa", 1.0, 2000.0, "one fan's maximum static pressure");
  ps.add("fan_count", v.fan_count, "-", 1, 20, "fans in parallel");
  ps.add("filter_resistance_Pa_s_m3", v.filter_resistance_Pa_s_m3, "Pa s/m^3", 0.0, 1e5,
         "inlet filter pressure drop per volume flow");
  ps.add("minor_loss_Pa_s2_m6", v.minor_loss_Pa_s2_m6, "Pa s^2/m^6", 0.0, 1e7,
         "entry and exit losses per volume flow squared");
  ps.add("air_pressure_Pa", v.air_pressure_Pa, "Pa", 5e4, 1.2e5, "ambient air pressure (density)");
  ps.add("air_cp_J_kgK", v.air_cp_J_kgK, "J/(kg K)", 900.0, 1100.0, "air specific heat");
  ps.setPrefix("warm_start/");
  ps.add("cell_above_ambient_K", thermal.warm_cell_above_ambient_K, "K", 0.0, 40.0,
         "start:=warm: cells above the ambient air");
  ps.add("housing_above_ambient_K", thermal.warm_housing_above_ambient_K, "K", 0.0, 40.0,
         "start:=warm: housing above the ambient air");

  ps.setPrefix("numerics/");
  ps.add("min_temperature_K", numerics.min_temperature_K, "K", 100.0, 300.0, "divergence bound");
  ps.add("max_temperature_K", numerics.max_temperature_K, "K", 320.0, 1000.0, "divergence bound");
  ps.setPrefix("");
}

void BatteryParams::validate(const std::string& file) const {
  // 48 V class: the pack must stay below the 60 V DC protective-extra-low-voltage limit even at
  // the charge-voltage limit.
  const double v_pack_max = pack.cells_in_series * cell.max_voltage_V;
  if (!(v_pack_max < 60.0)) {
    std::ostringstream os;
    os << "Ns x cell/max_voltage_V = " << v_pack_max << " V must stay below 60 V (48 V class)";
    throw InputError(file, "pack/cells_in_series", os.str());
  }
  if (!(cell.max_voltage_V > cell.min_voltage_V))
    throw InputError(file, "cell/max_voltage_V", "must be above cell/min_voltage_V");
  if (cell.table_file.empty()) throw InputError(file, "cell/table_file", "must name the 1-RC table CSV");
  if (!(limits.soc_max - limits.soc_min > 2.0 * limits.soc_taper))
    throw InputError(file, "limits/soc_max", "must exceed limits/soc_min by more than 2 x soc_taper");
  if (!(limits.charge_full_K > limits.charge_zero_K))
    throw InputError(file, "limits/charge_full_K", "must be above limits/charge_zero_K");
  if (!(limits.max_temperature_K > limits.hot_derate_start_K))
    throw InputError(file, "limits/max_temperature_K", "must be above limits/hot_derate_start_K");
  if (!(limits.hot_derate_start_K > limits.charge_full_K))
    throw InputError(file, "limits/hot_derate_start_K", "must be above limits/charge_full_K");
  if (!(fan.off_K < fan.on_K)) throw InputError(file, "fan/off_K", "must be below fan/on_K (hysteresis)");
  if (!(numerics.max_temperature_K > limits.max_temperature_K))
    throw InputError(file, "numerics/max_temperature_K", "must be above limits/max_temperature_K");
  if (!(numerics.min_temperature_K < limits.charge_zero_K))
    throw InputError(file, "numerics/min_temperature_K", "must be below limits/charge_zero_K");
}

}  // namespace hbt::battery
