// Physics-based loss model of the 48 V PMSM + MOSFET inverter (no loss map is given by VECTO).
// All quantities at the EM shaft; phase quantities are per-phase RMS; SI units.
//
// Magnet temperature: the NdFeB remanence falls reversibly with the magnet temperature T_m,
//   β(T_m) = 1 + α_Br (T_m − T_ref),  α_Br < 0 [1/K], T_ref = the datasheet temperature of k_t,
// and with it the magnet flux linkage ψ_m: k_t = β k_t,ref, I_ch = β I_ch,ref (= ψ_m/L),
// B̂ = β B̂_ref. β is floored at 0.05 (far outside any sane operating range).
// Current (surface-magnet PMSM, i_d = 0 below the voltage limit):
//   k_e = k_t/3 [V s/rad]  (back-EMF per phase, RMS; P = 3 E I_q = T ω)
//   V_ph,max = k_v V_dc,   k_v = 1/√6 (SVPWM linear range, phase RMS)
//   ω_v = V_ph,max / k_e   speed at which the magnet EMF alone reaches the voltage limit
//   I_q = |T| / k_t
//   I_d = −I_ch max(0, 1 − ω_v/ω)     field weakening: the d-current that brings the stator flux
//                                     linkage ψ_m + L I_d down to V_ph,max/ω_e (no-load form,
//                                     I_ch = ψ_m/L); independent of the torque
//   I   = max( √(I_q² + I_d²), |T ω| / (3 V_ph,max) )
//         the second term: the phase voltage cannot exceed V_ph,max, so the air-gap power needs at
//         least this current (power factor <= 1) -- it is what makes the current, and the copper
//         loss, grow in the voltage-limited (constant-power) region.
// Copper:   P_cu = 3 I² R_20 (1 + α (T_w − 293.15 K)) (1 + (f/f_ac)²),  f = p ω/(2π) [Hz]
//           (DC resistance of copper, α = 0.00393 1/K; the (f/f_ac)² term is the low-frequency
//           form of skin/proximity losses in the few, large conductors of a 48 V winding)
// Iron (stator, two-term Steinmetz/Bertotti with exponent 2):
//           B = B̂ min(1, ω_v/ω)    (stator flux linkage limited to V/ω_e in field weakening)
//           P_fe = k_build m_fe (k_h f B² + k_e f² B²)   (hysteresis ∝ f B², eddy ∝ f² B²)
//           P_rotor = r_rot P_fe   (rotor iron + magnet eddy currents from slot and PWM harmonics)
// Mechanical: P_bearing = T_b ω,  P_windage = P_w,ref (ω/ω_ref)³
// Inverter (2-level, 6 MOSFET switch positions, sinusoidal phase currents):
//           conduction P_c = 3 I² R_inv
//           switching  P_sw = 3 f_sw E_ref (V_dc/V_ref) (Ī/I_ref),  Ī = (2√2/π) I (mean |i|)
//           fixed      P_0 while active (ω > 0 or T ≠ 0): gate drives, control, DC-link ESR
// DC power:  P_dc = T ω + P_cu + P_fe + P_rotor + P_bearing + P_windage + P_inv
//           (motoring T ω > 0: losses are drawn in addition; generating T ω < 0: the battery
//           receives |T ω| minus the losses).
#pragma once
#include "emachine/emachine_params.hpp"

namespace hbt::emachine {

struct LossBreakdown {
  double i_q_A = 0, i_d_A = 0, i_A = 0;  // phase RMS currents (i_d <= 0)
  double frequency_Hz = 0;               // electrical frequency
  double flux_ratio = 1;                 // B/B̂ (field weakening)
  double magnet_flux_factor = 1;         // β(T_m): k_t/k_t,ref
  double copper_W = 0, iron_W = 0, rotor_W = 0, bearing_W = 0, windage_W = 0;
  double inverter_conduction_W = 0, inverter_switching_W = 0, inverter_fixed_W = 0;
  double machineHeat() const { return copper_W + iron_W + rotor_W + bearing_W + windage_W; }
  double inverter() const { return inverter_conduction_W + inverter_switching_W + inverter_fixed_W; }
  double total() const { return machineHeat() + inverter(); }
};

class LossModel {
 public:
  LossModel() = default;
  LossModel(const ElectricalParams& e, const IronParams& fe, const MechanicalParams& m,
            const InverterParams& inv)
      : e_(e), fe_(fe), m_(m), inv_(inv) {}
  /// Losses at EM shaft torque T [Nm] (signed), EM speed w >= 0 [rad/s], DC voltage V [V],
  /// winding and magnet temperatures [K]. Finite for every finite input (w = 0, V = 0 included).
  LossBreakdown evaluate(double T_Nm, double w_rad_s, double V, double T_winding_K,
                         double T_magnet_K) const;
  /// Phase resistance incl. temperature and AC factor [ohm].
  double phaseResistance(double T_winding_K, double f_Hz) const;
  /// Magnet flux factor β(T_m) [-] (1 at the reference temperature).
  double magnetFluxFactor(double T_magnet_K) const;
  /// Torque constant k_t at the magnet temperature [Nm/A].
  double torqueConstant(double T_magnet_K) const {
    return e_.torque_constant_Nm_A * magnetFluxFactor(T_magnet_K);
  }
  /// ω_v at V and the magnet temperature [rad/s] (0 for V <= 0).
  double voltageLimitSpeed(double V, double T_magnet_K) const;

 private:
  ElectricalParams e_;
  IronParams fe_;
  MechanicalParams m_;
  InverterParams inv_;
};

}  // namespace hbt::emachine
