// The engine as the twin sees it: one ROS-free interface over the engine models, so that one
// participant (../engine/node/engine_participant.hpp) runs either of them, picked by the factory
// ../engine/engine_factory.hpp. Implementations, each beside
// its model: engine_map::MapEngineModel (../engine_map/map_engine_model.hpp, launch engine:=map)
// and engine_1d::Engine1DModel (../engine_1d/engine_1d_model.hpp, engine:=1d).
//
// Governing equations: the model's own (map_engine.hpp: VECTO map + PT1 torque build-up +
// quasi-steady gas path; engine_1d.hpp: crank-angle-resolved 1D gas dynamics + 0D cylinders +
// turbocharger). What this interface fixes is the boundary, in SI units:
//   the crank speed ω [rad/s] is imposed (by the vehicle's crank dynamics); per step of Δt [s]
//   the model turns the torque request T_req [Nm] into the brake torque T_b it delivers within
//   its limits T_mot(ω) <= T_b <= T_fl(ω), and the fuel flow ṁ_f [kg/s], exhaust state, engine-out
//   NOx and heat to the cooling that go with it, split by where it enters: Q̇_m into the engine
//   metal (combustion heat through the walls, the piston rings' and skirts' friction on the
//   liners) and Q̇_o into the oil (the bearings' and valve train's friction) [W], so that every
//   friction work W_f ends as Q_m + Q_o (common/friction_heat.hpp); cumulative quantities integrate over the
//   steps since reset(): m_f = Σ ṁ_f Δt [kg], W+ = Σ max(T_b ω, 0) Δt, W- = Σ min(T_b ω, 0) Δt [J],
//   and (here, for both models) the exhaust totals of a slower consumer (the aftertreatment,
//   which takes their difference over its 0.1 s step as the exact mean of the 10 ms values):
//   m_exh = Σ ṁ Δt [kg], Σ ṁ T Δt [kg K], Σ T Δt [K s], m_i = Σ ṁ y_i Δt [kg] (O2, CO2, H2O),
//   with ṁ = max(ṁ_exh, 0) and each step's outputs (what is published at the step's end); and
//   the crank angle θ = Σ ω Δt [rad] (the mechanical coolant pump's mean speed, 1:1).
// Policies (one place: this class):
//   start     reset(): at the engine's idle speed idleSpeed() (engine_map.yaml idle_speed_rad_s,
//             the reference engine data both models read), brake torque 0, the given ambient
//             temperature and the standard atmosphere units::kStandardAtmosphere_Pa unless given.
//   ambient   EngineInputs::ambient_p_Pa <= 0 (a command without one) = the standard atmosphere.
//   loops     coolant_T_K <= 0 (no cooling node): the model's own warm default (map: the warm
//             map, no cold-oil correction; 1D: its thermostat temperature, Engine1DInputs);
//             oil_T_K: the cooling node's oil temperature, which sets the cold-oil friction of
//             both models; <= 0 (no cooling node): map the warm map, 1D coolant + its offset;
//             back_pressure_Pa <= 0 (no aftertreatment node): the model's own exhaust system
//             (map: the bench back-pressure of its map; 1D: its orifice law). Both are echoed in
//             the outputs as used (0 = none).
//   engine off  fuel_enabled false (hybrid stop-start: stopped, spinning down, cranked; any
//             ω >= 0): brake_torque_Nm is what the engine puts on the crank, map: its motoring
//             curve (faded to 0 at 0 rpm), 1D: its crank torque of the step (compression pulses,
//             signed); the vehicle applies a braking one as friction, a driving one as it is.
//   exhaust T EngineOutputs::exhaust_T_K is always > 0: where the model has no exhaust flow state
//             yet (before its first step) the ambient temperature of the last inputs.
#pragma once
#include <algorithm>
#include <string>
#include <vector>

#include "common/units.hpp"

