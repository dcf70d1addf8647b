#include "aftertreatment/ats_params.hpp"

#include <cmath>

#include "common/errors.hpp"

namespace hbt::aftertreatment {

namespace {
void declareBrick(ParamSet& ps, const std::string& name, BrickParams& b) {
  ps.setPrefix(name + "/");
  ps.add("diameter_m", b.diameter_m, "m", 0.05, 0.6, "substrate diameter");
  ps.add("length_m", b.length_m, "m", 0.02, 0.8, "substrate length");
  ps.add("cpsi", b.cpsi, "1/in^2", 50.0, 1200.0, "cell density");
  ps.add("wall_thickness_mil", b.wall_thickness_mil, "mil", 1.0, 30.0, "wall thickness (1 mil = 25.4 um)");
  ps.add("wall_density_kg_m3", b.wall_density_kg_m3, "kg/m^3", 300.0, 8000.0, "apparent wall density");
  ps.add("wall_cp_J_kgK", b.wall_cp_J_kgK, "J/(kg K)", 300.0, 2000.0, "wall specific heat");
  ps.add("washcoat_g_L", b.washcoat_g_L, "g/L", 0.0, 400.0, "washcoat load per brick volume");
  ps.add("washcoat_cp_J_kgK", b.washcoat_cp_J_kgK, "J/(kg K)", 300.0, 2000.0, "washcoat specific heat");
  ps.add("can_mass_kg", b.can_mass_kg, "kg", 0.0, 50.0, "can + mat mass lumped with the wall");
  ps.add("can_cp_J_kgK", b.can_cp_J_kgK, "J/(kg K)", 300.0, 2000.0, "can/mat specific heat");
  ps.add("slices", b.slices, "-", 5, 50, "axial slices");
}
void declareSegment(ParamSet& ps, const std::string& name, PipeSegmentParams& s) {
  ps.setPrefix("line/" + name + "/");
  ps.add("length_m", s.length_m, "m", 0.01, 10.0, "gas path length");
  ps.add("diameter_m", s.diameter_m, "m", 0.01, 1.0, "hydraulic diameter of the gas path");
  ps.add("inner_area_m2", s.inner_area_m2, "m^2", 0.001, 10.0, "wetted area of the gas path");
  ps.add("wall_mass_kg", s.wall_mass_kg, "kg", 0.01, 200.0, "wall mass at one temperature");
  ps.add("wall_cp_J_kgK", s.wall_cp_J_kgK, "J/(kg K)", 300.0, 2000.0, "wall specific heat");
  ps.add("outer_area_m2", s.outer_area_m2, "m^2", 0.0, 10.0, "outer surface losing heat");
  ps.add("insulation_thickness_m", s.insulation_thickness_m, "m", 0.0, 0.1, "wrap / air gap (0 = bare)");
  ps.add("insulation_k_W_mK", s.insulation_k_W_mK, "W/(m K)", 0.01, 5.0, "wrap conductivity");
  ps.add("emissivity", s.emissivity, "-", 0.0, 1.0, "outer surface emissivity");
  ps.add("air_speed_factor", s.air_speed_factor, "-", 0.0, 1.5, "air speed at the surface / vehicle speed");
  ps.add("pulsating", s.pulsating, "upstream of the turbine: pulsating-flow Nusselt law");
}

void declareLine(ParamSet& ps, LineParams& l) {
  declareSegment(ps, "manifold", l.manifold);
  declareSegment(ps, "turbine_housing", l.turbine_housing);
  declareSegment(ps, "downpipe", l.downpipe);
  declareSegment(ps, "rear_pipe", l.rear_pipe);
  declareSegment(ps, "box_inlet", l.box_inlet);
  declareSegment(ps, "box_mixer", l.box_mixer);
  declareSegment(ps, "box_outlet", l.box_outlet);
  ps.setPrefix("line/");
  ps.add("laminar_nusselt", l.laminar_nusselt, "-", 1.0, 10.0, "laminar pipe flow (the lower bound)");
  ps.add("pulsating_nusselt_c", l.pulsating_nusselt_c, "-", 0.0, 1.0, "Nu = c Re^m, pulsating flow");
  ps.add("pulsating_nusselt_re_exponent", l.pulsating_nusselt_re_exponent, "-", 0.3, 1.0, "m");
  ps.add("pipe_nusselt_c", l.pipe_nusselt_c, "-", 0.0, 1.0, "Nu = c Re^m Pr^n, steady pipe flow");
  ps.add("pipe_nusselt_re_exponent", l.pipe_nusselt_re_exponent, "-", 0.3, 1.0, "m");
  ps.add("pipe_nusselt_pr_exponent", l.pipe_nusselt_pr_exponent, "-", 0.0, 1.0, "n");
}

void declareSoot(ParamSet& ps, SootParams& s) {
  ps.setPrefix("soot/");
  ps.add("engine_out_g_per_kg_co2", s.engine_out_g_per_kg_co2, "g/kg", 0.0, 10.0, "engine-out soot per kg CO2");
  ps.add("filtration_efficiency", s.filtration_efficiency, "-", 0.0, 1.0, "DPF mass filtration efficiency");
  ps.add("no2_A_nm_cm3_K05_s", s.no2_A_nm_cm3_K05_s, "nm cm^3/(K^0.5 s)", 0.0, 1e-9,
         "NO2 soot oxidation: diameter regression / (T^0.5 [NO2 molecules/cm^3])");
  ps.add("no2_E_J_mol", s.no2_E_J_mol, "J/mol", 0.0, 3e5, "NO2 soot oxidation activation energy");
  ps.add("primary_particle_diameter_m", s.primary_particle_diameter_m, "m", 1e-9, 1e-6, "soot primary particle");
  ps.add("co2_selectivity", s.co2_selectivity, "-", 0.0, 1.0, "carbon to CO2 (C + 2 NO2); the rest to CO (C + NO2)");
}
}  // namespace

void AtsParams::declare(ParamSet& ps) {
  declareBrick(ps, "doc", doc);
  declareBrick(ps, "dpf", dpf);
  declareBrick(ps, "scr", scr);
  declareBrick(ps, "asc", asc);
  declareLine(ps, line);
  declareSoot(ps, soot);

  ps.setPrefix("heat/");
  ps.add("nusselt", nusselt, "-", 1.0, 10.0, "channel Nusselt number (laminar)");
  ps.add("insulation_thickness_m", insulation_thickness_m, "m", 0.0, 0.05, "mat thickness");
  ps.add("insulation_k_W_mK", insulation_k_W_mK, "W/(m K)", 0.01, 5.0, "mat conductivity");
  ps.add("h_natural_W_m2K", h_natural_W_m2K, "W/(m^2 K)", 0.0, 50.0, "natural convection");
  ps.add("can_emissivity", can_emissivity, "-", 0.0, 1.0, "can emissivity");
  ps.add("underbody_air_factor", underbody_air_factor, "-", 0.0, 1.5, "air speed at the can / vehicle speed");
  ps.add("can_length_factor", can_length_factor, "-", 1.0, 3.0, "can lateral area / substrate lateral area");

  ps.setPrefix("doc_kinetics/");
  ps.add("co_k_ref_1_s", doc_co_k_ref_1_s, "1/s", 0.0, 1e4, "CO oxidation rate constant at co_T_ref");
  ps.add("co_T_ref_K", doc_co_T_ref_K, "K", 300.0, 900.0, "");
  ps.add("co_E_J_mol", doc_co_E_J_mol, "J/mol", 0.0, 3e5, "CO activation energy");
  ps.add("hc_k_ref_1_s", doc_hc_k_ref_1_s, "1/s", 0.0, 1e4, "HC oxidation rate constant at hc_T_ref");
  ps.add("hc_T_ref_K", doc_hc_T_ref_K, "K", 300.0, 900.0, "");
  ps.add("hc_E_J_mol", doc_hc_E_J_mol, "J/mol", 0.0, 3e5, "HC activation energy");
  ps.add("no_k_ref_1_s", doc_no_k_ref_1_s, "1/s", 0.0, 1e4, "NO oxidation rate constant at no_T_ref");
  ps.add("no_T_ref_K", doc_no_T_ref_K, "K", 300.0, 900.0, "");
  ps.add("no_E_J_mol", doc_no_E_J_mol, "J/mol", 0.0, 3e5, "NO oxidation activation energy");
  ps.add("engine_no2_fraction", engine_no2_fraction, "-", 0.0, 0.9, "NO2/NOx at the engine outlet");
  ps.add("hc_heating_value_J_kg", hc_heating_value_J_kg, "J/kg", 1e7, 6e7, "HC lower heating value");

  ps.setPrefix("dpf_flow/");
  ps.add("soot_load_g_L", dpf_soot_load_g_L, "g/L", 0.0, 10.0, "soot per litre of filter at t = 0");
  ps.add("wall_permeability_m2", dpf_wall_permeability_m2, "m^2", 1e-15, 1e-10, "clean wall");
  ps.add("soot_permeability_m2", dpf_soot_permeability_m2, "m^2", 1e-17, 1e-11, "soot cake");
  ps.add("soot_cake_density_kg_m3", dpf_soot_cake_density_kg_m3, "kg/m^3", 20.0, 1000.0, "soot cake packing density");

  ps.setPrefix("scr_kinetics/");
  ps.add("site_density_mol_m3", scr_site_density_mol_m3, "mol/m^3", 1.0, 2000.0, "Omega, NH3 sites per brick volume");
  ps.add("k_ads_m3_mol_s", scr_k_ads_m3_mol_s, "m^3/(mol s)", 0.0, 1e3, "adsorption");
  ps.add("k_des_1_s", scr_k_des_1_s, "1/s", 0.0, 1e14, "desorption pre-exponential");
  ps.add("E_des_J_mol", scr_E_des_J_mol, "J/mol", 1e4, 3e5, "desorption energy at theta = 0");
  ps.add("temkin_alpha", scr_temkin_alpha, "-", 0.0, 0.99, "Temkin coverage dependence");
  ps.add("k_std_ref_m3_mol_s", scr_k_std_ref_m3_mol_s, "m^3/(mol s)", 0.0, 1e4, "standard SCR at T_ref");
  ps.add("E_std_J_mol", scr_E_std_J_mol, "J/mol", 0.0, 3e5, "standard SCR activation energy");
  ps.add("k_fast_ref_m6_mol2_s", scr_k_fast_ref_m6_mol2_s, "m^6/(mol^2 s)", 0.0, 1e7, "fast SCR at T_ref");
  ps.add("E_fast_J_mol", scr_E_fast_J_mol, "J/mol", 0.0, 3e5, "fast SCR activation energy");
  ps.add("k_no2_ref_m3_mol_s", scr_k_no2_ref_m3_mol_s, "m^3/(mol s)", 0.0, 1e4, "NO2 SCR at T_ref");
  ps.add("E_no2_J_mol", scr_E_no2_J_mol, "J/mol", 0.0, 3e5, "NO2 SCR activation energy");
  ps.add("k_ox_ref_1_s", scr_k_ox_ref_1_s, "1/s", 0.0, 1e4, "NH3 oxidation at T_ox_ref");
  ps.add("E_ox_J_mol", scr_E_ox_J_mol, "J/mol", 0.0, 3e5, "NH3 oxidation activation energy");
  ps.add("T_ref_K", scr_T_ref_K, "K", 300.0, 900.0, "reference T of the SCR rate constants");
  ps.add("T_ox_ref_K", scr_T_ox_ref_K, "K", 300.0, 1000.0, "reference T of NH3 oxidation");
  ps.add("initial_coverage", scr_initial_coverage, "-", 0.0, 1.0, "NH3 coverage at t = 0");

  ps.setPrefix("dosing/");
  ps.add("release_T_K", dosing_release_T_K, "K", 400.0, 600.0, "no dosing below this SCR inlet gas T");
  ps.add("anr", dosing_anr, "-", 0.0, 2.0, "NH3/NOx molar feed ratio");
  ps.add("fill_start", dosing_fill_start, "-", 0.0, 2.0, "stored/target at which the ANR starts to drop");
  ps.add("fill_stop", dosing_fill_stop, "-", 0.0, 2.0, "stored/target at which dosing stops");
  ps.add("ref_nh3_ppm", dosing_ref_nh3_ppm, "ppm", 1.0, 2000.0, "gas NH3 defining the storage target");
  ps.add("adblue_urea_mass_fraction", adblue_urea_mass_fraction, "-", 0.1, 1.0, "urea in AdBlue (ISO 22241)");
  ps.add("adblue_heat_J_kg", adblue_heat_J_kg, "J/kg", 0.0, 5e6, "heat taken from the gas per kg AdBlue");

  ps.setPrefix("asc_kinetics/");
  ps.add("k_ref_1_s", asc_k_ref_1_s, "1/s", 0.0, 1e4, "NH3 oxidation on the ASC at T_ref");
  ps.add("T_ref_K", asc_T_ref_K, "K", 300.0, 900.0, "");
  ps.add("E_J_mol", asc_E_J_mol, "J/mol", 0.0, 3e5, "activation energy");

  ps.setPrefix("pressure/");
  ps.add("contraction_k", contraction_k, "-", 0.0, 2.0, "channel inlet loss coefficient");
  ps.add("muffler_k", muffler_k, "-", 0.0, 50.0, "muffler + tailpipe loss coefficient (pipe head)");
  ps.add("pipe_diameter_m", pipe_diameter_m, "m", 0.03, 0.3, "exhaust pipe diameter");

  ps.setPrefix("lightoff/");
  ps.add("filter_s", lightoff_filter_s, "s", 0.0, 100.0, "low-pass of the NOx flows");
  ps.add("conversion", lightoff_conversion, "-", 0.05, 0.99, "SCR conversion defining light-off");
  ps.add("min_nox_kg_s", lightoff_min_nox_kg_s, "kg/s", 0.0, 1e-3, "no decision below this NOx inflow");

  ps.setPrefix("warm_start/");
  ps.add("brick_K", warm_brick_T_K, "K", 300.0, 900.0, "start:=warm: every brick");
  ps.add("nh3_fill_of_target", warm_nh3_fill, "-", 0.0, 1.5, "start:=warm: SCR NH3 store / dosing target");

  ps.setPrefix("numerics/");
  ps.add("rtol", rtol, "-", 1e-12, 1e-3, "relative tolerance of the SCR coverages (Runge-Kutta 5(4))");
  ps.add("atol_theta", atol_theta, "-", 1e-15, 1e-4, "absolute tolerance of the SCR coverages");
  ps.add("max_steps", max_steps, "-", 10, 1000000, "Runge-Kutta steps per model step (at most)");
  ps.setPrefix("");
}

void AtsParams::validate(const std::string& file) const {
  const BrickParams* b[4] = {&doc, &dpf, &scr, &asc};
  const char* n[4] = {"doc", "dpf", "scr", "asc"};
  for (int i = 0; i < 4; ++i) {
    const double pitch = 0.0254 / std::sqrt(b[i]->cpsi);
    if (b[i]->wall_thickness_mil * 25.4e-6 >= 0.8 * pitch)
      throw InputError(file, std::string(n[i]) + "/wall_thickness_mil",
                       "wall thicker than 80 % of the cell pitch");
  }
  if (dosing_fill_stop <= dosing_fill_start)
    throw InputError(file, "dosing/fill_stop", "must be larger than dosing/fill_start");
}

}  // namespace hbt::aftertreatment
