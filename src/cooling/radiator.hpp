// Radiator (liquid-to-air, cross-flow, both fluids unmixed) by the effectiveness-NTU method.
//
//   C_air = ṁ_air c_p,air,  C_cool = ṁ_cool c_p,cool  [W/K],  C_min/max = min/max,  C_r = C_min/C_max
//   NTU = UA / C_min
//   ε = 1 - exp[ NTU^0.22 / C_r · (exp(-C_r NTU^0.78) - 1) ]     (C_r > 0)
//   ε = 1 - exp(-NTU)                                              (C_r = 0)
//   Q̇ = ε C_min (T_cool,in - T_air,in)  [W]   (> 0: heat from coolant to air)
// (Incropera, DeWitt, Bergman, Lavine, "Fundamentals of Heat and Mass Transfer", Table 11.3,
// cross-flow single pass, both fluids unmixed; approximate closed form, exact for C_r = 0.)
//
// UA depends on both flows through a series of two film resistances, each a power law of its
// flow (fin-side j-factor ∝ Re^-0.4 -> h_air ∝ ṁ^0.6, tube side Dittus-Boelter h ∝ ṁ^0.8):
//   1/UA = 1/(hA_air,ref (ṁ_air/ṁ_air,ref)^n_a) + 1/(hA_cool,ref (ṁ_cool/ṁ_cool,ref)^n_c)
//   hA_air,ref = UA_ref/f_air,  hA_cool,ref = UA_ref/(1 - f_air)
// UA_ref is found once from a rated point (Q̇_rated at T_cool,in, T_air,in, ṁ_air,ref, ṁ_cool,ref):
// ε_rated = Q̇_rated/(C_min ΔT_in), NTU_rated = ε^-1(ε_rated, C_r) by bisection, UA_ref = NTU C_min.
#pragma once
#include <string>

namespace hbt::cooling {

/// ε of a single-pass cross-flow exchanger, both fluids unmixed. ntu >= 0, 0 <= cr <= 1.
double effectivenessCrossflowUnmixed(double ntu, double cr);
/// Inverse of effectivenessCrossflowUnmixed in NTU (bisection to 1e-12 relative); throws
/// std::domain_error if eps is not reachable (eps >= max over NTU in [0, 50]).
double ntuCrossflowUnmixed(double eps, double cr);

struct RadiatorRating {
  double heat_W = 0.0;
  double coolant_in_K = 0.0, air_in_K = 0.0;
  double air_mass_flow_kg_s = 0.0, coolant_mass_flow_kg_s = 0.0;
  double air_side_resistance_fraction = 0.75;
  double air_flow_exponent = 0.6, coolant_flow_exponent = 0.8;
};

class Radiator {
 public:
  Radiator() = default;
  /// Derives UA_ref from the rated point. Throws InputError(file, key_prefix + "rated_heat_W")
  /// if the rated heat needs ε >= the exchanger's reachable maximum.
  Radiator(const RadiatorRating& r, double air_cp_J_kgK, double coolant_cp_J_kgK,
           const std::string& file = "(cooling parameters)", const std::string& key_prefix = "");
  double ratedUA_W_K() const { return ua_ref_; }
  /// UA at the given flows [W/K] (0 if either flow is 0).
  double ua_W_K(double air_mass_flow_kg_s, double coolant_mass_flow_kg_s) const;
  /// Conductance G = ε C_min [W/K] so that Q̇ = G (T_cool,in - T_air,in).
  double conductance_W_K(double air_mass_flow_kg_s, double coolant_mass_flow_kg_s) const;

 private:
  RadiatorRating r_;
  double cp_air_ = 1007.0, cp_cool_ = 3550.0;
  double ua_ref_ = 0.0, hA_air_ref_ = 0.0, hA_cool_ref_ = 0.0;
};

}  // namespace hbt::cooling
