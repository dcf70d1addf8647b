#include "example_participant/trip_computer.hpp"

#include "common/units.hpp"

namespace hbt::example {

void TripComputerParams::declare(ParamSet& ps) {
  ps.add("min_distance_m", min_distance_m, "m", 0.0, 1e5, "consumption shown from this distance on");
  ps.add("standstill_speed_m_s", standstill_speed_m_s, "m/s", 0.0, 1.0, "below this the bus stands");
}

void TripComputer::update(double dt_s, const TripInputs& in) {
  out_.fuel_l = units::dieselLitres(in.fuel_mass_kg);
  out_.distance_km = in.distance_m / 1000.0;
  out_.shown = in.distance_m >= p_.min_distance_m;
  out_.consumption_l_100km = out_.shown ? out_.fuel_l / (in.distance_m / 1e5) : 0.0;
  const bool idling_at_standstill = in.vehicle_speed_m_s < p_.standstill_speed_m_s && in.engine_speed_rad_s > 0.0;
  out_.standstill_idle_s = idling_at_standstill ? out_.standstill_idle_s + dt_s : 0.0;
}

}  // namespace hbt::example
