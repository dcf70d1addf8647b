#include "battery/pack_ventilation.hpp"

#include <cmath>

namespace hbt::battery {

PackVentilation::PackVentilation(const PackVentilationParams& p) : p_(p) {
  const double slope = p_.fan_max_pressure_Pa / (p_.fan_count * p_.fan_free_flow_m3_s);  // [Pa s/m^3]
  const double b = p_.linear_resistance_Pa_s_m3 + slope;
  const double c = p_.fan_max_pressure_Pa;
  flow_m3_s_ = 2.0 * c / (b + std::sqrt(b * b + 4.0 * p_.quadratic_resistance_Pa_s2_m6 * c));
}

double PackVentilation::pressure_Pa() const {
  return p_.fan_max_pressure_Pa * (1.0 - flow_m3_s_ / (p_.fan_count * p_.fan_free_flow_m3_s));
}

}  // namespace hbt::battery
