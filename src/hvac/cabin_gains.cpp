#include "hvac/cabin_gains.hpp"

#include "common/errors.hpp"

namespace hbt::hvac {

CabinGains::CabinGains(const GainParams& g, const CabinParams& c, double payload_kg, const std::string& file)
    : g_(g), c_(c), irradiance_(g.solar_ambient_K, g.solar_irradiance_W_m2, file, "gains/solar_ambient_K") {
  if (!(payload_kg >= 0.0)) throw InputError(file, "payload_kg", "must be >= 0");
  persons_ = payload_kg / g_.mass_per_passenger_kg + g_.crew;
  window_m2_ = c_.window_area_per_length_m2_m * c_.length_m + c_.front_rear_window_area_m2;
}

double CabinGains::people_W(double T_a) const {
  return persons_ * (T_a < g_.person_boundary_ambient_K ? g_.heat_per_person_cold_W : g_.heat_per_person_warm_W);
}

double CabinGains::solar_W(double T_a) const {
  const double clouding = T_a < g_.person_boundary_ambient_K ? g_.clouding_cold : g_.clouding_warm;
  return irradiance_(T_a) * window_m2_ * c_.g_factor * clouding * c_.solar_orientation_factor;
}

}  // namespace hbt::hvac
