#include "aftertreatment/step_inputs.hpp"

#include <algorithm>

namespace hbt::aftertreatment {

AtsInputs StepInputs::next(const InputTotals& now, const AtsInputs& point, double dt_s) {
  AtsInputs in = point;
  if (started_ && dt_s > 0.0) {
    const double dm = now.exhaust_mass_kg - prev_.exhaust_mass_kg;
    in.exhaust_mass_flow_kg_s = std::max(0.0, dm / dt_s);
    if (dm > 0.0) {
      in.exhaust_T_K = (now.exhaust_mass_T_kg_K - prev_.exhaust_mass_T_kg_K) / dm;
      in.comp.y_O2 = (now.o2_kg - prev_.o2_kg) / dm;
      in.comp.y_CO2 = (now.co2_kg - prev_.co2_kg) / dm;
      in.comp.y_H2O = (now.h2o_kg - prev_.h2o_kg) / dm;
    } else {
      in.exhaust_T_K = (now.exhaust_T_time_K_s - prev_.exhaust_T_time_K_s) / dt_s;  // no flow
    }
    in.nox_mass_flow_kg_s = std::max(0.0, (now.nox_kg - prev_.nox_kg) / dt_s);
    in.hc_mass_flow_kg_s = std::max(0.0, (now.hc_kg - prev_.hc_kg) / dt_s);
    in.co_mass_flow_kg_s = std::max(0.0, (now.co_kg - prev_.co_kg) / dt_s);
    in.vehicle_speed_m_s = std::max(0.0, (now.distance_m - prev_.distance_m) / dt_s);
  }
  in.exhaust_mass_flow_kg_s = std::max(0.0, in.exhaust_mass_flow_kg_s);
  in.comp.y_N2 = 1.0 - in.comp.y_O2 - in.comp.y_CO2 - in.comp.y_H2O;
  prev_ = now;
  started_ = true;
  return in;
}

}  // namespace hbt::aftertreatment
