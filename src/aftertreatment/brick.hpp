// One aftertreatment brick (monolith substrate in its can): geometry, 1D-in-flow thermal model
// and pressure drop. ROS-free; no allocation after construction.
//
// Geometry (square cells): pitch p = 25.4 mm / sqrt(cpsi), wall w = mil * 25.4 um, channel width
// d = p - w (= hydraulic diameter), open frontal area OFA = (d/p)^2, geometric surface area per
// brick volume GSA = 4 d / p^2 [m^2/m^3], brick volume V = pi D^2/4 L.
// Heat capacity of slice i (N equal slices):
//   C_i = [V (1 - OFA) rho_w c_w + V m_wc c_wc + m_can c_can] / N                      [J/K]
// (substrate, washcoat and the can/mat lump share one temperature T_i, axial conduction in the
// wall is neglected).
//
// Thermal model of slice i, quasi-steady gas (gas heat capacity per slice ~ 0.3 J/K versus
// C_i ~ 1 kJ/K, residence time ~ 10 ms versus wall time constants of minutes):
//   gas:  mdot cp dTg/dx = h P (T_i - Tg)  ->  Tg_out = T_i + (Tg_in - T_i) exp(-NTU_i),
//         NTU_i = h A_i / (mdot cp),  A_i = GSA V / N,  h = Nu k(Tg_in,i) / d (gas conductivity at
//         the temperature of the gas entering the slice),
//         Nu = 2.98 (Shah & London, "Laminar flow forced convection in ducts", 1978: fully
//         developed laminar flow in a square duct at constant wall temperature; channel Re < 500).
//   wall: C_i dT_i/dt = G_i (Tg_in - T_i) + Qr_i - UA_i (T_i - T_amb),
//         G_i = mdot cp (1 - exp(-NTU_i))                                                   [W/K]
//         Qr_i = reaction heat released on slice i (from the chemistry of the step)           [W]
//   can:  UA_i = A_can,i / (t_ins/k_ins + 1/h_ext), A_can,i = pi (D + 2 t_ins) L/N f_can,
//         h_ext = h_nat + h_rad + h_forced(v): h_rad = 4 eps sigma T_m^3 (linearised around
//         T_m = (T_i + T_amb)/2), h_forced from Hilpert's cylinder in cross flow,
//         Nu_D = C Re^m Pr^(1/3) (C, m = 0.193, 0.618 for Re < 4e4; 0.027, 0.805 above;
//         Incropera & DeWitt, "Fundamentals of Heat and Mass Transfer", table 7.2), air speed
//         = underbody_air_factor * vehicle speed (lumped_wall.hpp).
// Over one step Tg_in, mdot, cp, Qr and h_ext are held constant and the linear wall ODE is
// integrated exactly: T_i(t) = T_eq + (T_i0 - T_eq) exp(-lambda t), lambda = (G+UA)/C. The gas
// outlet T is the step average Tg_out = Tg_in - G_i (Tg_in - Tbar_i) / (mdot cp), Tbar_i the
// time-mean wall temperature, so that the energy of the step closes exactly:
//   C_i (T_i1 - T_i0) = dt [G_i (Tg_in - Tbar_i) + Qr_i - UA_i (Tbar_i - T_amb)].
// Slices are swept from inlet to outlet (the outlet of slice i is the inlet of slice i+1).
//
// Pressure drop (laminar, Re_channel < 2000 at every operating point of a 7 L engine):
//   flow-through: dp = fRe/2 mu u L / d^2 + (K_c + (1 - OFA)^2) rho u^2 / 2,
//                 u = Vdot / (A OFA), fRe = 56.91 (Darcy, square duct, Shah & London);
//   wall-flow (DPF, Konstandopoulos & Johnson, SAE 890405, simplified): half the channels are
//     inlets (N_in = A / (2 p^2)), filtration area A_f = 4 d L N_in, wall velocity
//     u_w = Vdot / A_f, inlet-channel velocity u0 = Vdot / (N_in d^2);
//     dp = F mu u0 L / d^2            (inlet + outlet channel, velocity linear in x, F = 28.45)
//        + mu u_w w / k_wall           (Darcy, clean wall)
//        + mu u_w w_soot / k_soot      (soot cake, w_soot = m_soot / (rho_cake A_f))
//        + (K_c + (1 - OFA/2)^2) rho u0^2 / 2.
// The "laminar" part (everything proportional to mu Vdot) is reported separately.
#pragma once
#include <string>
#include <vector>

