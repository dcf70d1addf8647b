// Parameters of the 0D cylinder model (declared for hbt::ParamSet, keys "cylinder/...").
//
// Calibration maps over engine speed [rpm] × load [-] (load = injected fuel per cycle divided by
// fuel_ref_kg, the full-load fuel per cylinder and cycle) are bilinear tables with end clamping:
//   Table2D:  y(n, L) = bilinear in the cell of (speed_axis_rpm, load_axis), values row-major
//             (one row per speed, one column per load).
// Angles are crank degrees from firing TDC of the cylinder (cycle −360…360, negative = before TDC).
#pragma once
#include <string>
#include <vector>

#include "common/params.hpp"
#include "cylinder/combustion.hpp"
#include "cylinder/kinematics.hpp"
#include "cylinder/losses.hpp"
#include "common/table2d.hpp"
#include "cylinder/thermo.hpp"

namespace hbt::cylinder {

using hbt::Table2D;  // common/table2d.hpp

struct CylinderParams {
  Geometry geometry;
  // Valve events used by the model phases (Woschni C1/C2, two-zone split, IVC reference state).
  // The engine assembly's valve boundaries must use the same timing.
  double ivo_deg = 350.0, ivc_deg = -150.0, evo_deg = 130.0, evc_deg = 370.0;
  FuelSpec fuel;
  double fuel_temperature_K = 340.0;
  double cetane_number = 50.0;
  double ignition_delay_multiplier = 1.0;
  bool constant_cp = false;          // test option: cp of every group frozen at constant_cp_T_K
  double constant_cp_T_K = 300.0;
  Nozzle nozzle;
  double fuel_ref_kg = 130e-6;       // full-load fuel per cylinder and cycle (load = 1)
  // Injection maps (speed × load).
  std::vector<double> speed_axis_rpm{600, 1000, 1400, 1800, 2200};
  std::vector<double> load_axis{0.0, 0.25, 0.5, 0.75, 1.0};
  std::vector<double> soi_main_deg, rail_pressure_bar, pilot_fraction, pilot_dwell_deg,
      post_fraction, post_offset_deg;
  // Double-Wiebe maps (speed × load) and constants.
  std::vector<double> premixed_duration_deg, premixed_m, diffusion_tail_deg, diffusion_m;
  double wiebe_a = 6.908;
  double diffusion_injection_factor = 1.0;  // Δθ_diff = factor × Δθ_inj,after SOC + tail
  double flame_lambda = 1.5;                // air/fuel of the burned zone relative to stoich.
  WoschniParams woschni;
  std::string heat_transfer_correlation = "woschni";  // woschni | hohenberg (sets woschni.hohenberg)
  WallTemperatures walls;
  ChenFlynn friction;
  bool nox_enabled = true;
  double nox_interval_deg = 5.0;
  double nox_min_temperature_K = 1700.0;
  bool nox_dissociation = true;  // NO kinetics at the dissociated burned-zone temperature
  std::string nox_model = "hot_zone";       // hot_zone | burned_zone (hot_zone_no.hpp, README)
  bool nox_hot_zone = true;                 // set by finalize() from nox_model
  double nox_hot_zone_residence_s = 0.135e-3; // τ_hz: residence in the stoichiometric hot zone
  double max_substep_deg = 1.0;

  CylinderParams();                  // typical HD common-rail defaults (see README)
  void declare(ParamSet& ps);        // keys "cylinder/<group>/<name>"
  /// Builds the tables; throws InputError(file, key) on inconsistent sizes.
  void finalize(const std::string& file = "(parameters)");

  Table2D soi_main, rail_pressure, pilot_frac, pilot_dwell, post_frac, post_offset;
  Table2D premix_dur, premix_m, diff_tail, diff_m;
};

}  // namespace hbt::cylinder
