#include "cylinder/cylinder_params.hpp"

#include <algorithm>

#include "common/errors.hpp"

namespace hbt::cylinder {

CylinderParams::CylinderParams() {
  // Rows: 600, 1000, 1400, 1800, 2200 rpm; columns: load 0, 0.25, 0.5, 0.75, 1.
  soi_main_deg = {-1, -2, -3, -3, -3,  -2, -3, -4, -4, -4,  -3, -4, -5, -6, -6,
                  -4, -5, -6, -7, -8,  -5, -6, -8, -9, -10};
  rail_pressure_bar = {500, 600, 750,  900,  1000, 600, 800,  1000, 1300, 1500,
                       700, 1000, 1300, 1600, 1800, 800, 1100, 1500, 1800, 2000,
                       900, 1200, 1600, 1900, 2200};
  pilot_fraction = {0.15, 0.06, 0.03, 0.02, 0.015, 0.15, 0.06, 0.03, 0.02, 0.015,
                    0.15, 0.06, 0.03, 0.02, 0.015, 0.15, 0.06, 0.03, 0.02, 0.015,
                    0.15, 0.06, 0.03, 0.02, 0.015};
  pilot_dwell_deg = {8, 8, 8, 8, 8,  10, 10, 10, 10, 10,  12, 12, 12, 12, 12,
                     14, 14, 14, 14, 14,  16, 16, 16, 16, 16};
  post_fraction.assign(25, 0.0);
  post_offset_deg.assign(25, 25.0);
  premixed_duration_deg = {6, 6, 6, 6, 6,  7, 7, 7, 7, 7,  8, 8, 8, 8, 8,
                           9, 9, 9, 9, 9,  10, 10, 10, 10, 10};
  premixed_m.assign(25, 2.0);
  diffusion_tail_deg = {25, 28, 30, 32, 35,  28, 31, 34, 37, 40,  30, 34, 38, 42, 45,
                        32, 36, 41, 45, 48,  35, 40, 45, 48, 50};
  diffusion_m.assign(25, 1.0);
}

void CylinderParams::declare(ParamSet& ps) {
  ps.setPrefix("cylinder/geometry/");
  ps.add("bore_m", geometry.bore_m, "m", 0.05, 0.3, "cylinder bore");
  ps.add("stroke_m", geometry.stroke_m, "m", 0.05, 0.4, "piston stroke");
  ps.add("rod_m", geometry.rod_m, "m", 0.05, 0.8, "connecting-rod length");
  ps.add("compression_ratio", geometry.compression_ratio, "-", 8.0, 25.0, "geometric CR");
  ps.add("head_area_factor", geometry.head_area_factor, "-", 1.0, 2.0, "fire deck / piston area");
  ps.add("piston_area_factor", geometry.piston_area_factor, "-", 1.0, 3.0, "crown incl. bowl / piston area");
  ps.add("top_land_height_m", geometry.top_land_height_m, "m", 0.0, 0.02, "liner exposed at TDC");
  ps.setPrefix("cylinder/valve_events/");
  ps.add("ivo_deg", ivo_deg, "deg", -360.0, 720.0, "inlet valve opening (firing TDC = 0)");
  ps.add("ivc_deg", ivc_deg, "deg", -360.0, 0.0, "inlet valve closing");
  ps.add("evo_deg", evo_deg, "deg", 0.0, 360.0, "exhaust valve opening");
  ps.add("evc_deg", evc_deg, "deg", 0.0, 720.0, "exhaust valve closing");
  ps.setPrefix("cylinder/fuel/");
  ps.add("n_C", fuel.nC, "-", 1.0, 30.0, "carbon atoms of the surrogate C_nC H_nH");
  ps.add("n_H", fuel.nH, "-", 1.0, 60.0, "hydrogen atoms of the surrogate");
  ps.add("lhv_J_kg", fuel.lhv_J_kg, "J/kg", 38e6, 46e6, "lower heating value (liquid)");
  ps.add("hfg_J_kg", fuel.hfg_J_kg, "J/kg", 0.0, 0.6e6, "latent heat of vaporisation");
  ps.add("temperature_K", fuel_temperature_K, "K", 250.0, 450.0, "injected fuel temperature");
  ps.add("cetane_number", cetane_number, "-", 30.0, 80.0, "cetane number (ignition delay)");
  ps.setPrefix("cylinder/thermo/");
  ps.add("constant_cp", constant_cp, "freeze cp of every group (test option only)");
  ps.add("constant_cp_T_K", constant_cp_T_K, "K", 200.0, 3000.0, "temperature of the frozen cp");
  ps.setPrefix("cylinder/injection/");
  ps.add("nozzle_holes", nozzle.holes, "-", 1, 20, "injector nozzle holes");
  ps.add("nozzle_hole_diameter_m", nozzle.hole_diameter_m, "m", 0.05e-3, 0.5e-3, "hole diameter");
  ps.add("nozzle_discharge_coeff", nozzle.discharge_coeff, "-", 0.3, 1.0, "hole discharge coefficient");
  ps.add("fuel_density_kg_m3", nozzle.fuel_density_kg_m3, "kg/m^3", 700.0, 900.0, "liquid fuel density");
  ps.add("fuel_ref_kg", fuel_ref_kg, "kg", 10e-6, 1e-3, "full-load fuel per cylinder-cycle (load = 1)");
  ps.add("speed_axis_rpm", speed_axis_rpm, "rpm", 0.0, 5000.0, "map speed axis");
  ps.add("load_axis", load_axis, "-", 0.0, 2.0, "map load axis (fuel / fuel_ref)");
  ps.add("soi_main_deg", soi_main_deg, "deg", -40.0, 20.0, "main start of injection map");
  ps.add("rail_pressure_bar", rail_pressure_bar, "bar", 100.0, 3000.0, "rail pressure map");
  ps.add("pilot_fraction", pilot_fraction, "-", 0.0, 0.5, "pilot mass fraction map");
  ps.add("pilot_dwell_deg", pilot_dwell_deg, "deg", 0.0, 40.0, "pilot SOI before main SOI");
  ps.add("post_fraction", post_fraction, "-", 0.0, 0.5, "post mass fraction map");
  ps.add("post_offset_deg", post_offset_deg, "deg", 0.0, 90.0, "post SOI after main SOI");
  ps.setPrefix("cylinder/combustion/");
  ps.add("ignition_delay_multiplier", ignition_delay_multiplier, "-", 0.2, 5.0, "factor on Hardenberg-Hase");
  ps.add("wiebe_a", wiebe_a, "-", 1.0, 20.0, "Wiebe efficiency parameter a");
  ps.add("premixed_duration_deg", premixed_duration_deg, "deg", 1.0, 60.0, "premixed Wiebe duration map");
  ps.add("premixed_m", premixed_m, "-", 0.0, 6.0, "premixed Wiebe shape map");
  ps.add("diffusion_tail_deg", diffusion_tail_deg, "deg", 1.0, 150.0, "diffusive duration beyond injection");
  ps.add("diffusion_m", diffusion_m, "-", 0.0, 6.0, "diffusive Wiebe shape map");
  ps.add("diffusion_injection_factor", diffusion_injection_factor, "-", 0.0, 3.0, "weight of injection duration");
  ps.add("flame_lambda", flame_lambda, "-", 1.0, 3.0, "air excess of the burned zone");
  ps.setPrefix("cylinder/heat_transfer/");
  ps.add("correlation", heat_transfer_correlation, "woschni | hohenberg");
  ps.add("hohenberg_C", woschni.hohenberg_C, "-", 10.0, 1000.0, "Hohenberg constant C_H (130)");
  ps.add("woschni_C0", woschni.C0, "-", 0.5, 10.0, "Woschni constant (3.26)");
  ps.add("swirl_ratio", woschni.swirl_ratio, "-", 0.0, 5.0, "swirl ratio for C1");
  ps.add("woschni_C2_m_sK", woschni.C2_m_sK, "m/(s K)", 0.0, 0.02, "combustion term C2");
  ps.add("multiplier", woschni.multiplier, "-", 0.0, 5.0, "calibration factor on h");
  ps.add("head_dT0_K", walls.head_dT0_K, "K", 0.0, 400.0, "head above coolant at no load");
  ps.add("head_dTload_K", walls.head_dTload_K, "K", 0.0, 400.0, "head rise at load 1");
  ps.add("liner_dT0_K", walls.liner_dT0_K, "K", 0.0, 400.0, "liner above coolant at no load");
  ps.add("liner_dTload_K", walls.liner_dTload_K, "K", 0.0, 400.0, "liner rise at load 1");
  ps.add("piston_dT0_K", walls.piston_dT0_K, "K", 0.0, 500.0, "piston above coolant at no load");
  ps.add("piston_dTload_K", walls.piston_dTload_K, "K", 0.0, 500.0, "piston rise at load 1");
  ps.setPrefix("cylinder/friction/");
  ps.add("A_bar", friction.A_bar, "bar", 0.0, 3.0, "Chen-Flynn constant term");
  ps.add("B", friction.B, "-", 0.0, 0.05, "Chen-Flynn peak-pressure term");
  ps.add("C_bar_s_m", friction.C_bar_s_m, "bar s/m", 0.0, 1.0, "Chen-Flynn piston-speed term");
  ps.add("D_bar_s2_m2", friction.D_bar_s2_m2, "bar s^2/m^2", 0.0, 0.1, "Chen-Flynn quadratic term");
  ps.add("visc_exponent", friction.visc_exponent, "-", 0.0, 1.0, "exponent on viscosity ratio");
  ps.add("vogel_b_K", friction.vogel_b_K, "K", 300.0, 3000.0, "Vogel viscosity b");
  ps.add("vogel_c_K", friction.vogel_c_K, "K", 50.0, 250.0, "Vogel viscosity c");
  ps.add("T_oil_ref_K", friction.T_oil_ref_K, "K", 300.0, 420.0, "oil temperature of the fit");
  ps.add("oil_minus_coolant_K", friction.oil_minus_coolant_K, "K", -20.0, 40.0, "oil above coolant");
  ps.setPrefix("cylinder/nox/");
  ps.add("enabled", nox_enabled, "integrate Zeldovich NO in the burned zone");
  ps.add("interval_deg", nox_interval_deg, "deg", 0.1, 20.0, "CVODE interval");
  ps.add("min_temperature_K", nox_min_temperature_K, "K", 1000.0, 2500.0, "NO frozen below");
  ps.add("dissociation", nox_dissociation,
         "NO kinetics at the equilibrium (dissociated) burned-zone temperature");
  ps.add("model", nox_model, "hot_zone | burned_zone: where the NO forms");
  ps.add("hot_zone_residence_s", nox_hot_zone_residence_s, "s", 0.0, 0.02,
         "residence time in the stoichiometric hot zone (WHTC calibration constant)");
  ps.setPrefix("cylinder/numerics/");
  ps.add("max_substep_deg", max_substep_deg, "deg", 0.01, 5.0, "largest internal step");
  ps.setPrefix("");
}

void CylinderParams::finalize(const std::string& file) {
  const std::string k = "cylinder/injection/";
  const std::string c = "cylinder/combustion/";
  auto mk = [&](const std::vector<double>& v, const std::string& key) {
    return Table2D(speed_axis_rpm, load_axis, v, file, key);
  };
  soi_main = mk(soi_main_deg, k + "soi_main_deg");
  rail_pressure = mk(rail_pressure_bar, k + "rail_pressure_bar");
  pilot_frac = mk(pilot_fraction, k + "pilot_fraction");
  pilot_dwell = mk(pilot_dwell_deg, k + "pilot_dwell_deg");
  post_frac = mk(post_fraction, k + "post_fraction");
  post_offset = mk(post_offset_deg, k + "post_offset_deg");
  premix_dur = mk(premixed_duration_deg, c + "premixed_duration_deg");
  premix_m = mk(premixed_m, c + "premixed_m");
  diff_tail = mk(diffusion_tail_deg, c + "diffusion_tail_deg");
  diff_m = mk(diffusion_m, c + "diffusion_m");
  if (heat_transfer_correlation == "woschni")
    woschni.hohenberg = false;
  else if (heat_transfer_correlation == "hohenberg")
    woschni.hohenberg = true;
  else
    throw InputError(file, "cylinder/heat_transfer/correlation",
                     "'" + heat_transfer_correlation + "' is not one of woschni, hohenberg");
  if (nox_model == "hot_zone")
    nox_hot_zone = true;
  else if (nox_model == "burned_zone")
    nox_hot_zone = false;
  else
    throw InputError(file, "cylinder/nox/model",
                     "'" + nox_model + "' is not one of hot_zone, burned_zone");
  if (!(ivc_deg < 0.0 && evo_deg > 0.0 && evo_deg - ivc_deg < 360.0))
    throw InputError(file, "cylinder/valve_events/ivc_deg", "need IVC < 0 < EVO within 360 deg");
}

}  // namespace hbt::cylinder
