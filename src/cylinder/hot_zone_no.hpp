// NO of a mixing-controlled, stoichiometric, dissociated hot zone ("NO frozen at mixing").
//
// Picture (diffusion flame of a diesel spray: the fuel burns where it meets air in
// stoichiometric proportion; Heywood, "ICE Fundamentals", §11.2.3 and Fig. 11-6; Egnell,
// SAE 981021; Heider, Woschni & Zeilinger, MTZ 59 (1998)): each portion of fuel dm_fb [kg] that
// burns forms a packet of stoichiometric products with the unburned gas it meets (air plus the
// residual gas mixed with it). The packet sits at the dissociated adiabatic flame temperature for
// a residence time τ_hz [s] — the time the gas spends in the near-stoichiometric sheath before
// the spray's mixing dilutes it with excess air — and its NO forms there by the extended
// Zeldovich mechanism. Diluted, the gas cools by several hundred kelvin and its NO is frozen
// (added to the cylinder's NO, not formed or destroyed further).
//
// Per kg of fuel burned, with unburned gas of air mass fraction y_A (the rest residual/EGR):
//   a_A = AFR_st,   a_R = AFR_st (1/y_A − 1),   m_p = 1 + a_A + a_R        [kg products / kg fuel]
// frozen flame temperature T_f (sensible enthalpies h_g of the groups, thermo.hpp, zero at 298 K):
//   m_p h_B(T_f) = h_F(T_u) + LHV + h_fg + a_A h_A(T_u) + a_R h_B(T_u)    [J/kg fuel]
// (burning 1 kg of fuel vapour releases LHV + h_fg, as in the cylinder's first law);
// dissociated temperature T_hz at the same absolute enthalpy and pressure (flame_temperature.hpp);
// equilibrium concentrations [X]_e at (T_hz, p) (rates and equilibrium of zeldovich.hpp) and NO
// by the extended Zeldovich mechanism from [NO] = 0 over τ_hz, at the packet's constant T and p
// with N quasi-steady (Heywood eq. 11.10): α = [NO]/[NO]_e obeys
//   dα/dt = (1 − α²) / (τ_NO (1 + Kα)),   τ_NO = [NO]_e/(2 R1),   K = R1/(R2 + R3)
// with the one-way equilibrium rates R1 = k1f [O][N2], R2 = k2f [N][O2], R3 = k3f [N][OH]
// [mol/(m³ s)], whose exact solution from α(0) = 0 is
//   ½ ln((1 + α)/(1 − α)) − ½ K ln(1 − α²) = τ_hz/τ_NO                     (solved for α)
//   n_NO = α [NO]_e · v_p · m_p · dm_fb,   v_p = n_eq R_u T_hz / p           [mol], [m³/kg]
// Limits: τ_hz → 0 gives no NO; τ_hz ≫ τ_NO gives the equilibrium NO of the stoichiometric zone,
// which depends on T_hz far less than the Zeldovich rate (Heywood eq. 11.8: the initial rate
// 2 k1f [O]_e [N2]_e ∝ exp(−69 090/T)). test_hot_zone_no.cpp checks the limits and the closed
// form against a CVODE integration of the kinetics with N not quasi-steady.
// τ_hz is the one calibration constant of the engine-out NOx level (config/engine_1d_cylinder.yaml
// cylinder/nox/hot_zone_residence_s, set on the WHTC target of src/engine_1d/NOX.md).
#pragma once

#include "cylinder/flame_temperature.hpp"
#include "cylinder/thermo.hpp"
#include "cylinder/zeldovich.hpp"

namespace hbt::cylinder {

class HotZoneNO {
 public:
  struct Packet {
    double T_frozen_K = 0.0;       // frozen stoichiometric flame temperature
    double T_K = 0.0;              // dissociated hot-zone temperature
    double products_kg_kg = 0.0;   // m_p: kg of hot-zone gas per kg of fuel burned
    double volume_m3_kg = 0.0;     // v_p: volume of 1 kg of hot-zone gas at (T_K, p)
    double no_eq_mol_m3 = 0.0;     // equilibrium [NO] at (T_K, p)
    double no_mol_m3 = 0.0;        // [NO] after the residence time
  };

  explicit HotZoneNO(const GasThermo& thermo);
  HotZoneNO(const HotZoneNO&) = delete;
  HotZoneNO& operator=(const HotZoneNO&) = delete;

  /// Frozen stoichiometric flame temperature [K] of fuel vapour burning with unburned gas at
  /// T_u_K of air mass fraction y_air (0 < y_air <= 1). NaN if the Newton iteration fails.
  double frozenFlameTemperature_K(double T_u_K, double y_air) const;
  /// NO [mol] formed by dm_fuel_kg of fuel burning at T_u_K, p_Pa with unburned gas of air
  /// mass fraction y_air, over the residence time tau_s [s]. Fills out if given. Returns a
  /// negative value if the flame temperature or the equilibrium fails (the caller raises).
  /// Packets whose frozen flame temperature is below T_min_K (thermal NO negligible: the
  /// cylinder's nox/min_temperature_K) form no NO.
  double noMoles(double dm_fuel_kg, double T_u_K, double y_air, double p_Pa, double tau_s,
                 double T_min_K, Packet* out = nullptr);
  /// Hot-zone kg of gas per kg of fuel burned with unburned gas of air mass fraction y_air:
  /// m_p = 1 + AFR_st / y_air [-].
  double productsPerFuel(double y_air) const { return 1.0 + th_.afrStoich() / y_air; }
  /// NO [mol] per kg of hot-zone gas, [NO](tau) v_p, of a packet of frozen flame temperature
  /// T_frozen_K at p_Pa after the residence time tau_s: a function of (T_frozen_K, p_Pa, tau_s)
  /// alone, since the hot zone is always the stoichiometric products (the BURNED group). Fills
  /// out (all but T_frozen_K, products_kg_kg) if given. Negative if the dissociated flame
  /// temperature (equilibrium) fails. tolerance_K: of the dissociated temperature
  /// (DissociatedFlame::solve).
  double specificNO_mol_kg(double T_frozen_K, double p_Pa, double tau_s, Packet* out = nullptr,
                           double tolerance_K = DissociatedFlame::kToleranceK);
  /// Forget the equilibrium warm start: the next packet starts from complete combustion, so
  /// its result does not depend on the packets before it.
  void coldStart() { flame_.reset(); }
  /// The Zeldovich rates and equilibrium concentrations at the last packet's conditions (tests).
  const ZeldovichNO& zeldovich() const { return zeldovich_; }

 private:
  double alphaAt(double t_s) const;  // [NO]/[NO]_e after t_s from [NO] = 0 (closed form)

  const GasThermo& th_;
  DissociatedFlame flame_;
  ZeldovichNO zeldovich_;
};

}  // namespace hbt::cylinder