#include "aftertreatment/ats_params.hpp"

namespace hbt::aftertreatment {

struct HeatTransferParams {
  double nusselt = 2.98, insulation_thickness_m = 0.008, insulation_k_W_mK = 0.12;
  double h_natural_W_m2K = 5.0, can_emissivity = 0.8, underbody_air_factor = 0.5;
  double can_length_factor = 1.0;
};

struct DpfFlowParams {
  double soot_load_g_L = 2.0, wall_permeability_m2 = 5e-13, soot_permeability_m2 = 2e-14;
  double soot_cake_density_kg_m3 = 100.0;
};

/// Energy terms of one step of one brick [J].
struct BrickEnergy {
  double gas_to_wall_J = 0.0;  ///< convective heat from the gas
  double can_loss_J = 0.0;     ///< to ambient
  double reaction_J = 0.0;     ///< reaction heat deposited in the wall
  double stored_J = 0.0;       ///< change of the wall energy
};

struct PressureDrop {
  double laminar_Pa = 0.0;  ///< part proportional to mu Vdot
  double minor_Pa = 0.0;    ///< contraction/expansion (rho u^2)
  double total() const { return laminar_Pa + minor_Pa; }
};

class Brick {
 public:
  Brick(std::string name, const BrickParams& p, const HeatTransferParams& h, bool wall_flow);

  void setUniformTemperature(double T_K);
  /// One step of the wall temperatures; gas enters at Tg_in. qr_W[i]: reaction heat per slice.
  /// Returns the outlet gas temperature (step average). Throws ModelDivergence on NaN.
  double stepThermal(double dt, double mdot_kg_s, double cp, double Tg_in_K, const double* qr_W,
                     double T_amb_K, double air_speed_m_s, BrickEnergy& e);
  PressureDrop pressureDrop(double Vdot_m3_s, double T_K, double rho_kg_m3,
                            const DpfFlowParams* dpf, double contraction_k) const;

  const std::string& name() const { return name_; }
  int slices() const { return n_; }
  double T(int i) const { return T_[i]; }
  const std::vector<double>& temperatures() const { return T_; }
  double meanT() const;
  double heatCapacity() const { return C_slice_ * n_; }       ///< [J/K]
  double sliceHeatCapacity() const { return C_slice_; }        ///< [J/K]
  double volume() const { return V_; }                         ///< [m^3]
  double sliceVolume() const { return V_ / n_; }
  double wallArea() const { return gsa_ * V_; }                ///< gas-wall area [m^2]
  double channelWidth() const { return d_; }
  double openFrontalArea() const { return ofa_; }
  double frontalArea() const { return A_; }
  /// External (can) heat transfer coefficient incl. radiation [W/(m^2 K)].
  double externalH(double T_wall_K, double T_amb_K, double air_speed_m_s) const;
  /// Can conductance of one slice [W/K].
  double canUA(double T_wall_K, double T_amb_K, double air_speed_m_s) const;
  /// Gas-wall conductance h A of one slice [W/K], gas conductivity at Tg_K.
  double sliceHA(double Tg_K) const;

 private:
  std::string name_;
  BrickParams p_;
  HeatTransferParams h_;
  bool wall_flow_;
  int n_;
  double A_, V_, pitch_, w_, d_, ofa_, gsa_, C_slice_, A_can_slice_;
  std::vector<double> T_;
};

}  // namespace hbt::aftertreatment
