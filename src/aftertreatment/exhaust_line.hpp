// The walls of the exhaust line as a series of lumped walls (exhaust manifold, turbine housing,
// down-pipe, pipe to the one-box, the box's inlet chamber; or one chamber of the box): each
// stores heat, takes it from the gas by convection and loses it to the surrounding air.
// ROS-free; no allocation after construction.
//
// Segment i: wall heat capacity C_i = m_i c_i [J/K], gas path of length L_i and hydraulic
// diameter D_i, wetted inner area A_i (pi D_i L_i for a pipe; a chamber's sheet and baffles),
// outer area A_out,i.
//   gas side:  Re = 4 mdot / (pi D mu(Tg)),  h = Nu k(Tg) / D  (gas properties at the temperature
//              of the gas entering the segment, gas.hpp), Nu = max(Nu_lam, Nu_turb) with
//              - upstream of the turbine (pulsating = true): Nu_turb = c_p Re^m_p, the
//                correlation of Depcik & Assanis (SAE 2002-01-0372) fitted to measured exhaust
//                manifold heat transfer: the pulsation of the exhaust blow-down and the bends and
//                entrance lengths of a manifold are inside its coefficient; the flow is taken at
//                its cycle-mean mass flow;
//              - downstream of the turbine (pulsating = false): Nu_turb = c Re^m Pr^n
//                (Dittus-Boelter, fully developed turbulent pipe flow, n = 0.3 for a cooled
//                gas; Incropera & DeWitt eq. 8.60): the turbine damps the pulsation;
//              - Nu_lam = 3.66 (fully developed laminar flow, constant wall temperature) as the
//                lower bound at idle flows;
//              NTU = h A / (mdot cp), G = mdot cp (1 - exp(-NTU)) [W/K].
//   outer:     UA = A_out / (t_ins / k_ins + 1 / h_ext), h_ext = natural + linearised radiation +
//              Hilpert cross flow at air_speed_factor x vehicle speed on a cylinder of diameter
//              D_out = A_out / (pi L) (lumped_wall.hpp).
//   wall:      C dT/dt = G (Tg_in - T) - UA (T - T_amb), integrated exactly over the step with
//              inputs held (lumped_wall.hpp); the gas leaves at the step mean
//              Tg_out = Tg_in - G (Tg_in - Tbar) / (mdot cp), so that the energy of every step
//              closes to round-off: mdot cp (Tg_in - Tg_out) dt = C (T1 - T0) + UA (Tbar - T_amb) dt.
//   steady state (analytic): T_w = (G Tg_in + UA T_amb)/(G + UA),
//              Tg_out = T_w + (Tg_in - T_w) exp(-NTU).
// Without flow the gas carries no enthalpy and the walls cool through their outer surface alone.
// The segments are swept in flow direction: the outlet of segment i is the inlet of segment i+1.
#pragma once
#include <string>
#include <vector>

#include "aftertreatment/ats_params.hpp"
#include "aftertreatment/brick.hpp"

namespace hbt::aftertreatment {

class ExhaustLine {
 public:
  /// names[i] and segments[i] in flow direction; nusselt laws of `line`.
  ExhaustLine(std::vector<std::string> names, std::vector<PipeSegmentParams> segments,
              const LineParams& line, double h_natural_W_m2K);

  void setUniformTemperature(double T_K);
  /// One step; gas enters at Tg_in. Returns the outlet gas temperature (step mean); adds the
  /// step's gas-to-wall heat, outer loss (can_loss_J) and stored change to e. Throws
  /// ModelDivergence on a non-physical wall temperature.
  double step(double dt, double mdot_kg_s, double cp, double Tg_in_K, double T_amb_K,
              double vehicle_speed_m_s, BrickEnergy& e);

  int segments() const { return static_cast<int>(seg_.size()); }
  const std::string& name(int i) const { return names_[i]; }
  double T(int i) const { return T_[i]; }
  double heatCapacity(int i) const { return C_[i]; }   ///< [J/K]
  double energyStored() const;                          ///< sum C_i T_i [J]
  /// Gas-side Nusselt number and conductance h A [W/K] of segment i (gas at Tg_K).
  double nusselt(int i, double mdot_kg_s, double Tg_K) const;
  double gasSideHA(int i, double mdot_kg_s, double Tg_K) const;
  /// Outer conductance [W/K] of segment i at wall temperature T_wall_K.
  double outerUA(int i, double T_wall_K, double T_amb_K, double vehicle_speed_m_s) const;

 private:
  std::vector<std::string> names_;
  std::vector<PipeSegmentParams> seg_;
  LineParams line_;
  double h_natural_;
  std::vector<double> C_, T_;
};

}  // namespace hbt::aftertreatment
