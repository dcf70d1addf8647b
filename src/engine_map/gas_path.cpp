#include "engine_map/gas_path.hpp"

#include <algorithm>
#include <cmath>

#include "common/friction_heat.hpp"
#include "common/species.hpp"
#include "common/units.hpp"

namespace hbt::engine_map {
namespace {
// Molar masses [g/mol]: atoms C and H, N2* (atmospheric nitrogen incl. argon) of this gas path;
// O2, CO2 and H2O from common/species.
constexpr double kM_C = 12.011, kM_H = 1.008, kM_N2 = 28.155;
constexpr double kM_O2 = species::gPerMol(species::kO2_kg_mol);
constexpr double kM_CO2 = species::gPerMol(species::kCO2_kg_mol);
constexpr double kM_H2O = species::gPerMol(species::kH2O_kg_mol);
constexpr double kN2_per_O2 = 3.773;  // mol N2* per mol O2 in air
}  // namespace

double stoichiometricAfr(double y) {
  return (1.0 + y / 4.0) * (kM_O2 + kN2_per_O2 * kM_N2) / (kM_C + y * kM_H);
}

ExhaustComposition leanProducts(double lambda, double y) {
  const double a = 1.0 + y / 4.0;
  ExhaustComposition c;
  if (!(lambda < kLambdaAirOnly)) {  // no fuel: air
    const double o = kM_O2, n = kN2_per_O2 * kM_N2;
    c.y_O2 = o / (o + n);
    c.y_N2 = n / (o + n);
    return c;
  }
  const double l = std::max(lambda, 1.0);
  // Masses per mole of CH_y [g].
  const double mCO2 = kM_CO2, mH2O = 0.5 * y * kM_H2O, mO2 = (l - 1.0) * a * kM_O2;
  const double mN2 = l * a * kN2_per_O2 * kM_N2;
  const double tot = mCO2 + mH2O + mO2 + mN2;
  c.y_CO2 = mCO2 / tot;
  c.y_H2O = mH2O / tot;
  c.y_O2 = mO2 / tot;
  c.y_N2 = mN2 / tot;
  return c;
}

GasPathState computeGasPath(const GasPathParams& p, double w, double torque_Nm,
                            double load_fraction, double fuel_kg_s, double fuel_ref_kg_s,
                            double T_amb, double p_amb, double friction_W, double cold_friction_W) {
  GasPathState s;
  const double wpos = std::max(w, 0.0);
  const double xf = fuel_ref_kg_s > 0.0 ? std::clamp(fuel_kg_s / fuel_ref_kg_s, 0.0, 1.0) : 0.0;
  s.pressure_ratio = 1.0 + (p.boost_pressure_ratio_max - 1.0) * std::pow(xf, p.boost_fuel_exponent);
  s.boost_pressure_Pa = s.pressure_ratio * p_amb;
  const double k = (p.air_gamma - 1.0) / p.air_gamma;
  s.compressor_out_T_K =
      T_amb * (1.0 + (std::pow(s.pressure_ratio, k) - 1.0) / p.compressor_efficiency);
  s.intake_manifold_T_K =
      s.compressor_out_T_K - p.intercooler_effectiveness * (s.compressor_out_T_K - T_amb);
  const double rho_im = s.boost_pressure_Pa / (p.air_R_J_kgK * s.intake_manifold_T_K);
  s.air_mass_flow_kg_s =
      p.volumetric_efficiency * rho_im * p.displacement_m3 * wpos / (4.0 * units::kPi);
  s.exhaust_mass_flow_kg_s = s.air_mass_flow_kg_s + fuel_kg_s;
  const double afr = stoichiometricAfr(p.fuel_h_to_c_molar);
  s.lambda = fuel_kg_s > 0.0 ? s.air_mass_flow_kg_s / (afr * fuel_kg_s) : kLambdaNoFuel;
  s.comp = leanProducts(s.lambda, p.fuel_h_to_c_molar);

  s.fuel_power_W = fuel_kg_s * units::kDieselLhv_J_kg;
  s.brake_power_W = torque_Nm * w;
  const double x = std::clamp(load_fraction, 0.0, 1.0);
  const double fcool =
      p.coolant_fraction_light_load + x * (p.coolant_fraction_full_load - p.coolant_fraction_light_load);
  s.friction_W = std::max(friction_W, 0.0);
  const double fired_heat_W = s.fuel_power_W > 0.0 ? fcool * s.fuel_power_W + std::max(cold_friction_W, 0.0) : 0.0;
  s.coolant_heat_W = std::max(fired_heat_W, s.friction_W);  // the wall heat Q_cool - P_f >= 0
  s.misc_heat_W = p.misc_heat_fraction * s.fuel_power_W;
  s.intercooler_heat_W =
      s.air_mass_flow_kg_s * p.air_cp_J_kgK * (s.compressor_out_T_K - s.intake_manifold_T_K);
  const double qexh = s.fuel_power_W - s.brake_power_W - s.coolant_heat_W - s.misc_heat_W -
                      s.intercooler_heat_W;
  // At standstill (no flow) or a non-physical negative residual, the gas leaves at ambient and
  // the residual is assigned to the coolant so that the balance stays closed.
  if (s.exhaust_mass_flow_kg_s > 1e-9 && qexh >= 0.0) {
    s.exhaust_enthalpy_W = qexh;
    s.exhaust_T_K = T_amb + qexh / (s.exhaust_mass_flow_kg_s * p.exhaust_cp_J_kgK);
  } else {
    s.exhaust_enthalpy_W = 0.0;
    s.exhaust_T_K = T_amb;
    s.coolant_heat_W += qexh;
  }
  // Everything but the friction is wall heat (incl. a negative residual above, into the metal).
  const EngineHeatSplit split =
      splitEngineHeat(s.coolant_heat_W - s.friction_W, s.friction_W, p.friction_heat_to_oil_fraction);
  s.metal_heat_W = split.metal_W;
  s.oil_heat_W = split.oil_W;
  s.nox_mass_flow_kg_s = p.nox_emission_index_kg_per_kg * fuel_kg_s;
  return s;
}

}  // namespace hbt::engine_map
