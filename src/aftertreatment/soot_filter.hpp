// Soot in the DPF: deposition of the engine-out soot and its oxidation by NO2 (passive
// regeneration), per axial slice of the filter. ROS-free; no allocation after construction.
//
// Engine-out soot: mdot_soot = EF ṁ_CO2, EF [kg soot / kg CO2] (the engine publishes no soot;
// its CO2 is its fuel's carbon); the DPF captures eta_f of it, spread evenly over its N slices;
// (1 - eta_f) leaves at the tailpipe.
// NO2 oxidation (Shrivastava et al., "Kinetics of soot oxidation by NO2", Environ. Sci. Technol.
// 44 (2010) 4796, first order in NO2): the diameter of a soot particle regresses at
//   dd/dt = -A T^0.5 [NO2] exp(-E/(R T)),  A [nm K^-0.5 s^-1 cm^3], [NO2] [molecules/cm^3];
// for particles of diameter d_p (m ∝ d^3) the mass-specific rate is
//   k_m(T, c) = -(1/m) dm/dt = (3/d_p) A' T^0.5 c exp(-E/(R T))   [1/s],
//   A' = A 1e-9 [m/nm] x N_A 1e-6 [m^3/cm^3]  (c in mol/m^3),
// with d_p the primary particle diameter (the agglomerate's accessible surface).
// Stoichiometry: a fraction s of the carbon by C + 2 NO2 -> CO2 + 2 NO, 1 - s by
// C + NO2 -> CO + NO: nu = 1 + s NO2 per C; NO2 becomes NO (NOx in moles is unchanged).
// Reaction heat per mol C from formation enthalpies (NIST-JANAF, 298 K: CO2 -393.5, CO -110.5,
// NO 90.3, NO2 33.1 kJ/mol): s 279.1 + (1 - s) 53.3 kJ/mol, deposited on the slice's wall.
// Wall flow: the gas crosses the soot cake once, each slice passing 1/N of the flow, so the NO2
// portion F/N through slice i (soot mass m_i, wall temperature T_i, volume flow Vdot/N) leaves
// as (F/N) exp(-kappa_i), kappa_i = nu (3/d_p) A' T_i^0.5 exp(-E/(R T_i)) m_i / (M_C Vdot/N)
// (plug flow through the cake, first order in NO2; soot mass held over the step). The carbon
// burnt on slice i over dt is min(consumed NO2 / nu dt, m_i + deposit) / M_C; the soot mass
// balance closes exactly: m_i(t + dt) = m_i + deposit_i - burnt_i.
// O2 oxidation is not modelled: it needs > 450-600 degC (Jeguirim et al., C. R. Chimie 17
// (2014) 672), which the DPF of a city bus does not reach without active regeneration.
#pragma once
#include <vector>

#include "aftertreatment/ats_params.hpp"

namespace hbt::aftertreatment {

constexpr double kM_C = 12.011e-3;          // kg/mol carbon
constexpr double kAvogadro = 6.02214076e23; // 1/mol
constexpr double kDH_C_2NO2 = 279.1e3;      // J/mol C released, C + 2 NO2 -> CO2 + 2 NO
constexpr double kDH_C_NO2 = 53.3e3;        // J/mol C released, C + NO2 -> CO + NO

/// Amounts of one step of the soot filter.
struct SootStep {
  double n_NO2_out_mol_s = 0.0;  ///< NO2 leaving the filter [mol/s]
  double no2_consumed_mol = 0.0; ///< NO2 reduced to NO over the step [mol]
  double carbon_co2_mol = 0.0;   ///< carbon burnt to CO2 over the step [mol]
  double carbon_co_mol = 0.0;    ///< carbon burnt to CO over the step [mol]
  double captured_kg = 0.0;      ///< soot deposited over the step [kg]
  double slip_kg = 0.0;          ///< soot passing the filter over the step [kg]
};

class SootFilter {
 public:
  SootFilter(const SootParams& p, int slices, double slice_volume_m3);

  /// Every slice at load_g_L (1 g/L = 1 kg/m^3 of filter volume).
  void setUniformLoad(double load_g_L);
  /// One step: engine-out soot in, NO2 oxidation at the wall temperatures T_K[i]; writes the
  /// reaction heat per slice to qr_W[i] [W]. Flows in mol/s; p_Pa the filter pressure.
  SootStep step(double dt, double co2_kg_s, double n_NO2_mol_s, double n_tot_mol_s, double p_Pa,
                const double* T_K, double* qr_W);

  /// Mass-specific NO2 oxidation rate k_m [1/s] at T_K and NO2 concentration c [mol/m^3].
  double specificRate_1_s(double T_K, double c_NO2_mol_m3) const;
  double mass_kg() const;                       ///< soot in the filter [kg]
  double load_g_L() const;                      ///< soot per filter volume [g/L]
  double sliceMass_kg(int i) const { return m_[i]; }
  int slices() const { return n_; }

 private:
  SootParams p_;
  int n_;
  double V_slice_;
  std::vector<double> m_;  ///< soot per slice [kg]
};

}  // namespace hbt::aftertreatment
