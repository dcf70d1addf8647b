// Parameters of the 48 V Li-ion pack (cells, pack layout, operating limits, enclosure and fan). SI
// units. Keys (group/key) = config/battery.yaml, where every value, its source and the sizing of
// the pack are documented. The pack set (groups pack/ and housing/) can be replaced by a file
// config/battery_pack/<name>.yaml (launch argument pack, declarePackSet()).
#pragma once
#include <string>

#include "battery/pack_fan.hpp"
#include "battery/pack_ventilation.hpp"
#include "common/params.hpp"
#include "common/units.hpp"

namespace hbt::battery {

/// Pack layout and initial state.
struct PackParams {
  int cells_in_series = 13;       // Ns: 13 x 4.2 V = 54.6 V at full charge (< 60 V, 48 V class)
  int cells_in_parallel = 7;      // Np: sized for ~19 kW discharge at the minimum voltage
  double initial_soc = 0.5;       // [-] SPEC §6
};

/// One cell: the 1-RC equivalent-circuit table and the cell's ratings.
struct CellParams {
  /// CSV (long format: SOC [-], T [K], OCV [V], R0 [Ohm], R1 [Ohm], tau1 [s]) on a full SOC x T
  /// grid. Relative paths: against the working directory (tools, tests) or the package root
  /// (the node, cosim::resolvePackagePath).
  std::string table_file = "../shared/data/battery/kokam_27Ah_mathworks_example/ecm_1RC_SOC_T_lookup.csv";
  double capacity_Ah = 27.0;
  double max_voltage_V = 4.2;             // charge-voltage limit (terminal)
  double min_voltage_V = 3.0;             // discharge cut-off (terminal)
  double max_discharge_current_A = 135.0; // 5C (assumption, battery.yaml)
  double max_charge_current_A = 81.0;     // 3C (assumption, battery.yaml)
  double mass_kg = 0.554;
  double cp_J_kgK = 1040.0;
  double cooled_area_m2 = 0.1019;         // both faces of the pouch
};

/// Derating of the current limits (and so of the power limits) with SOC and temperature.
struct LimitParams {
  double soc_min = 0.20;                  // usable window for the power limits
  double soc_max = 0.80;
  double soc_taper = 0.05;                // limits ramp from 0 at the window edge to full this far inside
  double charge_zero_K = units::celsiusToK(-10.0);   // no charging at or below
  double charge_full_K = units::celsiusToK(15.0);    // full charge current at or above
  double hot_derate_start_K = units::celsiusToK(50.0);  // both directions derate above ...
  double max_temperature_K = units::celsiusToK(60.0);   // ... to zero at this hard limit
  double horizon_s = 0.01;                // step length the published limits are computed for
};

/// The housing of this pack size (pack set, with pack/).
struct HousingParams {
  double area_m2 = 1.08;                  // inner = outer surface of the housing [m^2]
  double mass_kg = 8.7;                   // housing wall [kg]
  double flow_length_m = 0.75;            // length along the air flow over the housing [m]
  double cell_gap_resistance_Pa_s_m3 = 89.0;  // laminar flow through the cell gaps, dp/V [Pa s/m^3]
};

/// Ventilation through the housing with the fans on (pack_ventilation.hpp): fan curve, filter,
/// minor losses, air. The linear resistance of the model = filter + housing/cell gaps.
struct VentilationParams {
  double fan_free_flow_m3_s = 0.0267;     // one fan, dp = 0 [m^3/s]
  double fan_max_pressure_Pa = 38.8;      // one fan, V = 0 [Pa]
  int fan_count = 2;                      // in parallel
  double filter_resistance_Pa_s_m3 = 346.0;   // inlet filter, dp/V [Pa s/m^3]
  double minor_loss_Pa_s2_m6 = 5.1e3;     // entry and exit losses, dp/V^2 [Pa s^2/m^6]
  double air_pressure_Pa = 101325.0;      // ambient pressure [Pa]
  double air_cp_J_kgK = 1007.0;           // air specific heat [J/(kg K)]
};

/// Heat transfer of the enclosure: cells -> enclosure air -> housing wall -> ambient (pack_thermal.hpp).
struct EnclosureParams {
  double housing_cp_J_kgK = 903.0;        // housing material specific heat [J/(kg K)]
  double h_cells_natural_W_m2K = 4.0;     // cell faces -> enclosure air, fan off
  double h_cells_fan_W_m2K = 20.0;        // same, fan on
  double h_wall_inside_natural_W_m2K = 4.0;
  double h_wall_inside_fan_W_m2K = 20.0;
  double h_outside_natural_W_m2K = 4.0;   // housing -> ambient air, free convection
  double emissivity_cells = 0.9, emissivity_housing = 0.9;
  double radiation_mean_temperature_K = 300.0;
  double air_conductivity_W_mK = 0.0263, air_viscosity_m2_s = 15.89e-6, air_prandtl = 0.707;
};

/// Start state.
struct ThermalParams {
  double warm_cell_above_ambient_K = 17.0;   // start:=warm: cells this far above the ambient air
  double warm_housing_above_ambient_K = 10.0; // start:=warm: housing this far above the ambient air
};

struct NumericsParams {
  double min_temperature_K = 200.0;       // cell temperature outside [min, max] = divergence
  double max_temperature_K = 400.0;
};

struct BatteryParams {
  PackParams pack;
  CellParams cell;
  LimitParams limits;
  HousingParams housing;
  EnclosureParams enclosure;
  PackFanParams fan;
  VentilationParams ventilation;
  ThermalParams thermal;
  NumericsParams numerics;
  /// Registers every parameter as "<group>/<key>" (groups pack, housing, cell, limits,
  /// enclosure, fan, ventilation, warm_start, numerics) = config/battery.yaml.
  void declare(ParamSet& ps);
  /// The pack set alone (groups pack/ and housing/): what a config/battery_pack/<name>.yaml holds.
  void declarePackSet(ParamSet& ps);
  /// Cross-field checks (48 V class, voltage window, SOC window, derating temperatures). Throws
  /// InputError(file, key). The table-dependent checks are in BatteryModel's constructor.
  void validate(const std::string& file = "(battery parameters)") const;
};

}  // namespace hbt::battery
