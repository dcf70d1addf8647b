// Trip computer: what a bus's on-board computer shows of the trip so far. The example participant
// of docs/adding_a_participant.md (a ROS-free model beside its thin node, as every participant).
//   fuel volume        V_f = m_f / (rho_f * 1e-3 m^3/L)      [L]      m_f: the engine's cumulative fuel [kg],
//                                                                       rho_f = units::kDieselDensity_kg_m3
//   consumption        c = V_f / (s / 100 km)                 [L/100 km], shown once s >= min_distance_m
//                                                                       (0 and shown = false before)
//   standstill idling  t_idle += dt while v < v_stand and the crank turns (omega > 0); 0 otherwise [s]
// Inputs are point samples of cumulative totals, so the figures are exact at every update,
// whatever the update period.
#pragma once
#include "common/params.hpp"

namespace hbt::example {

struct TripComputerParams {
  double min_distance_m = 1000.0;        ///< consumption shown from this distance on [m]
  double standstill_speed_m_s = 0.5 / 3.6;  ///< below this the bus stands [m/s] (0.5 km/h)
  void declare(ParamSet& ps);
};

struct TripInputs {
  double fuel_mass_kg = 0.0;        ///< cumulative fuel since t = 0 [kg]
  double distance_m = 0.0;          ///< travelled distance since t = 0 [m]
  double vehicle_speed_m_s = 0.0;   ///< [m/s]
  double engine_speed_rad_s = 0.0;  ///< crank speed [rad/s]
};

struct TripOutputs {
  double fuel_l = 0.0;               ///< fuel burnt [L]
  double distance_km = 0.0;          ///< [km]
  double consumption_l_100km = 0.0;  ///< [L/100 km]; 0 until shown
  bool shown = false;                ///< distance >= min_distance_m
  double standstill_idle_s = 0.0;    ///< the current standstill with the engine turning, so far [s]
};

class TripComputer {
 public:
  explicit TripComputer(const TripComputerParams& p) : p_(p) {}
  /// The figures after a period of dt_s [s] ending with the sample `in`.
  void update(double dt_s, const TripInputs& in);
  const TripOutputs& outputs() const { return out_; }

 private:
  TripComputerParams p_;
  TripOutputs out_;
};

}  // namespace hbt::example
