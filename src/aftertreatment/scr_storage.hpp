// NH3 storage and NOx reduction on the SCR brick, integrated over one step at frozen wall
// temperatures and inlet flows with the explicit Runge-Kutta 5(4) of Dormand & Prince
// (common/dormand_prince.hpp, error-controlled, restarted each step: nothing carries over the
// jump of the inputs at the step boundary). Explicit, because the coverages are not stiff on the
// 0.1 s step: they relax on time scales of seconds and longer (the fastest, Temkin desorption,
// <= ~0.2 1/s at the coverages a store holds up to 350 degC), so |lambda h| stays far inside the
// method's stability region (~3.3 on the real axis) and one 5th-order step per model step meets
// rtol 1e-8; a stiffer state (a full store heated to 350 degC: ~70 1/s) only makes the error
// control take smaller steps (at most max_steps).
//
// Sites: Omega [mol/m^3 of brick] NH3 sites, coverage theta_i per axial slice (volume V_s).
// Rates per brick volume [mol/(m^3 s)] on slice i at its wall temperature T_i (Eley-Rideal
// with stored NH3, after Olsson, Sjovall & Blint, "A kinetic model for ammonia selective
// catalytic reduction over Cu-ZSM-5", Appl. Catal. B 81 (2008) 203-217, and Chatterjee et al.,
// "Numerical simulation of zeolite- and V-based SCR catalytic converters", SAE 2007-01-1136):
//   adsorption    r_ads  = k_ads c_NH3 Omega (1 - theta)
//   desorption    r_des  = k_des exp(-E_des (1 - alpha theta) / (R T)) Omega theta      (Temkin)
//   standard SCR  r_std  = k_std(T) c_NO Omega theta         4 NH3 + 4 NO + O2 -> 4 N2 + 6 H2O
//   fast SCR      r_fast = k_fast(T) c_NO c_NO2 Omega theta  2 NH3 + NO + NO2 -> 2 N2 + 3 H2O
//   NO2 SCR       r_no2  = k_no2(T) c_NO2 Omega theta        8 NH3 + 6 NO2 -> 7 N2 + 12 H2O
//   NH3 oxidation r_ox   = k_ox(T) Omega theta               4 NH3 + 3 O2 -> 2 N2 + 6 H2O
//   k_j(T) = k_j,ref exp(-E_j/R (1/T - 1/T_ref))
//   Omega dtheta_i/dt = r_ads - r_des - r_std - 2 r_fast - 4/3 r_no2 - r_ox
// (r_std counts mol NO = mol NH3, r_fast counts events consuming 1 NO + 1 NO2 + 2 NH3, r_no2 mol
// NO2, r_ox mol NH3). The gas in a slice is quasi-steady and well mixed (a series of N CSTRs; residence time
// ~ 5 ms): with the molar flows F_in and Vdot_i = F_tot R T_i / p,
//   NH3: Vdot_i (c_in - c) = V_s (r_ads - r_des)  -> c = (Vdot c_in + V_s r_des)/(Vdot + V_s k_ads Omega (1-theta))
//   NO2: Vdot_i (c2_in - c2) = V_s (r_fast + r_no2),  NO: Vdot_i (c1_in - c1) = V_s (r_std + r_fast)
//        -> one quadratic in c1, solved in closed (cancellation-free) form.
// The storage capacity at a given gas NH3 level falls with temperature through the Temkin
// equilibrium k_ads c (1 - theta) = k_des exp(-E_des (1 - alpha theta)/RT) theta (equilibriumCoverage).
// Integrated alongside with the same Runge-Kutta stages (outside its error norm; the integrands
// are smooth functions of the coverages alone): cumulative NH3 slip, mol of standard / fast /
// NO2 / oxidation events, and the reaction heat per slice (the NH3 balance closes to round-off:
// a Runge-Kutta method keeps linear invariants)
//   dQ_i/dt = V_s (r_std dH_std + r_fast dH_fast + r_no2 dH_no2 + r_ox dH_ox),
//   dH_std = 407 kJ/mol NO, dH_fast = 757 kJ per event, dH_no2 = 455.5 kJ/mol NO2,
//   dH_ox = 317 kJ/mol NH3 (released; from
//   the formation enthalpies of NH3 -45.9, NO 90.3, NO2 33.1, H2O(g) -241.8 kJ/mol).
// The state and stage vectors are allocated once; step() does not allocate.
#pragma once
#include "common/units.hpp"
#include <memory>
#include <vector>

