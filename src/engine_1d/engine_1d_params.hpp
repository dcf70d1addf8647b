// Parameters of the 1D engine assembly (keys "engine_1d/...", config/engine_1d.yaml) and the
// bundle of every model's parameters the assembly needs (cylinder, turbocharger, reference map).
//
// Geometry conventions (SI): pipes by length L [m], diameter D [m] and cell count n (FSM mesh;
// the TVD reference runs n x tvd_mesh_factor cells); volumes [m^3]; valve lift [m] over crank
// angle from the valve events of the cylinder model (cylinder/valve_events/*):
//   L(phi) = L_max sin(pi phi / Delta)^k,  phi = theta - theta_open in [0, Delta]  (0 outside),
//   A_eff  = n_v Cd(L/d) pi d L  (curtain area; Cd tables over L/d include the port restriction)
// Quasi-steady pressure losses (air filter, default back-pressure), K from a reference point:
//   dp = K mdot^2 T/p,   K = dp_ref p_ref/(mdot_ref^2 T_ref)            [Pa]
#pragma once
#include <string>
#include <vector>

#include "common/params.hpp"
#include "common/units.hpp"
#include "cylinder/cylinder_params.hpp"
#include "engine_map/map_engine.hpp"
#include "turbo/turbo_config.hpp"

namespace hbt::engine_1d {

/// Largest cylinder count of the assembly (range of engine_1d/cylinders).
constexpr int kMaxCylinders = 12;

struct PipeSpec {
  double length_m = 0.3;
  double diameter_m = 0.05;
  int cells = 2;      // base mesh: the TVD reference runs cells x tvd_mesh_factor
  int fsm_cells = 0;  // FSM mesh (> 0); 0: the FSM runs `cells`
};

struct ValveSpec {
  double diameter_m = 0.036;   // inner seat diameter d [m]
  int count = 2;               // valves per cylinder n_v
  double max_lift_m = 0.0125;  // L_max [m]
  double shape_exponent = 1.5; // k of the lift law [-]
  std::vector<double> ld{0.0, 0.1, 0.2, 0.3, 0.4};          // L/d breakpoints [-]
  std::vector<double> cd_normal{0.70, 0.66, 0.58, 0.48, 0.40};   // normal flow direction
  std::vector<double> cd_back{0.65, 0.60, 0.52, 0.44, 0.37};     // back flow
};

struct Engine1DConfig {
  std::string solver = "fsm";        // fsm | tvd
  double tvd_mesh_factor = 2.0;      // TVD: cells x factor (fine-mesh reference)
  // Cylinders: count n, firing order (cylinder numbers 1..n, fired 720/n deg apart) and the
  // twin-entry turbine entry (1, 2) each cylinder's exhaust runner feeds through its bank
  // collector; validate() checks them against each other.
  int cylinders = 6;
  std::vector<double> firing_order{1, 5, 3, 6, 2, 4};
  std::vector<double> exhaust_bank{1, 1, 1, 2, 2, 2};
  double firingIntervalDeg() const { return 720.0 / cylinders; }  // [deg crank]
  /// Turbine entry (0, 1) of cylinder k (0-based): exhaust_bank[k] - 1.
  int exhaustEntry(int k) const { return static_cast<int>(exhaust_bank[k]) - 1; }
  // Air path
  double air_filter_dp_ref_Pa = 3000.0, air_filter_ref_flow_kg_s = 0.30;
  PipeSpec compressor_outlet{0.6, 0.065, 4};
  PipeSpec charge_air_duct{2.0, 0.075, 10};  // CAC core + return duct (cold side)
  double intake_plenum_m3 = 4.0e-3;
  PipeSpec intake_runner{0.20, 0.045, 2};
  double intake_friction_darcy = 0.02;
  // Exhaust path
  PipeSpec exhaust_runner{0.20, 0.040, 1};
  double exhaust_junction_m3 = 0.6e-3;   // per bank (log manifold collector)
  PipeSpec turbine_inlet{0.20, 0.045, 1};
  double turbine_outlet_m3 = 1.5e-3;
  PipeSpec downpipe{0.8, 0.100, 4};
  double exhaust_friction_darcy = 0.025;
  double exhaust_wall_T_K = 650.0;       // Reynolds-analogy wall heat in exhaust pipes
  // Default back pressure (when the input is <= 0)
  double back_dp_ref_Pa = 15000.0, back_ref_flow_kg_s = 0.30, back_ref_T_K = 600.0,
         back_ref_p_Pa = 116000.0;
  ValveSpec intake_valve, exhaust_valve;
  // Controllers
  double fuel_kp = 2.0e-8, fuel_ki = 1.5e-7;     // kg per cylinder-cycle per Nm (and per Nm s)
  double fuel_trim_max = 0.5;                    // |trim| <= fraction of the feed-forward + ...
  double torque_dead_angle_deg = 220.0;          // request -> brake torque dead angle of the
                                                 // torque response model (controllers.hpp) [deg]
  double lambda_smoke = 1.25;                    // smoke limiter: lambda >= this
  double wg_kp = 3.0e-5, wg_ki = 6.0e-5;         // opening per Pa (and per Pa s)
  std::vector<double> boost_speed_rpm{600, 1000, 1400, 1800, 2300};
  std::vector<double> boost_load{0.0, 0.5, 1.0};
  std::vector<double> boost_pressure_ratio{1.05, 1.3, 1.6,   1.1, 1.7, 2.2,  1.2, 2.0, 2.5,
                                           1.25, 2.1, 2.55,  1.3, 2.1, 2.5};
  double controller_period_s = 0.0;      // 0: controllers act every macro step
  // Numerics
  double coupling_max_deg = 2.0;         // largest crank-angle step of the coupled step
  double coupling_cylinder_cfl = 0.0;    // > 0: dt <= cfl V_cyl/(c_cyl sum A_valve,eff) (explicit
                                         // cylinder-as-reservoir coupling limit)
  bool valve_area_midstep = false;       // valve areas at the coupled step's mid crank angle
  bool implicit_volumes = false;         // open ends to plenum/collectors implicit (gasdyn)
  bool implicit_one_cell_pipes = false;  // + the one-cell pipes at those ends (gasdyn volume.hpp)
  double subcycle_coupling_cfl = 0.0;    // > 0: pipes of >= 2 FSM cells sub-cycled (gasdyn pipe.hpp)
  double cylinder_substep_deg = 0.0;     // > 0 overrides cylinder/numerics/max_substep_deg
  double cylinder_substep_open_deg = 0.0;  // sub-step while a valve is open (EVO..IVC), if larger
  double nox_interval_deg = 0.0;         // > 0 overrides cylinder/nox/interval_deg
  double cycle_window_max_s = 0.3;       // longest window of the cycle means [s] (slow crank)
  double coupling_cylinder_cfl_slow = 0.5;  // the cylinder limit's cfl on a slow crank
  double rest_hold_after_s = 0.0;        // > 0: the gas at rest is held after the crank has stood
                                         // this long [s] (engine_assembly.hpp "Held rest"); 0: off
  double rest_hold_flow_kg_s = 0.0;      // ... and while the mean air and exhaust flows are below [kg/s]
  /// Below this crank speed a 720 deg cycle takes longer than cycle_window_max_s [rad/s].
  double slowCrank_rad_s() const { return 4.0 * units::kPi / cycle_window_max_s; }
  double friction_heat_to_oil_fraction = 0.5;  // share of the friction work carried by the oil (common/friction_heat.hpp)
  // Calibration of the cylinder model for this assembly (applied on top of cylinder/*):
  double woschni_multiplier = 0.0;       // > 0 overrides cylinder/heat_transfer/multiplier
  double diffusion_tail_scale = 1.0;     // x cylinder/combustion/diffusion_tail_deg
  double premixed_duration_scale = 1.0;  // x cylinder/combustion/premixed_duration_deg
  double friction_scale = 1.0;           // x Chen-Flynn A, C, D (B: peak-pressure term kept)
  double initial_turbo_speed_rpm = 40000.0;
  // BSFC validation region of the steady check (engine_1d_steady, steady_point.hpp): where the
  // reference fuel map and its own drag curve agree (config comment, README "BSFC against the
  // reference"); points outside are kept in the tables, flagged
  double validation_min_speed_rpm = 1100.0;
  double validation_min_load = 0.35;     // T_req / T_full-load
  // Files of the other models: relative to the folder of the engine YAML itself (so a copy of
  // the config folder, launch argument config:=DIR, brings its own sub-files), or absolute
  std::string cylinder_file = "engine_1d_cylinder.yaml";
  std::string turbo_file = "engine_1d_turbo.yaml";
  std::string reference_file = "engine_map.yaml";

