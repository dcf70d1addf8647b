// Parameters of the aftertreatment system (DOC -> DPF -> SCR -> ASC), declared once with units,
// ranges and docs (hbt::ParamSet, common/params.hpp). Values and their sources:
// config/aftertreatment.yaml. All quantities SI unless the key says otherwise (cpsi, mil, g/L).
#pragma once
#include <string>

#include "common/params.hpp"

namespace hbt::aftertreatment {

/// Geometry and thermal mass of one brick (monolith in its can).
struct BrickParams {
  double diameter_m = 0.267;         ///< substrate diameter
  double length_m = 0.15;            ///< substrate length
  double cpsi = 400.0;               ///< cell density [cells per square inch]
  double wall_thickness_mil = 4.0;   ///< substrate wall thickness [1/1000 inch]
  double wall_density_kg_m3 = 1700;  ///< apparent density of the (porous) wall material
  double wall_cp_J_kgK = 1000.0;     ///< specific heat of the wall material
  double washcoat_g_L = 100.0;       ///< washcoat load per litre of brick volume
  double washcoat_cp_J_kgK = 900.0;  ///< specific heat of the washcoat
  double can_mass_kg = 3.0;          ///< can + mat mass lumped with the substrate (same T)
  double can_cp_J_kgK = 500.0;       ///< specific heat of the can/mat lump
  int slices = 8;                    ///< axial slices (>= 5)
};

/// One lumped wall of the exhaust line (manifold, turbine housing, pipe, a chamber of the box).
struct PipeSegmentParams {
  double length_m = 1.0;               ///< gas path length
  double diameter_m = 0.1;             ///< hydraulic diameter of the gas path (Re, Nu)
  double inner_area_m2 = 0.3;          ///< wetted area of the gas path (pipe: pi D L)
  double wall_mass_kg = 5.0;           ///< wall (and flanges, shields) at one temperature
  double wall_cp_J_kgK = 500.0;        ///< wall specific heat
  double outer_area_m2 = 0.3;          ///< outer surface losing heat to the surrounding air
  double insulation_thickness_m = 0.0; ///< wrap / air gap on the outer surface (0 = bare)
  double insulation_k_W_mK = 0.06;     ///< its conductivity
  double emissivity = 0.8;             ///< outer surface (or the wrap's cover)
  double air_speed_factor = 0.0;       ///< air speed at the outer surface / vehicle speed
  bool pulsating = false;              ///< upstream of the turbine: the pulsating-flow Nusselt law
};

/// The exhaust line: walls upstream of the DOC, between DPF and SCR (mixer), after the ASC.
struct LineParams {
  PipeSegmentParams manifold, turbine_housing, downpipe, rear_pipe, box_inlet, box_mixer, box_outlet;
  double laminar_nusselt = 3.66;       ///< fully developed laminar pipe flow, T_wall const
  double pulsating_nusselt_c = 0.07;   ///< Nu = c Re^m upstream of the turbine
  double pulsating_nusselt_re_exponent = 0.75;
  double pipe_nusselt_c = 0.023;       ///< Nu = c Re^m Pr^n downstream of the turbine
  double pipe_nusselt_re_exponent = 0.8;
  double pipe_nusselt_pr_exponent = 0.3;
};

/// DPF soot: engine-out soot, filtration, NO2 oxidation (passive regeneration).
struct SootParams {
  double engine_out_g_per_kg_co2 = 0.03;     ///< engine-out soot per kg of exhaust CO2
  double filtration_efficiency = 0.99;       ///< captured / entering the DPF (mass)
  double no2_A_nm_cm3_K05_s = 2.4e-14;       ///< diameter regression rate / (T^0.5 [NO2])
  double no2_E_J_mol = 47.1e3;               ///< its activation energy
  double primary_particle_diameter_m = 25e-9;///< soot primary particle (specific surface)
  double co2_selectivity = 1.0;              ///< carbon leaving as CO2 (C + 2 NO2), rest as CO
};

struct AtsParams {
  BrickParams doc, dpf, scr, asc;
  LineParams line;
  SootParams soot;

  // Heat transfer gas -> wall and can -> ambient.
  double nusselt = 2.98;                  ///< laminar fully developed, square channel, T_w const
  double insulation_thickness_m = 0.008;  ///< mat + air gap between substrate and can
  double insulation_k_W_mK = 0.12;        ///< conductivity of the insulation
  double h_natural_W_m2K = 5.0;           ///< natural convection on the can at standstill
  double can_emissivity = 0.8;            ///< radiation from the can (linearised)
  double underbody_air_factor = 0.5;      ///< air speed at the can / vehicle speed
  double can_length_factor = 1.0;         ///< can lateral area / substrate lateral area

