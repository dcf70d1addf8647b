// Chemical equilibrium of C–H–O–N(–Ar) combustion products at given T, p and element amounts.
//
// Twelve species: N2 O2 Ar CO2 H2O CO H2 OH H O N NO (Ar inert). Every species is formed from the
// base species H2, O2, N2, CO; its mole fraction follows from the equilibrium constant of that
// formation reaction (data: NASA-7 Gibbs functions of thermo.hpp, p° = 1 bar, P = p/p°):
//   ½H2 ⇌ H        x_H   = K x_H2^½ P^−½        ½O2 ⇌ O         x_O   = K x_O2^½ P^−½
//   ½N2 ⇌ N        x_N   = K x_N2^½ P^−½        ½H2 + ½O2 ⇌ OH  x_OH  = K x_H2^½ x_O2^½
//   ½O2 + ½N2 ⇌ NO x_NO  = K x_O2^½ x_N2^½       H2 + ½O2 ⇌ H2O  x_H2O = K x_H2 x_O2^½ P^½
//   CO + ½O2 ⇌ CO2 x_CO2 = K x_CO x_O2^½ P^½     ln K = −Σ ν_i g°_i/(R_u T)
// Unknowns z = (ln x_H2, ln x_O2, ln x_N2, ln x_CO, ln n) [n: mol of mixture per kg] from the four
// element balances n Σ_s a_es x_s = b_e (e = C, H, O, N) and Σ x_s + b_Ar/n = 1, solved by a
// damped Newton iteration (analytic Jacobian, 5×5 Gauss elimination), warm-started from the
// previous solution. Elements that are absent drop out with their base species.
#pragma once
#include <array>

#include "cylinder/thermo.hpp"

namespace hbt::cylinder {

class Equilibrium {
 public:
  /// b: element moles per kg (C, H, O, N, Ar). x_out: mole fractions indexed by Species
  /// (kFuel entry set to 0). Returns false if Newton did not converge.
  bool solve(const std::array<double, 5>& b, double T_K, double p_Pa, double x_out[kNumSpecies]);
  int lastIterations() const { return iters_; }
  /// Moles of the mixture per kg [mol/kg] of the last solution.
  double molesPerKg() const;
  void reset() { warm_ = false; }

 private:
  double z_[5] = {0, 0, 0, 0, 0};
  bool warm_ = false;
  int iters_ = 0;
};

}  // namespace hbt::cylinder
