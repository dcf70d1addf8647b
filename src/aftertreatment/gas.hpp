// Exhaust-gas properties for the aftertreatment (ROS-free, inline, allocation-free).
//
// Species: O2, CO2, H2O, N2 by mass fraction; the rest (NOx, HC, CO, Ar: < 0.5 %) is counted
// as N2. Properties:
//   cp_i(T) = a_i + b_i (T - 300 K)  [J/(kg K)], linear fits 300-1000 K to the JANAF/NIST
//            tables (N2 1039->1167, O2 918->1090, CO2 846->1234, H2O 1864->2288 J/(kg K));
//   cp = sum y_i cp_i(T);  M = 1 / sum(y_i / M_i);  R = R_u / M;
//   mu(T) = 1.716e-5 (T/273.15)^1.5 (273.15 + 110.4)/(T + 110.4) [Pa s] (Sutherland, air);
//   k(T)  = 0.0241 (T/273.15)^0.81 [W/(m K)] (power-law fit to air, 250-1000 K, +-3 %).
// Exhaust gas at lambda > 1.3 is ~75 % N2: the air values of mu and k are within a few percent.
#pragma once
#include "common/species.hpp"
#include "common/units.hpp"
#include <algorithm>
#include <cmath>

namespace hbt::aftertreatment {

constexpr double kRu = units::kUniversalGas_J_molK;  // J/(mol K)
constexpr double kAtm_Pa = units::kStandardAtmosphere_Pa;
constexpr double kM_NO2 = species::kNO2_kg_mol;  // kg/mol (NOx is reported as NO2)
constexpr double kM_NH3 = species::kNH3_kg_mol;  // kg/mol
constexpr double kM_CO = species::kCO_kg_mol;    // kg/mol
constexpr double kM_urea = species::kUrea_kg_mol;  // kg/mol
constexpr double kT_ref_K = 298.15;       // enthalpy reference of the energy balance

struct GasComposition {
  double y_O2 = 0.12, y_CO2 = 0.07, y_H2O = 0.05, y_N2 = 0.76;  // mass fractions [-]
};

inline double cpMix(const GasComposition& g, double T) {
  const double d = std::clamp(T, 250.0, 1200.0) - 300.0;
  const double yN2 = std::max(0.0, 1.0 - g.y_O2 - g.y_CO2 - g.y_H2O);
  return g.y_O2 * (918.0 + 0.2457 * d) + g.y_CO2 * (846.0 + 0.5543 * d) +
         g.y_H2O * (1864.0 + 0.6057 * d) + yN2 * (1039.0 + 0.1829 * d);
}

/// Molar mass [kg/mol]; everything that is not O2, CO2, H2O counts as N2.
inline double molarMass(const GasComposition& g) {
  const double yN2 = std::max(0.0, 1.0 - g.y_O2 - g.y_CO2 - g.y_H2O);
  return 1.0 / (g.y_O2 / species::kO2_kg_mol + g.y_CO2 / species::kCO2_kg_mol +
                g.y_H2O / species::kH2O_kg_mol + yN2 / species::kN2_kg_mol);
}

inline double viscosity(double T) {
  return 1.716e-5 * std::pow(T / 273.15, 1.5) * (273.15 + 110.4) / (T + 110.4);
}

inline double conductivity(double T) { return 0.0241 * std::pow(T / 273.15, 0.81); }

}  // namespace hbt::aftertreatment
