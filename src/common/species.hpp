// Molar masses of the gas species the models share, each defined once here [kg/mol], and the gas
// constant of dry air (the molar gas constant is units::kUniversalGas_J_molK). A formula written
// per mole of fuel in grams (the map engine's gas path) takes gPerMol() of these: for O2, CO2 and
// H2O that is the same double as the decimal g/mol value (test_common: Species).
//
// The cylinder's NASA-7 species table (cylinder/thermo.cpp) keeps its own molar masses, the sums
// of its element masses, so that its element and mass balances close exactly.
#pragma once

namespace hbt::species {

constexpr double kO2_kg_mol = 31.999e-3;
constexpr double kCO2_kg_mol = 44.010e-3;
constexpr double kH2O_kg_mol = 18.015e-3;
constexpr double kN2_kg_mol = 28.013e-3;
constexpr double kCO_kg_mol = 28.010e-3;
constexpr double kNO2_kg_mol = 46.006e-3;  // NOx is reported as NO2
constexpr double kNH3_kg_mol = 17.031e-3;
constexpr double kUrea_kg_mol = 60.056e-3;  // CO(NH2)2

// Specific gas constant of dry air [J/(kg K)]: R_u / M_air with M_air = 28.9647 g/mol.
constexpr double kDryAirGas_J_kgK = 287.05;

constexpr double kGram_per_kg = 1e3;
/// Molar mass in g/mol (= kg/kmol) of a molar mass M_kg_mol [kg/mol].
constexpr double gPerMol(double M_kg_mol) { return M_kg_mol * kGram_per_kg; }

}  // namespace hbt::species
