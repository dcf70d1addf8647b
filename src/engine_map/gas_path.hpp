// Quasi-steady air path, exhaust state and energy split of the map-based engine.
//
// Diesel fuel CH_y (y = H/C molar ratio) burnt lean (λ >= 1), dry air = O2 + 3.773 N2*
// (N2* = atmospheric nitrogen incl. argon, M = 28.155 g/mol so that M_air = 28.96 g/mol):
//
//   CH_y + λ(1 + y/4)(O2 + 3.773 N2*) -> CO2 + (y/2) H2O + (λ-1)(1 + y/4) O2 + 3.773 λ(1 + y/4) N2*
//   AFR_st = (1 + y/4)(M_O2 + 3.773 M_N2*) / (M_C + y M_H)                 [kg air / kg fuel]
//
// Air path (turbocharged, air-to-air intercooled; quasi-steady, no turbo lag -- the torque
// build-up lag of the engine model stands for it):
//   PR   = 1 + (PR_max - 1) · clamp(ṁ_f / ṁ_f,ref, 0, 1)^β   boost ∝ exhaust energy ∝ fuel flow
//   T_co = T_amb (1 + (PR^((γ-1)/γ) - 1)/η_c)                  compressor outlet [K]
//   T_im = T_co - ε_ic (T_co - T_amb)                           intercooler, ambient cold side
//   ṁ_a  = η_v · (PR p_amb / (R T_im)) · V_d · ω/(4π)           4-stroke swallowing [kg/s]
//   λ    = ṁ_a / (AFR_st ṁ_f)
//
// Energy balance over the control volume air-filter inlet -> turbine outlet, enthalpies
// relative to ambient temperature, fuel at ambient (LHV = lower heating value of diesel,
// units::kDieselLhv_J_kg: the one definition the ledger and the EMS use too) [W]:
//   ṁ_f LHV = P_b + Q_cool + Q_misc + Q_ic + ṁ_exh c_p,exh (T_exh - T_amb)
//   P_b    = T_b ω                                      brake power
//   Q_cool = max(f_cool(x) ṁ_f LHV + P_f,cold, P_f)     heat into the engine (metal + oil;
//            f_cool linear in load fraction x = T_b/T_fl between the light-load and the
//            full-load fraction of a warm engine's measured balance, which holds its warm
//            friction; P_f = mechanical friction work rate, warm + cold-oil extra; P_f,cold =
//            the cold-oil extra ΔT_fric ω, which the cold engine dissipates as heat instead of
//            delivering it as brake work). Motoring (no fuel): Q_cool = P_f, the rest of the
//            motoring work (pumping) heats the gas. Split (common/friction_heat.hpp):
//            Q_oil = f_o P_f, Q_metal = Q_cool - Q_oil (wall heat Q_cool - P_f >= 0)
//   Q_misc = f_misc ṁ_f LHV                             oil cooler / radiation / convection
//   Q_ic   = ṁ_a c_p,a (T_co - T_im)                     heat removed by the intercooler
// which gives the turbine-outlet (aftertreatment-inlet) temperature T_exh.
// Engine-out NOx: emission-index estimate ṁ_NOx = EI_NOx · ṁ_f (as NO2 mass).
#pragma once
#include "common/units.hpp"

