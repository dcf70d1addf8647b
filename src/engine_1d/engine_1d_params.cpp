#include "engine_1d/engine_1d_params.hpp"

#include <algorithm>
#include <set>

#include "common/errors.hpp"
#include "common/yaml_params.hpp"

namespace hbt::engine_1d {
namespace {

void addPipe(ParamSet& ps, const std::string& key, PipeSpec& p, const std::string& what) {
  ps.add(key + "/length_m", p.length_m, "m", 0.02, 10.0, what + ": length");
  ps.add(key + "/diameter_m", p.diameter_m, "m", 0.005, 0.5, what + ": inner diameter");
  ps.add(key + "/cells", p.cells, "-", 2, 200, what + ": base cells (TVD x tvd_mesh_factor)");
  ps.add(key + "/fsm_cells", p.fsm_cells, "-", 0, 200, what + ": FSM cells (0: = cells)");
}

void addValve(ParamSet& ps, const std::string& key, ValveSpec& v, const std::string& what) {
  ps.add(key + "/diameter_m", v.diameter_m, "m", 0.005, 0.1, what + ": inner seat diameter");
  ps.add(key + "/count", v.count, "-", 1, 4, what + ": valves per cylinder");
  ps.add(key + "/max_lift_m", v.max_lift_m, "m", 0.001, 0.03, what + ": maximum lift");
  ps.add(key + "/shape_exponent", v.shape_exponent, "-", 0.5, 4.0,
         what + ": lift law L_max sin(pi phi/Delta)^k");
  ps.add(key + "/ld", v.ld, "-", 0.0, 1.0, what + ": L/d breakpoints of the Cd tables");
  ps.add(key + "/cd_normal", v.cd_normal, "-", 0.0, 1.0, what + ": Cd (curtain) normal flow");
  ps.add(key + "/cd_back", v.cd_back, "-", 0.0, 1.0, what + ": Cd (curtain) back flow");
}

// Cylinder count, firing order and exhaust banks against each other (before any simulation).
void validateCylinders(const Engine1DConfig& e, const std::string& f) {
  const int n = e.cylinders;
  const std::string one_to_n = "1.." + std::to_string(n);
  if (n < 1 || n > kMaxCylinders)
    throw InputError(f, "engine_1d/cylinders",
                     "must be 1.." + std::to_string(kMaxCylinders) + ", got " + std::to_string(n));
  std::vector<double> fo = e.firing_order;
  std::sort(fo.begin(), fo.end());
  bool permutation = static_cast<int>(fo.size()) == n;
  for (std::size_t i = 0; permutation && i < fo.size(); ++i) permutation = fo[i] == i + 1.0;
  if (!permutation)
    throw InputError(f, "engine_1d/firing_order",
                     "must be a permutation of " + one_to_n + " (engine_1d/cylinders = " +
                         std::to_string(n) + "), got " + std::to_string(fo.size()) + " values");
  if (static_cast<int>(e.exhaust_bank.size()) != n)
    throw InputError(f, "engine_1d/exhaust_bank",
                     "needs one turbine entry per cylinder " + one_to_n + ": " + std::to_string(n) +
                         " values, got " + std::to_string(e.exhaust_bank.size()));
  int fed[2] = {0, 0};
  for (int k = 0; k < n; ++k) {
    const double b = e.exhaust_bank[k];
    if (b != 1.0 && b != 2.0)
      throw InputError(f, "engine_1d/exhaust_bank",
                       "cylinder " + std::to_string(k + 1) + ": turbine entry must be 1 or 2, got " +
                           std::to_string(b));
    ++fed[e.exhaustEntry(k)];
  }
  for (int b = 0; b < 2; ++b)
    if (fed[b] == 0)
      throw InputError(f, "engine_1d/exhaust_bank",
                       "turbine entry " + std::to_string(b + 1) +
                           " has no cylinder (the twin-entry turbine needs both fed)");
}

}  // namespace

std::string resolvePath(const std::string& root, const std::string& file) {
  if (!file.empty() && file[0] == '/') return file;
  return (root.empty() ? std::string(".") : root) + "/" + file;
}

void Engine1DConfig::declare(ParamSet& ps) {
  ps.setPrefix("engine_1d/");
  ps.add("solver", solver, "pipe solver: fsm (fast, staggered) or tvd (fine-mesh reference)");
  ps.add("tvd_mesh_factor", tvd_mesh_factor, "-", 1.0, 8.0, "TVD cells = FSM cells x factor");
  ps.add("cylinders", cylinders, "-", 1, kMaxCylinders, "cylinder count n (firing interval 720/n deg)");
  ps.add("firing_order", firing_order, "-", 1.0, kMaxCylinders, "cylinder numbers 1..n in firing order");
  ps.add("exhaust_bank", exhaust_bank, "-", 1.0, 2.0,
         "twin-entry turbine entry (1, 2) of cylinders 1..n (bank collector of its exhaust runner)");
  ps.add("air_filter/dp_ref_Pa", air_filter_dp_ref_Pa, "Pa", 0.0, 2e4, "filter loss at ref flow");
  ps.add("air_filter/ref_flow_kg_s", air_filter_ref_flow_kg_s, "kg/s", 0.01, 2.0,
         "reference flow of the filter loss (at 298 K, 100 kPa)");
  addPipe(ps, "intake/compressor_outlet", compressor_outlet, "compressor outlet (hot) pipe");
  addPipe(ps, "intake/charge_air_duct", charge_air_duct, "CAC core + duct to the manifold");
  ps.add("intake/plenum_m3", intake_plenum_m3, "m^3", 1e-4, 0.05, "intake manifold plenum");
  addPipe(ps, "intake/runner", intake_runner, "intake runner (one per cylinder)");
  ps.add("intake/friction_darcy", intake_friction_darcy, "-", 0.0, 0.2, "Darcy friction factor");
  addPipe(ps, "exhaust/runner", exhaust_runner, "exhaust runner (one per cylinder)");
  ps.add("exhaust/junction_m3", exhaust_junction_m3, "m^3", 1e-5, 0.02, "collector per bank");
  addPipe(ps, "exhaust/turbine_inlet", turbine_inlet, "collector -> turbine entry (per bank)");
  ps.add("exhaust/turbine_outlet_m3", turbine_outlet_m3, "m^3", 1e-5, 0.05, "turbine outlet");
  addPipe(ps, "exhaust/downpipe", downpipe, "turbine outlet -> aftertreatment inlet");
  ps.add("exhaust/friction_darcy", exhaust_friction_darcy, "-", 0.0, 0.2, "Darcy factor");
  ps.add("exhaust/wall_T_K", exhaust_wall_T_K, "K", 300.0, 1200.0,
         "exhaust pipe wall temperature (Reynolds-analogy heat transfer)");
  ps.add("back_pressure/dp_ref_Pa", back_dp_ref_Pa, "Pa", 0.0, 1e5, "ATS loss at ref point");
  ps.add("back_pressure/ref_flow_kg_s", back_ref_flow_kg_s, "kg/s", 0.01, 2.0, "ref flow");
  ps.add("back_pressure/ref_T_K", back_ref_T_K, "K", 250.0, 1200.0, "ref temperature");
  ps.add("back_pressure/ref_p_Pa", back_ref_p_Pa, "Pa", 5e4, 3e5, "ref pressure");
  addValve(ps, "valves/intake", intake_valve, "intake valves");
  addValve(ps, "valves/exhaust", exhaust_valve, "exhaust valves");
  ps.add("control/fuel_kp", fuel_kp, "kg/Nm", 0.0, 1e-5, "torque PID: kg per cyl-cycle per Nm");
  ps.add("control/fuel_ki", fuel_ki, "kg/(Nm s)", 0.0, 1e-4, "torque PID integral gain");
  ps.add("control/fuel_trim_max", fuel_trim_max, "-", 0.0, 2.0,
         "PID trim limited to +- this fraction of the full-load fuel");
  ps.add("control/torque_dead_angle_deg", torque_dead_angle_deg, "deg", 0.0, 720.0,
         "crank angle from a torque request to the first brake torque it gives (fuel trim model)");
  ps.add("control/lambda_smoke", lambda_smoke, "-", 1.0, 3.0, "smoke limiter: minimum lambda");
  ps.add("control/wastegate_kp", wg_kp, "1/Pa", 0.0, 1e-2, "boost PID proportional gain");
  ps.add("control/wastegate_ki", wg_ki, "1/(Pa s)", 0.0, 1e-1, "boost PID integral gain");
  ps.add("control/boost_speed_rpm", boost_speed_rpm, "rpm", 0.0, 5000.0, "boost map speed axis");
  ps.add("control/boost_load", boost_load, "-", 0.0, 1.5, "boost map load axis (T_req/T_fl)");
  ps.add("control/boost_pressure_ratio", boost_pressure_ratio, "-", 0.8, 5.0,
         "boost target p_im/p_amb (rows = speeds, columns = loads)");
  ps.add("control/period_s", controller_period_s, "s", 0.0, 1.0, "0 = every macro step");
  ps.add("numerics/coupling_max_deg", coupling_max_deg, "deg", 0.1, 10.0,
         "largest crank-angle increment of one coupled step");
  ps.add("numerics/coupling_cylinder_cfl", coupling_cylinder_cfl, "-", 0.0, 2.0,
         "> 0: coupled step <= cfl V_cyl/(c_cyl sum A_valve,eff)");
  ps.add("numerics/valve_area_midstep", valve_area_midstep,
         "valve areas at the mid crank angle of the coupled step (else at its start)");
  ps.add("numerics/implicit_volumes", implicit_volumes,
         "open ends to finite volumes linearised-implicit in the volume pressure");
  ps.add("numerics/implicit_one_cell_pipes", implicit_one_cell_pipes,
         "one-cell pipes at those open ends implicit in their cell pressure too");
  ps.add("numerics/subcycle_coupling_cfl", subcycle_coupling_cfl, "-", 0.0, 2.0,
         "> 0: pipes of >= 2 FSM cells take their own CFL sub-steps; their end cells limit the "
         "coupled step to this x dx/(|u| + c)");
  ps.add("numerics/cylinder_substep_deg", cylinder_substep_deg, "deg", 0.0, 10.0,
         "> 0 overrides cylinder/numerics/max_substep_deg");
  ps.add("numerics/cylinder_substep_open_deg", cylinder_substep_open_deg, "deg", 0.0, 10.0,
         "cylinder sub-step while a valve is open (EVO..IVC) if larger than cylinder_substep_deg");
  ps.add("numerics/nox_interval_deg", nox_interval_deg, "deg", 0.0, 20.0,
         "> 0 overrides cylinder/nox/interval_deg");
  ps.add("numerics/cycle_window_max_s", cycle_window_max_s, "s", 0.01, 10.0,
         "longest window of the published cycle means (a cycle slower than this: the last S seconds)");
  ps.add("numerics/coupling_cylinder_cfl_slow", coupling_cylinder_cfl_slow, "-", 0.01, 2.0,
         "coupling_cylinder_cfl below the slow-crank speed 720 deg / cycle_window_max_s");
  ps.add("numerics/rest_hold_after_s", rest_hold_after_s, "s", 0.0, 60.0,
         "the gas state is held once the crank has stood this long (0: never)");
  ps.add("numerics/rest_hold_flow_kg_s", rest_hold_flow_kg_s, "kg/s", 0.0, 0.1,
         "largest mean air / exhaust flow at which the gas at rest is held");
  ps.add("numerics/initial_turbo_speed_rpm", initial_turbo_speed_rpm, "rpm", 0.0, 2e5,
         "turbo speed at reset (scaled with the requested load)");
  ps.add("calibration/woschni_multiplier", woschni_multiplier, "-", 0.0, 3.0,
         "> 0 overrides cylinder/heat_transfer/multiplier");
  ps.add("calibration/diffusion_tail_scale", diffusion_tail_scale, "-", 0.3, 3.0,
         "factor on cylinder/combustion/diffusion_tail_deg");
  ps.add("calibration/premixed_duration_scale", premixed_duration_scale, "-", 0.3, 3.0,
         "factor on cylinder/combustion/premixed_duration_deg");
  ps.add("calibration/friction_scale", friction_scale, "-", 0.3, 2.0,
         "factor on the Chen-Flynn constant and speed terms");
  ps.add("validation/min_speed_rpm", validation_min_speed_rpm, "rpm", 0.0, 5000.0,
         "BSFC validation region of the steady check: lowest speed");
  ps.add("validation/min_load", validation_min_load, "-", 0.0, 1.0,
         "BSFC validation region of the steady check: lowest load (T_req / T_full-load)");
  ps.add("friction_heat_to_oil_fraction", friction_heat_to_oil_fraction, "-", 0.0, 1.0,
         "share of the friction work carried by the oil (bearings, valve train); the rest heats the metal");
  ps.add("files/cylinder", cylinder_file, "cylinder model YAML (relative to this file's folder)");
  ps.add("files/turbo", turbo_file, "turbocharger YAML (relative to this file's folder)");
  ps.add("files/reference", reference_file, "reference map-engine YAML (relative to this file's folder)");
  ps.setPrefix("");
}

Engine1DParams Engine1DParams::load(const std::string& root, const std::string& engine_file) {
  const std::string f = resolvePath(root, engine_file);
  return load(readYamlParams(f), f);
}

Engine1DParams Engine1DParams::load(const ParamSource& engine, const std::string& engine_file) {
  Engine1DParams p;
  {
    ParamSet ps;
    p.engine.declare(ps);
    applyParams(ps, engine);
    requireKeys(ps, engine);  // after: a misspelt key is named as unknown first
    p.engine_source = engine.file;
  }
  const auto cut = engine_file.find_last_of('/');  // sub-files: beside the engine YAML
  const std::string folder = cut == std::string::npos ? "." : cut == 0 ? "/" : engine_file.substr(0, cut);
  {
    const ParamSource src = readYamlParams(resolvePath(folder, p.engine.cylinder_file));
    ParamSet ps;
    p.cylinder.declare(ps);
    applyParams(ps, src, {"cylinder_rig/"});
    requireKeys(ps, src);  // after: a misspelt key is named as unknown first
  }
  p.applyCalibration();
  p.cylinder.finalize(resolvePath(folder, p.engine.cylinder_file));
  {
    const ParamSource src = readYamlParams(resolvePath(folder, p.engine.turbo_file));
    ParamSet ps;
    p.turbo.declare(ps, "turbo/");
    applyParams(ps, src);
    requireKeys(ps, src);  // after: a misspelt key is named as unknown first
    p.turbo.source = src.file;
  }
  {
    const ParamSource src = readYamlParams(resolvePath(folder, p.engine.reference_file));
    ParamSet ps;
    p.reference.declare(ps);
    applyParams(ps, src);
    requireKeys(ps, src);  // after: a misspelt key is named as unknown first
  }
  p.validate();
  return p;
}

void Engine1DParams::applyCalibration() {
  const Engine1DConfig& e = engine;
  if (e.woschni_multiplier > 0.0) cylinder.woschni.multiplier = e.woschni_multiplier;
  for (double& v : cylinder.diffusion_tail_deg) v *= e.diffusion_tail_scale;
  for (double& v : cylinder.premixed_duration_deg) v *= e.premixed_duration_scale;
  cylinder.friction.A_bar *= e.friction_scale;
  cylinder.friction.C_bar_s_m *= e.friction_scale;
  cylinder.friction.D_bar_s2_m2 *= e.friction_scale;
}

void Engine1DParams::validate() const {
  const Engine1DConfig& e = engine;
  const std::string& f = engine_source;
  if (e.solver != "fsm" && e.solver != "tvd")
    throw InputError(f, "engine_1d/solver", "must be 'fsm' or 'tvd', got '" + e.solver + "'");
  validateCylinders(e, f);
  if (e.implicit_one_cell_pipes && !e.implicit_volumes)
    throw InputError(f, "engine_1d/numerics/implicit_one_cell_pipes",
                     "needs numerics/implicit_volumes: true (the cells are solved with their volume)");
  for (const auto* v : {&e.intake_valve, &e.exhaust_valve}) {
    const std::string k = v == &e.intake_valve ? "engine_1d/valves/intake" : "engine_1d/valves/exhaust";
    if (v->ld.size() < 2 || v->cd_normal.size() != v->ld.size() || v->cd_back.size() != v->ld.size())
      throw InputError(f, k + "/cd_normal", "ld, cd_normal and cd_back need the same size >= 2");
    for (std::size_t i = 1; i < v->ld.size(); ++i)
      if (!(v->ld[i] > v->ld[i - 1])) throw InputError(f, k + "/ld", "must strictly increase");
  }
  if (e.boost_pressure_ratio.size() != e.boost_speed_rpm.size() * e.boost_load.size())
    throw InputError(f, "engine_1d/control/boost_pressure_ratio",
                     "needs speeds x loads values (row-major)");
  if (cylinder.geometry.bore_m <= 0.0)
    throw InputError(f, "cylinder/geometry/bore_m", "must be > 0");
}

}  // namespace hbt::engine_1d
