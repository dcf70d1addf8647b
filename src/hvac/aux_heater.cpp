#include "hvac/aux_heater.hpp"

namespace hbt::hvac {

const AuxHeaterState& AuxHeater::step(double dt_s, double heater_water_T_K, bool heat_demanded) {
  if (!heat_demanded || heater_water_T_K > p_.off_above_K) s_.on = false;
  else if (heater_water_T_K < p_.on_below_K) s_.on = true;
  const bool burning = s_.on && p_.heat_output_W > 0.0;
  s_.heat_W = burning ? p_.heat_output_W : 0.0;
  s_.fuel_kg_s = s_.heat_W / (p_.efficiency * units::kDieselLhv_J_kg);
  s_.electric_W = burning ? p_.electric_power_W : 0.0;
  s_.heat_J += s_.heat_W * dt_s;
  s_.fuel_kg += s_.fuel_kg_s * dt_s;
  s_.electric_J += s_.electric_W * dt_s;
  return s_;
}

}  // namespace hbt::hvac
