// Extended Zeldovich NO kinetics in the burned zone, integrated with SUNDIALS CVODE (BDF).
//
// Reactions (forward rate coefficients from Heywood, "ICE Fundamentals", Table 11.1, converted
// from cm³/(mol s) to m³/(mol s)):
//   (1) O + N2 ⇌ NO + N    k1f = 7.6e7 exp(−38 000/T)
//   (2) N + O2 ⇌ NO + O    k2f = 6.4e3 T exp(−3 150/T)
//   (3) N + OH ⇌ NO + H    k3f = 4.1e7
// Reverse coefficients by detailed balance with the NASA-7 Gibbs data (k_r = k_f/K_c, Δn = 0 so
// K_c = K_p), so the kinetics relax exactly to the equilibrium NO of cylinder::Equilibrium.
// O, O2, N2, OH, H are held at their equilibrium concentrations [X]_e = x_e p/(R_u T); NO and N
// are kinetic (N is not assumed quasi-steady: that fast mode makes the system stiff):
//   r_i = k_if [A_i][B_i] − k_ir [NO][C_i]
//   d[NO]/dt = r1 + r2 + r3,   d[N]/dt = r1 − r2 − r3        [mol/(m³ s)]
// With [NO] = 0 and N quasi-steady this gives the classical initial rate d[NO]/dt = 2 k1f [O][N2].
//
// Cost control: one CVODE memory, vector, matrix and linear solver are created in the constructor
// and re-used with CVodeReInit for every interval (T, p and equilibrium held constant over the
// interval); N is started at its quasi-steady value so the solver does not resolve a ns transient.
#pragma once
#include <memory>

#include "cylinder/thermo.hpp"

namespace hbt {
class CvodeSolver;
}

namespace hbt::cylinder {

class ZeldovichNO {
 public:
  ZeldovichNO();
  ~ZeldovichNO();
  ZeldovichNO(const ZeldovichNO&) = delete;
  ZeldovichNO& operator=(const ZeldovichNO&) = delete;

  /// Sets T [K], p [Pa] and equilibrium mole fractions (indexed by Species).
  void setConditions(double T_K, double p_Pa, const double x_eq[kNumSpecies]);
  /// Integrates over dt [s]; c_NO, c_N [mol/m³] in/out. If start_N_qss, c_N is first set to its
  /// quasi-steady value for the given c_NO. Throws hbt::ModelDivergence on solver failure.
  void integrate(double dt_s, double& c_NO, double& c_N, bool start_N_qss = true);
  /// Right-hand side (for tests): d[NO]/dt, d[N]/dt at the current conditions.
  void rates(double c_NO, double c_N, double& dNO, double& dN) const;
  double quasiSteadyN(double c_NO) const;
  double equilibriumNO() const { return cNOe_; }  // mol/m³
  double k1f() const { return k1f_; }
  double k2f() const { return k2f_; }
  double k3f() const { return k3f_; }
  double conc(Species s) const { return c_[s]; }  // equilibrium concentration, mol/m³
  long stepsTaken() const { return steps_; }      // cumulative CVODE steps (cost diagnostics)
  /// Relative tolerance of CVODE (default 1e-4; absolute: 1e-12 / 1e-18 of the total concentration).
  void setRelativeTolerance(double rtol) { rtol_ = rtol; }

 private:
  std::unique_ptr<CvodeSolver> cvode_;  // state: [NO], [N] [mol/m³]
  double c_[kNumSpecies] = {};
  double k1f_ = 0, k1r_ = 0, k2f_ = 0, k2r_ = 0, k3f_ = 0, k3r_ = 0, cNOe_ = 0, ctot_ = 1;
  long steps_ = 0;
  double rtol_ = 1e-4;
 public:
  double init_frac_ = 0.05;
 private:
  friend struct ZeldovichAccess;
};

}  // namespace hbt::cylinder