namespace hbt::engine_map {

// Air-fuel equivalence ratio [-] reported without fuel (no combustion: the gas is air).
constexpr double kLambdaNoFuel = 1e9;
// lambda [-] at and above which leanProducts() gives air (no fuel).
constexpr double kLambdaAirOnly = 1e8;

struct GasPathParams {
  double displacement_m3 = 6.72e-3;            // swept volume V_d [m^3] (SPEC §3: 6.72 l)
  double volumetric_efficiency = 0.90;         // η_v [-] referred to intake-manifold density
  double boost_pressure_ratio_max = 2.4;       // PR at ṁ_f >= ṁ_f,ref [-]
  double boost_fuel_exponent = 0.6;            // β [-]
  double compressor_efficiency = 0.72;         // η_c isentropic [-]
  double intercooler_effectiveness = 0.85;     // ε_ic [-]
  double coolant_fraction_light_load = 0.30;   // f_cool at x = 0 [-] of fuel power
  double coolant_fraction_full_load = 0.20;    // f_cool at x = 1 [-] of fuel power
  double friction_heat_to_oil_fraction = 0.5; // f_o [-] of the friction work (common/friction_heat.hpp)
  double misc_heat_fraction = 0.03;            // f_misc [-] of fuel power
  double exhaust_cp_J_kgK = 1100.0;            // c_p,exh [J/(kg K)] lean exhaust 400-800 K
  double air_cp_J_kgK = 1005.0;                // c_p,a [J/(kg K)]
  double air_gamma = 1.4;                      // γ [-]
  double air_R_J_kgK = 287.05;                 // R [J/(kg K)]
  double fuel_h_to_c_molar = 1.86;             // y [-] (EN 590 diesel ≈ 1.8-1.9)
  double nox_emission_index_kg_per_kg = 0.024; // EI_NOx [kg NO2 / kg fuel]
};

struct ExhaustComposition {
  double y_O2 = 0.0, y_CO2 = 0.0, y_H2O = 0.0, y_N2 = 0.0;  // mass fractions [-], Σ = 1
};

struct GasPathState {
  double pressure_ratio = 1.0;           // boost PR [-]
  double boost_pressure_Pa = 0.0;        // intake-manifold pressure [Pa]
  double compressor_out_T_K = 0.0;       // [K]
  double intake_manifold_T_K = 0.0;      // [K]
  double air_mass_flow_kg_s = 0.0;       // [kg/s]
  double lambda = kLambdaNoFuel;         // air-fuel equivalence ratio [-]
  double exhaust_mass_flow_kg_s = 0.0;   // air + fuel [kg/s]
  double exhaust_T_K = 0.0;              // turbine-outlet temperature [K]
  double fuel_power_W = 0.0;             // ṁ_f LHV [W]
  double brake_power_W = 0.0;            // [W]
  double coolant_heat_W = 0.0;           // Q_cool [W]: all heat into the engine (metal + oil)
  double friction_W = 0.0;               // P_f: mechanical friction work rate [W]
  double metal_heat_W = 0.0;             // Q_metal: into the metal (wall heat + ring/skirt friction) [W]
  double oil_heat_W = 0.0;               // Q_oil: into the oil (bearing and valve-train friction) [W]
  double misc_heat_W = 0.0;              // Q_misc [W]
  double intercooler_heat_W = 0.0;       // Q_ic [W]
  double exhaust_enthalpy_W = 0.0;       // ṁ_exh c_p (T_exh - T_amb) [W]
  double nox_mass_flow_kg_s = 0.0;       // [kg/s] as NO2
  ExhaustComposition comp;
};

/// Stoichiometric air-fuel ratio [kg/kg] of CH_y.
double stoichiometricAfr(double h_to_c_molar);
/// Lean products (λ >= 1; λ < 1 is clamped to 1, an over-fuelled point of the crude air path).
ExhaustComposition leanProducts(double lambda, double h_to_c_molar);

/// Quasi-steady gas path at engine speed ω [rad/s], brake torque [Nm], load fraction
/// x = T_b/T_fl [-], fuel flow [kg/s], reference (rated) fuel flow [kg/s], ambient T [K], p [Pa],
/// mechanical friction work rate P_f [W] and its cold-oil extra P_f,cold [W] (0 <= P_f,cold <= P_f).
GasPathState computeGasPath(const GasPathParams& p, double omega_rad_s, double torque_Nm,
                            double load_fraction, double fuel_kg_s, double fuel_ref_kg_s,
                            double ambient_T_K, double ambient_p_Pa, double friction_W,
                            double cold_friction_W);

}  // namespace hbt::engine_map
