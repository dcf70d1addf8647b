// Ideal-gas thermodynamics of the in-cylinder charge (ROS-free, allocation-free in use).
//
// Species data: NASA 7-coefficient polynomials (two ranges split at 1000 K)
//   cp°/R = a0 + a1 T + a2 T^2 + a3 T^3 + a4 T^4
//   h°/(R T) = a0 + a1 T/2 + a2 T^2/3 + a3 T^3/4 + a4 T^4/5 + a5/T
//   s°/R = a0 ln T + a1 T + a2 T^2/2 + a3 T^3/3 + a4 T^4/4 + a6
// for N2, O2, Ar, CO2, H2O, CO, H2, OH, H, O, N, NO (GRI-Mech 3.0 thermo data, Burcat/TPIS) and
// diesel vapour (Burcat "C12H23 Jet-A(g)" polynomial, used per kg for the diesel surrogate).
//
// The charge is described by three mass groups g (the "zones" of the mass accounting):
//   AIR   dry air (78.084 % N2, 20.946 % O2, 0.934 % Ar, 0.036 % CO2 by mole),
//   FUEL  vaporised diesel C_nC H_nH (default C12H22.3, 13.5 wt-% H, EN 590 typical),
//   BURNED stoichiometric combustion products of the fuel with air (CO2, H2O, N2, Ar).
// Any charge (air + residual/EGR + vapour + products at any lambda) is a linear combination of them.
// Per-kg group polynomials are mass-weighted sums of the species polynomials, so a mixture's
// extensive polynomial is the mass-weighted sum of three coefficient sets (no species loop per step).
//
// Energy convention (sensible, reference T_ref = 298.15 K):
//   h_g(T) = ∫_{T_ref}^{T} cp_g dT            [J/kg]  (enthalpy carried by flows)
//   u_g(T) = h_g(T) − R_g T                     [J/kg]  (internal energy of the charge)
// With this convention the formation enthalpies leave the energy balance and the chemical heat
// release of burning 1 kg of fuel vapour at any T is LHV_vap = LHV + h_fg (liquid LHV plus the
// latent heat of the fuel), while injected liquid fuel brings h_FUEL(T_fuel) − h_fg.
#pragma once
#include <array>

#include "common/units.hpp"

namespace hbt::cylinder {

enum Species { kN2, kO2, kAr, kCO2, kH2O, kCO, kH2, kOH, kH, kO, kN, kNO, kFuel, kNumSpecies };
enum Group { kAir = 0, kFuelVap = 1, kBurned = 2, kNumGroups = 3 };

constexpr double kRu = units::kUniversalGas_J_molK;  // J/(mol K)
constexpr double kTref = 298.15;      // K
constexpr double kPref = 1.0e5;       // Pa, standard pressure of the Gibbs data

/// NASA-7 record of one species (per mole, dimensionless).
struct Nasa7 {
  const char* name;
  double M;        // kg/mol
  double lo[7];    // 200(300)..1000 K
  double hi[7];    // 1000..3500(5000) K
  int nC, nH, nO, nN;
};
const Nasa7& species(Species s);
/// Dimensionless standard-state properties of a species.
double cpR(Species s, double T);
double hRT(Species s, double T);   // absolute enthalpy incl. formation / (R T)
double sR(Species s, double T);    // standard entropy at p° / R
double gRT(Species s, double T);   // g°/(R T) = h/RT − s/R

/// Per-kg polynomial of a fixed-composition mixture: cp(T) = Σ c[k] T^k [J/(kg K)],
/// h(T) = Σ c[k] T^(k+1)/(k+1) + c5 [J/kg] with c5 set so that h(T_ref) = 0.
struct Poly {
  double lo[6] = {0, 0, 0, 0, 0, 0};
  double hi[6] = {0, 0, 0, 0, 0, 0};
  double R = 0.0;  // J/(kg K)
  void addScaled(const Poly& o, double w) {  // this += w * o (extensive sums)
    for (int k = 0; k < 6; ++k) {
      lo[k] += w * o.lo[k];
      hi[k] += w * o.hi[k];
    }
    R += w * o.R;
  }
  double cp(double T) const {
    const double* c = T < 1000.0 ? lo : hi;
    return c[0] + T * (c[1] + T * (c[2] + T * (c[3] + T * c[4])));
  }
  double h(double T) const {
    const double* c = T < 1000.0 ? lo : hi;
    return T * (c[0] + T * (c[1] / 2 + T * (c[2] / 3 + T * (c[3] / 4 + T * c[4] / 5)))) + c[5];
  }
  double u(double T) const { return h(T) - R * T; }
};

struct FuelSpec {
  double nC = 12.0;          // carbon atoms of the surrogate C_nC H_nH
  double nH = 22.3;          // hydrogen atoms (13.5 wt-% H)
  double lhv_J_kg = 42.8e6;  // lower heating value of the liquid fuel (EN 590 typical 42.7–43.0)
  double hfg_J_kg = 0.25e6;  // latent heat of vaporisation
};

/// The three group polynomials and the stoichiometry of the chosen fuel.
class GasThermo {
 public:
  /// constant_cp: every group uses cp = cp_g(T_const) (for isentropic-law tests).
  explicit GasThermo(const FuelSpec& fuel = FuelSpec(), bool constant_cp = false,
                     double T_const = 300.0);
  const Poly& group(Group g) const { return group_[g]; }
  const FuelSpec& fuel() const { return fuel_; }
  double afrStoich() const { return afr_st_; }      // kg air / kg fuel
  double fuelMolarMass() const { return M_fuel_; }  // kg/mol
  /// Mass fraction of species s in group g (species set kN2..kH2O, kFuel).
  double massFraction(Group g, Species s) const { return Y_[g][s]; }
  /// Element moles (C, H, O, N, Ar) per kg of group g.
  const std::array<double, 5>& elements(Group g) const { return elem_[g]; }

 private:
  FuelSpec fuel_;
  double afr_st_ = 0.0, M_fuel_ = 0.0;
  Poly group_[kNumGroups];
  double Y_[kNumGroups][kNumSpecies] = {};
  std::array<double, 5> elem_[kNumGroups] = {};
};

/// Mixture by group masses [kg] → extensive polynomial (J/K units), built without allocation.
inline Poly mixturePoly(const GasThermo& th, const double m[kNumGroups]) {
  Poly p;
  for (int g = 0; g < kNumGroups; ++g)
    if (m[g] != 0.0) p.addScaled(th.group(Group(g)), m[g]);  // empty groups add exactly 0
  return p;
}

/// Solves m·u(T) = U for T by Newton (extensive poly); T0 = initial guess. Throws nothing;
/// returns NaN if it fails (the caller raises ModelDivergence with the element name).
double temperatureFromU(const Poly& ext, double U, double T0);

}  // namespace hbt::cylinder