namespace hbt::engine {

struct EngineInputs {
  double speed_rad_s = 0.0;        // imposed crank speed ω [rad/s]
  double torque_request_Nm = 0.0;  // requested brake torque [Nm]
  double ambient_T_K = 298.15;     // ambient = air-filter inlet temperature [K]
  double ambient_p_Pa = units::kStandardAtmosphere_Pa;  // [Pa]; <= 0: the standard atmosphere
  double back_pressure_Pa = 0.0;   // turbine-outlet (ATS inlet) pressure [Pa]; <= 0: none
  double coolant_T_K = 0.0;        // engine coolant temperature [K]; <= 0: none
  double oil_T_K = 0.0;            // engine oil temperature [K]; <= 0: none
  bool fuel_enabled = true;        // false: engine off / fuel cut (torque = motoring)
};

/// What the engine publishes (EngineState, ExhaustState, EngineHeat), model-neutral, SI.
struct EngineOutputs {
  double speed_rad_s = 0, brake_torque_Nm = 0;
  double max_torque_Nm = 0, min_torque_Nm = 0;  // live limits at ω: what may be requested [Nm]
  double fuel_mass_flow_kg_s = 0, fuel_mass_kg = 0;             // [kg/s], cumulative [kg]
  double positive_work_J = 0, motoring_work_J = 0;              // cumulative [J]
  double boost_pressure_Pa = 0, turbo_speed_rad_s = 0, lambda = 0;  // map: no turbo (0)
  double charge_air_T_K = 0;                                    // intake manifold [K]
  double exhaust_mass_flow_kg_s = 0, exhaust_T_K = 0;           // turbine outlet system
  double y_O2 = 0, y_CO2 = 0, y_H2O = 0, y_N2 = 0;              // mass fractions [-]
  double nox_mass_flow_kg_s = 0, nox_mass_kg = 0;               // engine-out, as NO2
  // exhaust totals since reset() (see the header comment): [kg], [kg K], [K s], [kg] x 3
  double exhaust_mass_kg = 0, exhaust_mass_T_kg_K = 0, exhaust_T_time_K_s = 0;
  double o2_mass_kg = 0, co2_mass_kg = 0, h2o_mass_kg = 0;
  double crank_angle_rad = 0;                                   // Σ ω Δt since reset() [rad]
  double heat_to_coolant_W = 0, heat_to_coolant_J = 0;          // into the metal [W], cumulative [J]
  double heat_to_oil_W = 0, heat_to_oil_J = 0;                  // into the oil [W], cumulative [J]
  double friction_W = 0;                                        // mechanical friction work rate [W]
  double coolant_T_K = 0, oil_T_K = 0, back_pressure_Pa = 0;  // loop inputs the engine used (0 = none)
  double friction_correction_Nm = 0, pumping_correction_Nm = 0;  // map: cold oil, back-pressure
};

/// One key/value of the engine's diagnostics (docs/diagnostics.md); the participant formats it
/// like every other participant's (a number %.6g, a count as an integer, a flag true/false).
struct EngineDiagnosticValue {
  enum class Kind { kNumber, kCount, kFlag };
  std::string key;
  double value = 0.0;
  Kind kind = Kind::kNumber;
};

class EngineModel {
 public:
  virtual ~EngineModel() = default;
  /// "map" | "1d" (the launch argument engine).
  virtual const char* name() const = 0;
  /// The engine's idle speed [rad/s]: where reset() starts.
  virtual double idleSpeed() const = 0;
  /// Static full-load and motoring (< 0) brake torque at speed ω [Nm] of the warm engine.
  virtual double fullLoadTorque(double speed_rad_s) const = 0;
  virtual double motoringTorque(double speed_rad_s) const = 0;

  /// Restarts: idle speed, brake torque 0, ambient T [K] and p [Pa] (the start policy above).
  void reset(double ambient_T_K, double ambient_p_Pa = units::kStandardAtmosphere_Pa) {
    in_ = EngineInputs{};
    in_.speed_rad_s = idleSpeed();
    in_.ambient_T_K = ambient_T_K;
    in_.ambient_p_Pa = ambient_p_Pa;
    out_ = EngineOutputs{};
    resetModel(in_);
    finishOutputs();
  }
  /// Advances by dt_s [s] (> 0) with the inputs held over the step; returns the outputs.
  const EngineOutputs& step(double dt_s, const EngineInputs& in) {
    in_ = in;
    if (!(in_.ambient_p_Pa > 0.0)) in_.ambient_p_Pa = units::kStandardAtmosphere_Pa;
    if (!(in_.coolant_T_K > 0.0)) in_.coolant_T_K = 0.0;
    if (!(in_.oil_T_K > 0.0)) in_.oil_T_K = 0.0;
    if (!(in_.back_pressure_Pa > 0.0)) in_.back_pressure_Pa = 0.0;
    stepModel(dt_s, in_);
    finishOutputs();
    const double m = std::max(0.0, out_.exhaust_mass_flow_kg_s);
    out_.exhaust_mass_kg += m * dt_s;
    out_.exhaust_mass_T_kg_K += m * out_.exhaust_T_K * dt_s;
    out_.exhaust_T_time_K_s += out_.exhaust_T_K * dt_s;
    out_.o2_mass_kg += m * out_.y_O2 * dt_s;
    out_.co2_mass_kg += m * out_.y_CO2 * dt_s;
    out_.h2o_mass_kg += m * out_.y_H2O * dt_s;
    out_.crank_angle_rad += std::max(0.0, out_.speed_rad_s) * dt_s;
    return out_;
  }
  const EngineOutputs& outputs() const { return out_; }
  /// The inputs of the last step (after the fallbacks above; reset(): the start state).
  const EngineInputs& inputs() const { return in_; }

  // --- diagnostics: the warning boost_limited (docs/diagnostics.md) and key/values ---
  /// The model's "too little boost air" condition of the last step: map = the request above the
  /// PT1 (turbo build-up) dynamic full load by more than margin_Nm while that limit is itself
  /// margin_Nm below the static full load; 1D = the smoke limiter (minimum λ) holds the fuel.
  virtual bool boostLimited(double margin_Nm) const = 0;
  /// Its message (the warning raised after duration_s [s] of it).
  virtual std::string boostLimitedMessage(double duration_s) const = 0;
  /// Appends the model's own key/values (after speed, request, brake torque, written by the
  /// participant). Called once per status: window counters restart here.
  virtual void diagnosticValues(std::vector<EngineDiagnosticValue>& kv) = 0;

 protected:
  /// The model's reset at in.speed_rad_s, torque 0, in.ambient_T_K / in.ambient_p_Pa; fills out_
  /// (the fields the model has; speed, loop echoes and the exhaust-T fallback are set after).
  virtual void resetModel(const EngineInputs& in) = 0;
  /// The model's step with the inputs after the fallbacks; fills out_ likewise.
  virtual void stepModel(double dt_s, const EngineInputs& in) = 0;
  EngineOutputs out_;

 private:
  void finishOutputs() {
    out_.speed_rad_s = in_.speed_rad_s;
    out_.coolant_T_K = in_.coolant_T_K;
    out_.oil_T_K = in_.oil_T_K;
    out_.back_pressure_Pa = in_.back_pressure_Pa;
    if (!(out_.exhaust_T_K > 0.0)) out_.exhaust_T_K = in_.ambient_T_K;
  }
  EngineInputs in_;
};

}  // namespace hbt::engine
