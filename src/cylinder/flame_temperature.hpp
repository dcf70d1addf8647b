// Hot-zone (burned-zone) temperature with dissociation, for the NO kinetics.
//
// The cylinder tracks the burned zone's energy with frozen products (CO2, H2O, N2, O2, Ar: no
// dissociation), which gives its temperature T_f. At the same pressure p and the same absolute
// enthalpy (formation included) the zone in chemical equilibrium (12 species of equilibrium.hpp)
// is cooler, because the dissociation (CO2 → CO + ½O2, H2O → OH + ½H2, … ) is endothermic:
//   h_eq(T_eq, p) = h_f(T_f)                                          [J/kg]
//   h_f(T)  = Σ_s Y_s,f h°_s(T)/M_s            (frozen mass fractions Y_s,f)
//   h_eq(T) = n(T) Σ_s x_s(T, p) h°_s(T)       (n: mol of equilibrium mixture per kg)
// with NO counted as ½N2 + ½O2 in h_eq: NO forms kinetically (zeldovich.hpp), far below its
// equilibrium, so its formation enthalpy is not taken from the zone (it would be ~10 K at
// 2400 K, λ 1.5, and would make lean products at 1200–1500 K appear 0.3–2.5 K "dissociated").
// (isobaric-adiabatic, the definition of the adiabatic flame temperature; h°_s from NASA-7,
// thermo.hpp). Solved for T_eq by a bounded secant iteration on the residual
// r(T) = h_eq(T) − h_f: first step with the frozen cp of the equilibrium mixture (overshoots
// below the root, since the equilibrium cp is larger), then secant steps; a temperature is
// accepted once the next correction is below kToleranceK = 0.05 K (NO rate error < 0.1 %); at
// most kMaxIterations + 1 equilibrium solves (warm-started; measured at λ 1.5, 30–150 bar: 2 at
// 1500–1900 K, 3 at 2100–2500 K; 4–6 for a stoichiometric flame at 1 bar). Where dissociation
// is negligible (λ 1.5: T_f − T_eq 0.1 K at 1500 K, 1.3 K at 1900 K, 15 K at 2400 K / 100 bar) the
// first step is below the tolerance and T_eq = T_f exactly (one solve, as without dissociation).
//
// Sensitivity: dT_eq/dT_f = cp,f / cp,eq < 1, so the hot zone's response to a warmer charge is
// damped where dissociation is significant (stoichiometric, hot, low pressure).
#pragma once
#include <array>

#include "cylinder/equilibrium.hpp"
#include "cylinder/thermo.hpp"

namespace hbt::cylinder {

/// Absolute enthalpy (formation included) of a frozen mixture of mass fractions Y [J/kg].
double frozenEnthalpy_J_kg(const double Y[kNumSpecies], double T_K);
/// Absolute enthalpy of an equilibrium mixture: n [mol/kg], mole fractions x [J/kg].
double mixtureEnthalpy_J_kg(double n_mol_kg, const double x[kNumSpecies], double T_K);

class DissociatedFlame {
 public:
  static constexpr int kMaxIterations = 12;
  static constexpr double kToleranceK = 0.05;  // K

  struct Result {
    double T_K = 0.0;             // equilibrium (dissociated) temperature
    double n_mol_kg = 0.0;        // mol of equilibrium mixture per kg
    double x[kNumSpecies] = {};   // equilibrium mole fractions at T_K (kFuel entry 0)
  };

  /// b: element moles per kg (C, H, O, N, Ar) of the zone; Y_frozen: its frozen mass fractions
  /// (same elements); T_frozen_K: its frozen temperature; p_Pa: pressure. Returns false if an
  /// equilibrium solve or the temperature iteration fails (out is then not valid).
  /// tolerance_K: the temperature is accepted once the next correction is below it.
  bool solve(const std::array<double, 5>& b, const double Y_frozen[kNumSpecies],
             double T_frozen_K, double p_Pa, Result& out, double tolerance_K = kToleranceK);
  int lastEquilibriumSolves() const { return solves_; }
  void reset() { eq_.reset(); }

 private:
  bool equilibriumAt(const std::array<double, 5>& b, double T, double p, Result& r);
  Equilibrium eq_;
  int solves_ = 0;
};

}  // namespace hbt::cylinder
