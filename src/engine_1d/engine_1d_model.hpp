// The crank-angle-resolved 1D engine behind the twin's engine interface (engine_interface/engine_model.hpp;
// launch engine:=1d): forwards the inputs to Engine1D (engine_1d.hpp, its equations) and its
// outputs to the model-neutral ones, nothing else.
//
// Mapping: inputs one to one, except coolant_T_K <= 0 (no cooling node) -> Engine1D's thermostat
// temperature kWarmCoolant_K (Engine1DInputs::coolant_T_K, 363.15 K: friction oil viscosity and
// wall temperatures of the warm engine); oil_T_K (the cooling node's oil) sets the Chen-Flynn
// friction's oil viscosity, <= 0 the coolant + the cylinder's oil offset; back_pressure_Pa <= 0 selects Engine1D's own orifice
// law of the exhaust system. The reset is warm as well (coolant kWarmCoolant_K). Outputs:
//   brake_torque_Nm     Engine1D's one-cycle mean while fuel is enabled; its crank torque (the
//                       mean over the step, compression pulses resolved; at rest the gas torque
//                       less friction) while the engine is off (fuel_enabled false: stopped by
//                       the EMS, spinning down, cranked by the e-machine): the torque the
//                       vehicle's crank dynamics integrate (engine_1d/README.md "Stop and restart")
//   positive/motoring_work_J  Σ of that published torque x ω Δt, split by sign (the interface's
//                       definition)
//   max/min_torque_Nm   the reference map's full-load and motoring torque at ω (warm, uncorrected)
//   friction/pumping_correction_Nm  0 (friction and pumping are inside the cycle simulation)
// Idle speed: the reference engine's MapEngineParams::idle_speed_rad_s (engine_map.yaml, the
// file engine_1d.yaml names as files/reference). boostLimited(): the smoke limiter holds the fuel.
#pragma once
#include <string>

#include "engine_interface/engine_model.hpp"
#include "engine_1d/engine_1d.hpp"

namespace hbt::engine_1d {

class Engine1DModel : public engine::EngineModel {
 public:
  /// Coolant temperature without a cooling node and at reset [K].
  static constexpr double kWarmCoolant_K = Engine1DInputs{}.coolant_T_K;

  /// Builds the Engine1D (turbo maps under repo_root/../shared). Throws InputError (file, key).
  Engine1DModel(const Engine1DParams& p, const std::string& repo_root);

  const char* name() const override { return "1d"; }
  double idleSpeed() const override { return engine_.params().reference.idle_speed_rad_s; }
  double fullLoadTorque(double w) const override { return engine_.fullLoadTorque(w); }
  double motoringTorque(double w) const override { return engine_.motoringTorque(w); }
  bool boostLimited(double margin_Nm) const override { return engine_.outputs().smoke_limited; }
  std::string boostLimitedMessage(double duration_s) const override;
  void diagnosticValues(std::vector<engine::EngineDiagnosticValue>& kv) override;
  /// The wrapped model (its own outputs: wastegate, peak pressure, sub-steps ...).
  const Engine1D& model() const { return engine_; }

 protected:
  void resetModel(const engine::EngineInputs& in) override;
  void stepModel(double dt_s, const engine::EngineInputs& in) override;

 private:
  void copyOutputs(double speed_rad_s, bool fuel_enabled);
  Engine1D engine_;
  long gas_steps_at_status_ = 0;  // coupled sub-steps counted at the last status
  double positive_work_J_ = 0.0, motoring_work_J_ = 0.0;  // of the published torque [J]
};

}  // namespace hbt::engine_1d
