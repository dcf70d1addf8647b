#include "ems/ems_params.hpp"

#include "common/errors.hpp"

namespace hbt::ems {

void EmsParams::declare(ParamSet& ps) {
  ps.setPrefix("ecms/");
  ps.add("equivalence_factor", ecms.equivalence_factor, "-", 0.5, 10.0, "s0: J fuel per J battery");
  ps.add("soc_target", ecms.soc_target, "-", 0.1, 0.9, "charge-sustaining SOC target");
  ps.add("soc_kp", ecms.soc_kp, "-", 0.0, 100.0, "SOC feedback gain on s");
  ps.add("soc_ki_per_s", ecms.soc_ki_per_s, "1/s", 0.0, 1.0, "SOC integral gain on s");
  ps.add("s_min", ecms.s_min, "-", 0.0, 10.0, "lower clamp of s");
  ps.add("s_max", ecms.s_max, "-", 0.5, 20.0, "upper clamp of s");
  ps.add("soc_min", ecms.soc_min, "-", 0.0, 1.0, "no boost below this SOC");
  ps.add("soc_max", ecms.soc_max, "-", 0.0, 1.0, "no charging by load-point shift above this SOC");
  ps.add("candidates", ecms.candidates, "-", 3, 1001, "EM torques tried per step");
  ps.add("em_motor_efficiency", ecms.em_motor_efficiency, "-", 0.3, 1.0, "controller's motoring efficiency");
  ps.add("em_generator_efficiency", ecms.em_generator_efficiency, "-", 0.3, 1.0, "controller's generating efficiency");
  ps.add("min_boost_torque_Nm", ecms.min_boost_torque_Nm, "Nm", 0.0, 100.0, "dead band of the split");
  ps.setPrefix("regen/");
  ps.add("min_engine_speed_rad_s", regen.min_engine_speed_rad_s, "rad/s", 0.0, 300.0, "no regeneration below");
  ps.setPrefix("warmup/");
  ps.add("coolant_warm_K", warmup.coolant_warm_K, "K", 273.15, 393.15, "engine warm from this coolant T");
  ps.add("scr_warm_K", warmup.scr_warm_K, "K", 273.15, 673.15, "ATS warm from this SCR brick T");
  ps.setPrefix("battery/");
  ps.add("assist_derate_start_K", battery.assist_derate_start_K, "K", 273.15, 343.15, "assist reduced from");
  ps.add("assist_zero_K", battery.assist_zero_K, "K", 273.15, 353.15, "no assist from");
  ps.add("limit_margin", battery.limit_margin, "-", 0.0, 0.2, "share of the pack's limits kept free");
  ps.setPrefix("stop_start/");
  ps.add("enabled", stop_start.enabled, "engine stop at standstill once warm");
  ps.add("soc_min_to_stop", stop_start.soc_min_to_stop, "-", 0.0, 1.0, "no stop below this SOC");
  ps.add("soc_restart", stop_start.soc_restart, "-", 0.0, 1.0, "restart below this SOC");
  ps.add("min_on_time_s", stop_start.min_on_time_s, "s", 0.0, 600.0, "least running time after a start");
  ps.add("crank_torque_Nm", stop_start.crank_torque_Nm, "Nm", 10.0, 2000.0, "EM cranking torque at the crank");
  ps.add("firing_speed_rad_s", stop_start.firing_speed_rad_s, "rad/s", 5.0, 100.0, "injection starts at");
  ps.add("max_crank_time_s", stop_start.max_crank_time_s, "s", 0.1, 30.0, "longest allowed start");
  ps.add("min_discharge_power_W", stop_start.min_discharge_power_W, "W", 0.0, 1e5, "battery power needed to stop");
  ps.setPrefix("");
}

void EmsParams::validate(const std::string& file) const {
  if (!(ecms.s_min < ecms.s_max)) throw InputError(file, "ecms/s_max", "must exceed ecms/s_min");
  if (!(ecms.soc_min < ecms.soc_max)) throw InputError(file, "ecms/soc_max", "must exceed ecms/soc_min");
  if (!(battery.assist_derate_start_K < battery.assist_zero_K))
    throw InputError(file, "battery/assist_zero_K", "must exceed battery/assist_derate_start_K");
  if (!(stop_start.soc_restart < stop_start.soc_min_to_stop))
    throw InputError(file, "stop_start/soc_restart", "must be below stop_start/soc_min_to_stop");
}

}  // namespace hbt::ems
