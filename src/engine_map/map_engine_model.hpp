// The map-based engine behind the twin's engine interface (engine_interface/engine_model.hpp; launch
// engine:=map): forwards the inputs to MapEngine (map_engine.hpp, its equations) and its outputs
// to the model-neutral ones, nothing else.
//
// Mapping: inputs one to one (oil_T_K <= 0 and back_pressure_Pa <= 0 switch MapEngine's
// cold-oil and back-pressure corrections off, as MapEngineInputs documents; the coolant
// temperature is not used). Outputs:
//   max/min_torque_Nm   the live limits T_fl(ω) − ΔT and T_mot(ω) − ΔT, ΔT = ΔT_fric + ΔT_pump
//                       (the extra indicated torque of cold oil and back-pressure of the step)
//   boost, λ, charge air, exhaust flow/T/composition, NOx: the quasi-steady gas path
//   heat_to_coolant_W / heat_to_oil_W   Q_metal / Q_oil of the gas path (friction work split)
//   turbo_speed_rad_s   0 (no turbocharger in this model)
// Idle speed: MapEngineParams::idle_speed_rad_s (engine_map.yaml). boostLimited(m): the request
// above the PT1 dynamic full load by more than m while that limit is m below the static one.
#pragma once
#include <memory>
#include <string>

#include "engine_interface/engine_model.hpp"
#include "engine_map/map_engine.hpp"

namespace hbt::engine_map {

class MapEngineModel : public engine::EngineModel {
 public:
  /// Builds the MapEngine (data files relative to base_dir). Throws InputError (file, key).
  MapEngineModel(const MapEngineParams& p, const std::string& base_dir);

  const char* name() const override { return "map"; }
  double idleSpeed() const override { return engine_.params().idle_speed_rad_s; }
  double fullLoadTorque(double w) const override { return engine_.fullLoadTorque(w); }
  double motoringTorque(double w) const override { return engine_.motoringTorque(w); }
  bool boostLimited(double margin_Nm) const override;
  std::string boostLimitedMessage(double duration_s) const override;
  void diagnosticValues(std::vector<engine::EngineDiagnosticValue>& kv) override;
  /// The wrapped model (its own outputs: PT1 limit, fuel cut, cumulative fuel energy ...).
  const MapEngine& model() const { return engine_; }

 protected:
  void resetModel(const engine::EngineInputs& in) override;
  void stepModel(double dt_s, const engine::EngineInputs& in) override;

 private:
  void copyOutputs(double speed_rad_s);
  MapEngine engine_;
};

}  // namespace hbt::engine_map
