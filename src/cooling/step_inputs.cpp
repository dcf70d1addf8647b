#include "cooling/step_inputs.hpp"

#include <algorithm>

#include "common/step_mean.hpp"

namespace hbt::cooling {

CoolingInputs StepInputs::next(const CoolingTotals& now, const CoolingInputs& point, double dt_s) {
  CoolingInputs in = point;
  if (started_ && dt_s > 0.0) {
    in.engine_heat_W = meanRate(now.engine_heat_J, prev_.engine_heat_J, dt_s);
    in.engine_oil_heat_W = meanRate(now.engine_oil_heat_J, prev_.engine_oil_heat_J, dt_s);
    in.pump_speed_rad_s = std::max(0.0, meanRate(now.pump_angle_rad, prev_.pump_angle_rad, dt_s));
    in.lt_heat_W = meanRate(now.lt_heat_J, prev_.lt_heat_J, dt_s);
    in.em_engine_heat_W = meanRate(now.em_engine_heat_J, prev_.em_engine_heat_J, dt_s);
    in.aux_heater_heat_W = meanRate(now.aux_heater_heat_J, prev_.aux_heater_heat_J, dt_s);
    in.gearbox_cooler_heat_W = meanRate(now.gearbox_cooler_heat_J, prev_.gearbox_cooler_heat_J, dt_s);
  }
  prev_ = now;
  started_ = true;
  return in;
}

}  // namespace hbt::cooling