namespace hbt {
class DormandPrince;
}

namespace hbt::aftertreatment {

struct ScrKinetics {
  double omega_mol_m3 = 150.0, k_ads = 2.0, k_des = 2.9e7, E_des = 110e3, alpha = 0.3;
  double k_std_ref = 0.47, E_std = 85e3, k_fast_ref = 1500.0, E_fast = 70e3;
  double k_no2_ref = 0.2, E_no2 = 90e3;
  double k_ox_ref = 0.1, E_ox = 160e3, T_ref = 523.15, T_ox_ref = 723.15;
};

/// Inlet of one step (held constant over the step).
struct ScrInlet {
  double n_NO_mol_s = 0.0, n_NO2_mol_s = 0.0, n_NH3_mol_s = 0.0;  ///< molar flows
  double n_total_mol_s = 0.0;                                     ///< total gas molar flow
  double p_Pa = units::kStandardAtmosphere_Pa;
};

/// Integrals over one step.
struct ScrStepResult {
  double nh3_slip_mol = 0.0;     ///< NH3 leaving the SCR
  double std_mol = 0.0;          ///< standard SCR events (mol NO = mol NH3)
  double fast_mol = 0.0;         ///< fast SCR events (1 NO + 1 NO2 + 2 NH3 each)
  double no2_mol = 0.0;          ///< NO2 reduced by NO2-SCR (4/3 NH3 each)
  double ox_mol = 0.0;           ///< NH3 oxidised
  double n_NO_out_mol_s = 0.0, n_NO2_out_mol_s = 0.0;  ///< outlet flows at the end of the step
  double nh3_out_mol_s = 0.0;
};

class ScrStorage {
 public:
  ScrStorage(const ScrKinetics& k, int slices, double slice_volume_m3, double rtol,
             double atol_theta, int max_steps);
  ~ScrStorage();
  ScrStorage(const ScrStorage&) = delete;
  ScrStorage& operator=(const ScrStorage&) = delete;

  void setCoverage(double theta);
  /// Advances by dt at the wall temperatures T_K[slices]; heat_J[slices] receives the reaction
  /// heat released per slice over the step. Throws ModelDivergence naming the quantity.
  ScrStepResult step(double dt, const ScrInlet& in, const double* T_K, double* heat_J);

  int slices() const { return n_; }
  double coverage(int i) const { return theta_[i]; }
  double storedMol() const;  ///< NH3 stored on the brick [mol]
  /// Temkin equilibrium coverage at temperature T and gas NH3 concentration c [mol/m^3].
  double equilibriumCoverage(double T_K, double c_NH3_mol_m3) const;
  const ScrKinetics& kinetics() const { return k_; }
  long solverSteps() const { return steps_; }

  /// Right-hand sides (public for the tests) at coverages theta[N]: dtheta/dt into yd
  /// and the quadratures' rates d[slip, std, fast, no2, ox, Q_0..N-1]/dt into qd (either may be
  /// null), the outlet molar flows [NO, NO2, NH3] into out_flows if given.
  void rhs(const double* theta, double* yd, double* qd, double* out_flows = nullptr) const;

 private:
  std::unique_ptr<DormandPrince> rk_;  // state: coverages; integrals: 5 amounts [mol], heats [J]
  ScrKinetics k_;
  int n_;
  double Vs_;
  double rtol_, atol_theta_;
  int max_steps_;
  std::vector<double> theta_;
  // frozen per step
  ScrInlet in_;
  std::vector<double> Vdot_, kd_, bT_, kstd_, kfast_, kno2_, kox_, scratch_;
  std::vector<double> q_;  // the step's integrals [slip, std, fast, no2, ox mol; heat J per slice]
  long steps_ = 0;
};

}  // namespace hbt::aftertreatment
