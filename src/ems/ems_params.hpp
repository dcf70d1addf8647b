// Parameters of the energy manager (config/ems.yaml). Units in every name; SI inside.
#pragma once
#include <string>

#include "common/params.hpp"
#include "common/units.hpp"

namespace hbt::ems {

/// Adaptive ECMS (equivalent consumption minimisation) with SOC feedback.
struct EcmsParams {
  double equivalence_factor = 2.6;      // s0 [-]: value of 1 J of battery energy in J of fuel
  double soc_target = 0.5;              // charge-sustaining target [-]
  double soc_kp = 10.0;                 // s = s0 + kp (soc_target - soc) + ki ∫(soc_target - soc) dt
  double soc_ki_per_s = 0.01;           // [1/s]
  double s_min = 1.0, s_max = 6.0;      // clamp of s [-]
  double soc_min = 0.3;                 // no boost below [-]
  double soc_max = 0.7;                 // no load-point shift (charging) above [-]
  int candidates = 41;                  // EM torques tried per step (grid over the feasible range)
  double em_motor_efficiency = 0.88;    // controller's estimate: DC power = T ω / η (motoring)
  double em_generator_efficiency = 0.88;  // DC power = T ω η (generating)
  double min_boost_torque_Nm = 5.0;     // smaller optimum EM torques are set to 0 (no dithering)
};

struct RegenParams {
  double min_engine_speed_rad_s = 62.8; // no regeneration below (600 rpm: gearbox downshifts)
};

/// Warm-up inhibit (SPEC §6): no boost and no stop-start while the engine or the ATS warm up.
struct WarmupParams {
  double coolant_warm_K = 343.15;       // engine warm from this HT coolant temperature (70 °C)
  double scr_warm_K = 473.15;           // ATS warm from this SCR brick temperature (200 °C)
};

struct BatteryLimitParams {
  double assist_derate_start_K = 313.15;  // electric assist reduced from 40 °C ...
  double assist_zero_K = 318.15;          // ... to zero at 45 °C (SPEC §6)
  double limit_margin = 0.005;            // share of the pack's power limits kept free [-]
};

struct StopStartParams {
  bool enabled = true;
  double soc_min_to_stop = 0.40;        // engine stays on below this SOC [-]
  double soc_restart = 0.30;            // a stopped engine restarts below this SOC [-]
  double min_on_time_s = 3.0;           // engine runs at least this long after a start [s]
  double crank_torque_Nm = 300.0;       // e-machine torque at the crank while cranking [Nm]
  double firing_speed_rad_s = 41.9;     // injection starts at this crank speed (400 rpm) [rad/s]
  double max_crank_time_s = 2.0;        // a start that takes longer stops the run (ModelDivergence)
  double min_discharge_power_W = 8000.0;  // the battery must offer this to stop the engine [W]
};

struct EmsParams {
  EcmsParams ecms;
  RegenParams regen;
  WarmupParams warmup;
  BatteryLimitParams battery;
  StopStartParams stop_start;
  void declare(ParamSet& ps);
  void validate(const std::string& file) const;
};

}  // namespace hbt::ems
