#include "battery/battery_params.hpp"

#include <sstream>

#include "common/errors.hpp"

namespace hbt::battery {

void BatteryParams::declare(ParamSet& ps) {
  ps.setPrefix("pack/");
  ps.add("cells_in_series", pack.cells_in_series, "-", 1, 20, "Ns, cells in series");
  ps.add("cells_in_parallel", pack.cells_in_parallel, "-", 1, 100, "Np, parallel strings");
  ps.add("initial_soc", pack.initial_soc, "-", 0.0, 1.0, "state of charge at reset");

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
  ps.add("cooled_area_m2", c.cooled_area_m2, "m^2", 0.0, 2.0, "cell surface swept by the cooling air");

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

  ps.setPrefix("thermal/");
  ps.add("h_W_m2K", thermal.h_W_m2K, "W/(m^2 K)", 0.0, 500.0, "cell-to-air heat transfer coefficient");
  ps.add("extra_heat_capacity_J_K", thermal.extra_heat_capacity_J_K, "J/K", 0.0, 1e7,
         "non-cell thermal mass lumped with the cells");
  ps.setPrefix("warm_start/");
  ps.add("cell_above_ambient_K", thermal.warm_cell_above_ambient_K, "K", 0.0, 40.0,
         "start:=warm: cells above the ambient air");

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
  if (!(numerics.max_temperature_K > limits.max_temperature_K))
    throw InputError(file, "numerics/max_temperature_K", "must be above limits/max_temperature_K");
  if (!(numerics.min_temperature_K < limits.charge_zero_K))
    throw InputError(file, "numerics/min_temperature_K", "must be below limits/charge_zero_K");
}

}  // namespace hbt::battery