  void declare(ParamSet& ps);  // keys "engine_1d/..."
};

/// Everything the Engine1D model needs.
struct Engine1DParams {
  Engine1DConfig engine;
  cylinder::CylinderParams cylinder;
  turbo::TurboConfig turbo;
  engine_map::MapEngineParams reference;
  std::string engine_source = "(parameters)";

  /// Reads config/engine_1d.yaml (path relative to repo_root unless absolute) and the files it
  /// names; each file is applied with its own ParamSet, so errors name the file and the key.
  static Engine1DParams load(const std::string& repo_root,
                             const std::string& engine_file = "config/engine_1d.yaml");
  /// The same from the engine's parameters already read (the ROS node: its private rosparam
  /// namespace, loaded by the launch file from `engine_file`, like every participant); the
  /// sub-files are read from the folder of `engine_file`.
  static Engine1DParams load(const ParamSource& engine, const std::string& engine_file);
  /// Applies engine.calibration factors to the cylinder parameters (once, by load()). Callers
  /// filling the parameters themselves (ROS node) call it, then cylinder.finalize().
  void applyCalibration();
  /// Checks cross-field consistency (throws InputError naming engine_source and the key).
  void validate() const;
};

/// Resolves `file` against `root` unless it is absolute.
std::string resolvePath(const std::string& root, const std::string& file);

}  // namespace hbt::engine_1d
