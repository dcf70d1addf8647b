// Thermal network of the ventilated 48 V pack: cells -> enclosure air -> housing wall -> ambient,
// and, with the fans on, enclosure air -> ambient by the ventilation flow (pack_ventilation.hpp).
// ROS-free, deterministic, no allocation in step().
//
// Two thermal masses: the cells (T_c, C_c = N m_cell c_p,cell) and the housing wall (T_w,
// C_w = m_housing c_p,housing). The enclosure air is a massless node (its heat capacity,
// ~0.05 m^3 x 1.2 kg/m^3 x 1007 J/(kg K) = 60 J/K, is ~0.1 % of the cells'; its time constant is a
// few seconds).
//
//   C_c dT_c/dt = Q_c + a_c Q_f - G_i (T_c - T_w) - G_cv (T_c - T_amb)                    [W]
//   C_w dT_w/dt = G_i (T_c - T_w) + a_w Q_f - (G_o + G_wv)(T_w - T_amb)                  [W]
//
// Q_c: the cells' losses [W]; Q_f: the fan's electric power, dissipated in the enclosure air [W].
// Inside: G_ca = h_c A_cells (cells -> air), G_aw = h_wi A_w (air -> wall), h_c, h_wi natural
// convection (fan off) or fan-forced values (fan on); radiation cells -> wall in parallel,
//   G_r = h_ri A_w,  h_ri = 4 sigma T_m^3 / (1/eps_c + 1/eps_w - 1)   (linearised exchange
//                                        between parallel grey surfaces at the mean temperature T_m)
// Ventilation (fans on): ambient air enters at T_amb and leaves at the enclosure air temperature
//   (well mixed), carrying G_v (T_air - T_amb), G_v = m_dot c_p (pack_ventilation.hpp); 0 fan off.
// The massless air node's balance G_ca (T_c - T_air) + Q_f = G_aw (T_air - T_w) + G_v (T_air - T_amb):
//   T_air = (G_ca T_c + G_aw T_w + G_v T_amb + Q_f)/S,  S = G_ca + G_aw + G_v.
// Eliminating T_air (star-delta transform of the air node) gives the conductances of the ODEs above:
//   G_i = G_ca G_aw/S + G_r (cells -> wall),  G_cv = G_ca G_v/S (cells -> ambient through the air),
//   G_wv = G_aw G_v/S (wall -> ambient through the air); the fan heat reaches the cells with the
//   share a_c = G_ca/S, the wall with a_w = G_aw/S and leaves with the air with a_v = G_v/S.
// Ventilation heat (leaving with the air) [W]: G_v (T_air - T_amb) = G_cv (T_c - T_amb)
//   + G_wv (T_w - T_amb) + a_v Q_f.
// Outside, wall -> ambient air [W/K]: G_o = A_w (h_o + h_ro), h_ro = 4 eps_w sigma T_m^3,
//   h_o = (h_nat^3 + h_forced^3)^(1/3)   (Churchill-Usagi combination of free and forced
//                                          convection, n = 3; Incropera 6th ed. eq. 9.54)
//   h_forced = Nu k/L, Re = v L/nu, flat plate parallel to the flow (Incropera eqs. 7.30, 7.38):
//     Re <= 5e5: Nu = 0.664 Re^(1/2) Pr^(1/3);  Re > 5e5: Nu = (0.037 Re^(4/5) - 871) Pr^(1/3)
//   v = air speed over the housing = vehicle speed (a roof-mounted pack in the free stream).
//
// One step of length h, conductances and heat inputs held (they are set at the start of the step):
// x = (T_c, T_w), dx/dt = A x + b is linear with constant coefficients, solved exactly:
//   A = [[-(G_i + G_cv)/C_c, G_i/C_c], [G_i/C_w, -(G_i + G_o')/C_w]],  G_o' = G_o + G_wv
//   x_inf: the steady state, u = T_c,inf - T_amb, w = T_w,inf - T_amb from
//     (G_i + G_cv) u - G_i w = Q_c + a_c Q_f,   -G_i u + (G_i + G_o') w = a_w Q_f   (Cramer)
//   x(h) = x_inf + E y0,  y0 = x(0) - x_inf,  E = e^{A h}
//   ∫_0^h (x - x_inf) dt = J y0,  J = ∫_0^h e^{A s} ds
// A has two real, distinct, negative eigenvalues (G_i, G_o > 0: det A > 0 and the discriminant
// (a11 - a22)^2/4 + a12 a21 > 0), so by Sylvester's formula with divided differences
//   E = e^{l1 h} I + phi[l1,l2] (A - l1 I),  phi[l1,l2] = h e^{m h} sinh(d h)/(d h)
//   J = psi(l1) I + psi[l1,l2] (A - l1 I),   psi(l) = (e^{l h} - 1)/l
//   (m = (l1 + l2)/2, d = (l1 - l2)/2; no cancellation in phi[]).
// Heat over the step (exact integrals): through the housing Q_amb = G_o [w h + (J y0)_w];
//   with the air Q_vent = G_cv [u h + (J y0)_c] + G_wv [w h + (J y0)_w] + a_v Q_f h.
// Energy: (Q_c + Q_f) h = C_c ΔT_c + C_w ΔT_w + Q_amb + Q_vent for every step (tested to round-off).
// Overall conductance cells -> ambient (Q_f = 0, steady state): G = Q_c/u = det/(G_i + G_o'),
//   det = (G_i + G_cv)(G_i + G_o') - G_i^2  (G_v = 0: 1/(1/G_i + 1/G_o)).
#pragma once

