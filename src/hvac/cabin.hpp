// Heat balance of the passenger compartment of the bus: one thermal node holding the interior
// air and the interior mass (seats, panels, floor) at the cabin temperature T [K]. ROS-free.
//
//   C dT/dt = Q̇_heat - Q̇_cool + Q̇_gain - (UA + (ṁ_fresh + ṁ_door) c_p) (T - T_a)        [W]
//   C       = ρ_ref V c_p + C_interior      (air at 20 °C, 1 atm: ρ_ref = p_0/(R 293.15 K)) [J/K]
//   UA      = U · 2 (L W + L H + W H)       (body envelope, VECTO SSM's surface)            [W/K]
//   ṁ_fresh = ρ_a n V / 3600,  ρ_a = p_a/(R T_a)                                           [kg/s]
//   ṁ_door  = ρ_a N (C_d/3) W_d H_d sqrt(g H_d |T - T_a| / T̄),  T̄ = (T + T_a)/2, doors open
//             (two-way buoyancy exchange through a large vertical opening, ASHRAE Handbook –
//             Fundamentals, ch. "Ventilation and infiltration"; 0 with the doors shut)    [kg/s]
// Q̇_heat: heat of the coolant convectors, Q̇_cool: heat the A/C evaporator removes, Q̇_gain:
// passengers + sun (cabin_gains.hpp), all held over the step; T_a ambient [K].
//
// Integration: the coefficients are frozen over a step (the door flow at the step's start
// temperature), and the linear ODE is advanced by its exact solution
//   G = UA + (ṁ_fresh + ṁ_door) c_p,  T_eq = T_a + Q̇_net/G,  T(t+h) = T_eq + (T - T_eq) e^{-hG/C},
// so a constant input gives the exact first-order response. The losses of the step are booked
// from the exact integral ∫(T - T_a) dt = (Q̇_net h - C ΔT)/G, split by conductance: in - out -
// C ΔT = 0 to round-off.
#pragma once
#include <string>

#include "hvac/hvac_params.hpp"

namespace hbt::hvac {

struct CabinInputs {
  double ambient_T_K = 298.15;
  double ambient_p_Pa = units::kStandardAtmosphere_Pa;
  double heat_W = 0.0;       // from the coolant convectors [W] (>= 0)
  double cool_W = 0.0;       // removed by the A/C evaporator [W] (>= 0)
  double gain_W = 0.0;       // passengers + sun [W]
  bool doors_open = false;
};

/// Conductances to the ambient at a state [W/K].
struct CabinConductance {
  double body_W_K = 0.0, fresh_air_W_K = 0.0, doors_W_K = 0.0;
  double total() const { return body_W_K + fresh_air_W_K + doors_W_K; }
};

/// Mean heat flows of one step [W] (losses > 0 leave the cabin).
struct CabinFlows {
  double body_W = 0.0, fresh_air_W = 0.0, doors_W = 0.0;
  double door_mass_flow_kg_s = 0.0, fresh_air_mass_flow_kg_s = 0.0;
};

class Cabin {
 public:
  Cabin(const CabinParams& c, const DoorParams& d, const AirParams& a);
  void reset(double T_K) { T_K_ = T_K; }
  double temperature_K() const { return T_K_; }
  double heatCapacity_J_K() const { return C_J_K_; }
  double bodyUA_W_K() const { return UA_W_K_; }
  /// Conductances at cabin temperature T_K with the inputs' ambient and doors.
  CabinConductance conductance(const CabinInputs& in, double T_K) const;
  /// Advances by dt_s with the inputs held (exact solution with frozen coefficients).
  CabinFlows step(double dt_s, const CabinInputs& in);

 private:
  double freshAirMassFlow_kg_s(const CabinInputs& in) const;
  double doorMassFlow_kg_s(const CabinInputs& in, double T_K) const;
  CabinParams c_;
  DoorParams d_;
  AirParams a_;
  double C_J_K_ = 0.0, UA_W_K_ = 0.0;
  double T_K_ = 293.15;
};

}  // namespace hbt::hvac
