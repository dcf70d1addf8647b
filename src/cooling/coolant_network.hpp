// Thermal network of the engine, its HT coolant volumes and the LT circuit, advanced over one
// substep by backward Euler with its coefficients frozen. ROS-free, no allocation.
//
// Nodes (θ = T - T_a [K], C in J/K, G and W in W/K, Q̇ in W):
//   m  engine metal: block, head, liners        C_m = m_metal c_metal
//   o  engine oil: sump, galleries, oil cooler  C_o = m_oil c_oil
//   c  engine loop: jacket, pump, thermostat housing, bypass, short pipes; its temperature is
//      the engine outlet ("the" HT coolant temperature: thermostat, fan, heater valve, EMS)
//   r  radiator volume: radiator core, tanks and its pipes (fed from c at the radiator flow)
//   v  convector volume: heater loop pipes and the passenger-compartment convectors (fed from c
//      at the heater-loop flow)
//   l  LT coolant + e-drive housings
//
//   C_m dθ_m/dt = Q̇_eng - G_mc (θ_m - θ_c) - G_om (θ_m - θ_o) - G_s θ_m
//   C_o dθ_o/dt = Q̇_oil + G_om (θ_m - θ_o) - G_oc (θ_o - θ_c)
//   C_c dθ_c/dt = G_mc (θ_m - θ_c) + G_oc (θ_o - θ_c) - W_r (θ_c - θ_r) - W_v (θ_c - θ_v) + Q̇_aux
//   C_r dθ_r/dt = W_r (θ_c - θ_r) - Q̇_rad,HT,     Q̇_rad,HT = G_HT (θ_c - p θ_l)
//   C_v dθ_v/dt = W_v (θ_c - θ_v) - Q̇_h + Q̇_loop,  Q̇_h = q_h + g_h θ_v
//   C_l dθ_l/dt = Q̇_LT - Q̇_rad,LT,                Q̇_rad,LT = G_LT θ_l
// W_r = ṁ_rad c_p and W_v = ṁ_heater c_p are the capacity rates of the coolant exchanged with
// the engine loop (well-mixed nodes: what leaves a node leaves at its temperature). The radiator
// is quasi-steady and driven by its inlet, the engine outlet (ε-NTU with inlet temperature
// T_c and air inlet T_a + p θ_l behind the LT radiator, radiator.hpp); its heat leaves the
// radiator volume, which holds the coolant between inlet and return. Since G_HT = ε C_min <=
// W_r, the radiator volume never falls below the air inlet temperature. The convectors are
// driven by the mean temperature of the water they hold (θ_v): their heat leaves the convector
// volume, also when the loop does not circulate (stagnant water cooled by the convector fans).
// Q̇_aux: heat into the engine loop (the automatic gearbox's oil cooler). Q̇_loop: heat into the
// heater loop (the fuel-fired water heater, in the heating circuit ahead of the convectors). Q̇_eng: the engine's
// heat into its metal (combustion heat through the walls, the friction of the piston rings and
// skirts on the liners); Q̇_oil: the friction heat the oil carries away from the bearings and the
// valve train. The oil gives its heat to the coolant through the engine's oil cooler (plate
// cooler in the engine loop, G_oc) and exchanges heat with the crankcase, block and pistons it
// is sprayed on and drains over (G_om).
//
// Backward Euler over h: (C/h + K) θ_new = C/h θ_old + sources, a 6x6 linear system
// (Eigen, partial-pivot LU). The fluxes are evaluated with θ_new, so that
//   h (Q̇_eng + Q̇_oil + Q̇_aux + Q̇_loop + Q̇_LT - Q̇_rad,HT - Q̇_rad,LT - Q̇_h - G_s θ_m) = Σ C (θ_new - θ_old)
// holds to round-off (the exchange terms W, G_mc, G_om and G_oc cancel pairwise).
#pragma once
#include <Eigen/Dense>

namespace hbt::cooling {

/// Node heat capacities [J/K].
struct NetworkCapacities {
  double metal = 0.0, engine_loop = 0.0, radiator = 0.0, convector = 0.0, lt = 0.0, oil = 0.0;
  double coolantHt() const { return engine_loop + radiator + convector; }
};

/// Coefficients of one substep (frozen).
struct NetworkCoefficients {
  double G_mc = 0.0;       // water-jacket conductance metal -> engine loop [W/K]
  double G_s = 0.0;        // engine surface -> ambient [W/K]
  double G_om = 0.0;       // oil <-> metal (crankcase, block, pistons) [W/K]
  double G_oc = 0.0;       // oil cooler oil -> engine loop [W/K]
  double W_rad = 0.0;      // radiator flow capacity rate ṁ_rad c_p [W/K]
  double W_heater = 0.0;   // heater-loop flow capacity rate ṁ_h c_p [W/K]
  double G_ht = 0.0;       // HT radiator conductance ε C_min [W/K]
  double preheat = 0.0;    // HT air inlet rise per K of LT coolant, G_LT/C_air [-]
  double G_lt = 0.0;       // LT radiator conductance [W/K]
  double q_heater = 0.0;   // heater: constant part of its heat [W]
  double g_heater = 0.0;   // heater: conductance on the convector temperature [W/K]
  double Q_engine = 0.0, Q_aux = 0.0, Q_lt = 0.0;  // heat into metal, engine loop, LT [W]
  double Q_oil = 0.0;      // heat into the oil (its share of the engine's friction) [W]
  double Q_loop = 0.0;     // heat into the heater loop (fuel-fired heater) [W]
};

/// Node temperatures [K].
struct NetworkState {
  double metal = 0.0, engine_loop = 0.0, radiator = 0.0, convector = 0.0, lt = 0.0, oil = 0.0;
};

/// Heat flows of one implicit update [W] (evaluated with the new temperatures).
struct NetworkFluxes {
  double radiator_ht = 0.0, radiator_lt = 0.0, heater = 0.0, surface = 0.0;
  double to_radiator = 0.0;   // W_r (θ_c - θ_r): engine loop -> radiator volume
  double to_convector = 0.0;  // W_v (θ_c - θ_v): engine loop -> convector volume
  double oil_cooler = 0.0;    // G_oc (θ_o - θ_c): oil -> engine loop through the oil cooler
  double oil_to_metal = 0.0;  // G_om (θ_o - θ_m): oil -> metal
};

class CoolantNetwork {
 public:
  CoolantNetwork() = default;
  explicit CoolantNetwork(const NetworkCapacities& c) : C_(c) {}
  const NetworkCapacities& capacities() const { return C_; }
  /// Advances the temperatures T [K] over h [s] at ambient T_a [K] with the coefficients k;
  /// returns the fluxes of the update.
  NetworkFluxes step(double h, double T_a, const NetworkCoefficients& k, NetworkState& T) const;
  /// Σ C (T - T_0) of the nodes [J]: heat stored since the state T0.
  double storedSince_J(const NetworkState& T, const NetworkState& T0) const;

 private:
  NetworkCapacities C_;
};

}  // namespace hbt::cooling