#include "battery/pack_ventilation.hpp"

namespace hbt::battery {

/// Conductances of the network for one step [W/K] and the fan heat shares [-].
struct PackConductances {
  double cells_to_air_W_K = 0.0;   // G_ca
  double air_to_wall_W_K = 0.0;    // G_aw
  double radiation_in_W_K = 0.0;   // h_ri A_w
  double ventilation_W_K = 0.0;    // G_v = m_dot c_p (0 with the fans off)
  double inner_W_K = 0.0;          // G_i (cells -> wall, after eliminating the air node)
  double cells_vent_W_K = 0.0;     // G_cv
  double wall_vent_W_K = 0.0;      // G_wv
  double outer_W_K = 0.0;          // G_o (housing surface -> ambient)
  double overall_W_K = 0.0;        // cells -> ambient in steady state
  double share_cells = 0.0, share_wall = 0.0, share_vent = 0.0;  // a_c, a_w, a_v of the fan heat
};

/// Geometry, materials and heat-transfer coefficients of the enclosure (config/battery.yaml enclosure/).
struct PackThermalParams {
  double cells_area_m2 = 9.27;         // cell surface in the enclosure air [m^2]
  double cells_heat_capacity_J_K = 5.24e4;  // C_c [J/K]
  double housing_area_m2 = 1.08;       // A_w, inner = outer surface of the housing [m^2]
  double housing_heat_capacity_J_K = 7.9e3; // C_w [J/K]
  double h_cells_natural_W_m2K = 4.0, h_cells_fan_W_m2K = 20.0;
  double h_wall_inside_natural_W_m2K = 4.0, h_wall_inside_fan_W_m2K = 20.0;
  double h_outside_natural_W_m2K = 4.0;
  double emissivity_cells = 0.9, emissivity_housing = 0.9;
  double radiation_mean_temperature_K = 300.0;  // T_m of the linearised radiation
  double flow_length_m = 0.75;         // L, housing length along the flow
  double air_conductivity_W_mK = 0.0263, air_viscosity_m2_s = 15.89e-6, air_prandtl = 0.707;
  PackVentilationParams ventilation;   // fans, vents and filter (pack_ventilation.hpp)
};

class PackThermal {
 public:
  explicit PackThermal(const PackThermalParams& p) : p_(p), vent_(p.ventilation) {}
  /// Conductances with the fan on or off at air speed v_air_m_s over the housing, ambient T_amb_K.
  PackConductances conductances(bool fan_on, double v_air_m_s, double T_amb_K) const;
  /// Forced-convection coefficient of the housing's outer surface at air speed v [W/(m^2 K)].
  double forcedOutsideH(double v_air_m_s) const;
  /// Both masses at T_K.
  void reset(double T_K) { reset(T_K, T_K); }
  /// Cells at cells_T_K, housing (and air) at housing_T_K.
  void reset(double cells_T_K, double housing_T_K);
  /// Advances by h with the cells' loss Q_cells_W, the fan heat Q_fan_W, ambient T_amb_K held.
  void step(double h, double Q_cells_W, double Q_fan_W, double T_amb_K, bool fan_on, double v_air_m_s);
  double cellsT_K() const { return Tc_; }
  double housingT_K() const { return Tw_; }
  double airT_K() const { return T_air_; }                 // enclosure air at the end of the step
  double heatToAmbient_J() const { return Q_amb_step_; }   // through the housing, over the last step
  double ventilationHeat_J() const { return Q_vent_step_; } // with the ventilation air, last step
  double cellsToWall_J() const { return Q_cw_step_; }      // over the last step (incl. radiation)
  /// Heat stored in both masses since reset [J].
  double storedHeat_J() const {
    return p_.cells_heat_capacity_J_K * (Tc_ - Tc0_) + p_.housing_heat_capacity_J_K * (Tw_ - Tw0_);
  }
  const PackThermalParams& params() const { return p_; }
  const PackVentilation& ventilation() const { return vent_; }

 private:
  PackThermalParams p_;
  PackVentilation vent_;
  double Tc_ = 298.15, Tw_ = 298.15, T_air_ = 298.15;
  double Tc0_ = 298.15, Tw0_ = 298.15;  // at reset
  double Q_amb_step_ = 0.0, Q_vent_step_ = 0.0, Q_cw_step_ = 0.0;
};

}  // namespace hbt::battery
