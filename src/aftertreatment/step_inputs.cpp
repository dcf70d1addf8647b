#include "aftertreatment/step_inputs.hpp"

#include <algorithm>

#include "common/step_mean.hpp"

namespace hbt::aftertreatment {

void StepInputs::exhaustGas(const InputTotals& now, double dt_s, AtsInputs& in) const {
  const WeightedMean T = weightedMean(now.exhaust_mass_T_kg_K, prev_.exhaust_mass_T_kg_K,
                                      now.exhaust_mass_kg, prev_.exhaust_mass_kg);
  if (!T.resolved) {  // no flow: the time-mean temperature, the sample's composition
    in.exhaust_T_K = meanRate(now.exhaust_T_time_K_s, prev_.exhaust_T_time_K_s, dt_s);
    return;
  }
  in.exhaust_T_K = T.value;
  const auto fraction = [&](double now_kg, double prev_kg) {
    return std::clamp(weightedMean(now_kg, prev_kg, now.exhaust_mass_kg, prev_.exhaust_mass_kg).value,
                      0.0, 1.0);
  };
  in.comp.y_O2 = fraction(now.o2_kg, prev_.o2_kg);
  in.comp.y_CO2 = fraction(now.co2_kg, prev_.co2_kg);
  in.comp.y_H2O = fraction(now.h2o_kg, prev_.h2o_kg);
}

AtsInputs StepInputs::next(const InputTotals& now, const AtsInputs& point, double dt_s) {
  AtsInputs in = point;
  if (started_ && dt_s > 0.0) {
    in.exhaust_mass_flow_kg_s = std::max(0.0, meanRate(now.exhaust_mass_kg, prev_.exhaust_mass_kg, dt_s));
    exhaustGas(now, dt_s, in);
    in.nox_mass_flow_kg_s = std::max(0.0, meanRate(now.nox_kg, prev_.nox_kg, dt_s));
    in.hc_mass_flow_kg_s = std::max(0.0, meanRate(now.hc_kg, prev_.hc_kg, dt_s));
    in.co_mass_flow_kg_s = std::max(0.0, meanRate(now.co_kg, prev_.co_kg, dt_s));
    in.vehicle_speed_m_s = std::max(0.0, meanRate(now.distance_m, prev_.distance_m, dt_s));
  }
  in.exhaust_mass_flow_kg_s = std::max(0.0, in.exhaust_mass_flow_kg_s);
  const double y_named = in.comp.y_O2 + in.comp.y_CO2 + in.comp.y_H2O;
  in.comp.y_N2 = std::max(0.0, 1.0 - y_named);
  prev_ = now;
  started_ = true;
  return in;
}

}  // namespace hbt::aftertreatment