  // DOC kinetics: first-order, k = k_ref exp(-E/R (1/T - 1/T_ref)) [1/s per brick volume].
  double doc_co_k_ref_1_s = 10.0;
  double doc_co_T_ref_K = 473.15;
  double doc_co_E_J_mol = 90e3;
  double doc_hc_k_ref_1_s = 10.0;
  double doc_hc_T_ref_K = 503.15;
  double doc_hc_E_J_mol = 100e3;
  double doc_no_k_ref_1_s = 10.0;
  double doc_no_T_ref_K = 523.15;
  double doc_no_E_J_mol = 60e3;
  double engine_no2_fraction = 0.1;       ///< NO2/NOx (molar) at the engine outlet
  double hc_heating_value_J_kg = 43e6;    ///< lower heating value of the HC slip

  // DPF (wall flow).
  double dpf_soot_load_g_L = 2.0;          ///< soot per litre of filter at t = 0
  double dpf_wall_permeability_m2 = 5e-13; ///< clean wall
  double dpf_soot_permeability_m2 = 2e-14; ///< soot cake
  double dpf_soot_cake_density_kg_m3 = 100.0;

  // SCR: NH3 storage (Temkin) and reactions (Eley-Rideal with stored NH3).
  double scr_site_density_mol_m3 = 150.0;  ///< Omega: NH3 sites per m^3 of brick
  double scr_k_ads_m3_mol_s = 2.0;         ///< adsorption (non-activated)
  double scr_k_des_1_s = 2.9e7;            ///< desorption pre-exponential
  double scr_E_des_J_mol = 110e3;          ///< desorption energy at zero coverage
  double scr_temkin_alpha = 0.3;           ///< E_des(theta) = E_des (1 - alpha theta)
  double scr_k_std_ref_m3_mol_s = 0.47;    ///< standard SCR at T_ref
  double scr_E_std_J_mol = 85e3;
  double scr_k_fast_ref_m6_mol2_s = 1500.0;///< fast SCR at T_ref
  double scr_E_fast_J_mol = 70e3;
  double scr_k_no2_ref_m3_mol_s = 0.2;    ///< NO2 SCR at T_ref
  double scr_E_no2_J_mol = 90e3;
  double scr_k_ox_ref_1_s = 0.1;           ///< NH3 oxidation at T_ox_ref
  double scr_E_ox_J_mol = 160e3;
  double scr_T_ref_K = 523.15;
  double scr_T_ox_ref_K = 723.15;
  double scr_initial_coverage = 0.0;       ///< theta at t = 0 (cold start: empty)

  // Urea dosing.
  double dosing_release_T_K = 473.15;      ///< dosing allowed above this SCR inlet T
  double dosing_anr = 1.0;                 ///< NH3/NOx molar ratio while storage not full
  double dosing_fill_start = 0.8;          ///< stored / target at which ANR starts to drop
  double dosing_fill_stop = 1.0;           ///< stored / target at which dosing stops
  double dosing_ref_nh3_ppm = 100.0;       ///< NH3 level defining the storage target
  double adblue_urea_mass_fraction = 0.325;
  double adblue_heat_J_kg = 2.3e6;         ///< evaporation + thermolysis/hydrolysis per kg AdBlue

  // ASC (NH3 -> N2).
  double asc_k_ref_1_s = 10.0;
  double asc_T_ref_K = 523.15;
  double asc_E_J_mol = 90e3;

  // Pressure drop.
  double contraction_k = 0.5;              ///< inlet loss coefficient of the channels
  double muffler_k = 5.0;                  ///< muffler + tailpipe losses in pipe dynamic heads
  double pipe_diameter_m = 0.127;          ///< exhaust pipe diameter (5")

  // Light-off detection.
  double lightoff_filter_s = 5.0;          ///< low-pass time constant of NOx flows
  double lightoff_conversion = 0.5;        ///< SCR conversion defining light-off
  double lightoff_min_nox_kg_s = 1e-6;     ///< no decision below this inflowing NOx

  // Warm start (launch argument start:=warm): a one-box mid-shift.
  double warm_brick_T_K = 523.15;          ///< every brick (substrate, washcoat, can) [K]
  double warm_nh3_fill = 0.9;              ///< SCR NH3 store / the dosing's storage target [-]

  // Numerics (explicit Runge-Kutta 5(4) for the NH3 storage).
  double rtol = 1e-8;
  double atol_theta = 1e-10;
  int max_steps = 5000;

  void declare(ParamSet& ps);
  /// Cross-checks beyond the per-key ranges; throws InputError naming file and key.
  void validate(const std::string& file = "(aftertreatment parameters)") const;
};

}  // namespace hbt::aftertreatment
