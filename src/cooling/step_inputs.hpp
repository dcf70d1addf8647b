// The cooling node's inputs over one of its macro steps (0.1 s) from its producers' cumulative
// totals, as the aftertreatment's (common/step_mean.hpp): the engine and the e-machine step every
// 10 ms, and the difference of two samples of a total is the exact mean of their 10 ms values
// over the step, Δt = t_now - t_prev:
//   Q̇_eng = ΔQ_eng / Δt     engine heat into its metal [W] (signed: the map engine books a
//                            negative exhaust residual to the coolant, gas_path.cpp)
//   Q̇_oil = ΔQ_oil / Δt     the engine's friction heat into its oil [W]
//   ω_pump = Δθ / Δt         mechanical HT pump speed = the crank's mean speed (1:1) [rad/s], >= 0
//   Q̇_LT = ΔQ_LT / Δt       e-machine + inverter heat into the LT coolant [W]
//   Q̇_em = ΔQ_em / Δt       heat the e-machine draws from the engine metal [W]
//   Q̇_gb = ΔQ_gb / Δt       the AT's oil cooler into the HT engine loop [W]
//   Q̇_aux = ΔQ_aux / Δt     fuel-fired heater's heat into the HT coolant [W] (hvac participant)
// An engine stop inside the step gives the mean of its running and stopped parts (the pump's
// flow falls with its mean speed, the heat with the fuel); a step wholly stopped gives 0 W and
// 0 rad/s exactly (the totals did not move). The first step (no earlier sample) takes the point
// values; the rest (vehicle speed, ambient, fan demand) are the sample's as they are.
#pragma once
#include "cooling/cooling_model.hpp"

namespace hbt::cooling {

/// Cumulative totals since t = 0 as the producers publish them (EngineHeat, EMachineState).
struct CoolingTotals {
  double engine_heat_J = 0.0;   // heat rejected by the engine into its metal [J]
  double engine_oil_heat_J = 0.0;  // the engine's friction heat into its oil [J]
  double pump_angle_rad = 0.0;  // angle turned by the HT pump [rad]
  double lt_heat_J = 0.0;       // heat into the LT coolant [J] (0 without an e-machine)
  double em_engine_heat_J = 0.0;  // heat the e-machine drew from the engine metal [J] (0 without one)
  double aux_heater_heat_J = 0.0;  // fuel-fired heater's heat into the HT coolant [J] (0 without hvac)
  double gearbox_cooler_heat_J = 0.0;  // the AT's oil cooler into the HT coolant [J] (VehicleToCooling)
};

class StepInputs {
 public:
  /// The inputs of the step that starts at the sample `now`, dt_s [s] after the previous one;
  /// `point` = the sample's instantaneous values (the first step; everything not averaged).
  CoolingInputs next(const CoolingTotals& now, const CoolingInputs& point, double dt_s);
  void reset() { started_ = false; }

 private:
  bool started_ = false;
  CoolingTotals prev_;
};

}  // namespace hbt::cooling
