// Driveline oil: a lumped oil (+ wetted housing) thermal node per unit (gearbox, axle) and the
// cold-oil factor on the unit's load-independent (drag) loss.
//
// Thermal node (one per unit), with the unit's loss power P [W] held over a step of dt [s]:
//   C dT/dt = P - UA (T - T_amb) - Q_cooler                     C [J/K], UA [W/K], T [K]
//   exact over the step: T_eq = T_amb + P/UA, τ = C/UA,
//                        T(dt) = T_eq + (T_0 - T_eq) exp(-dt/τ)
//   heat to ambient over the step = P dt - C (T(dt) - T_0)      (the integral of UA (T - T_amb))
//   cooler (oil-to-coolant heat exchanger, gearbox only), an ideal thermostat at T_open: once T
//   reaches T_open (at t* = τ ln((T_0 - T_eq)/(T_open - T_eq)) within the step) T stays there and
//   the cooler takes Q_cooler = P - UA (T_open - T_amb) for the rest of the step.
//   Balance, cumulative: heat_in = C (T - T_initial) + to_ambient + to_cooler (to round-off).
//
// Drag (spin, churning, open-clutch, bearing no-load) loss vs oil temperature:
//   ν(T) ∝ exp(b / (T - c))                       Vogel law of the unit's oil, b, c [K]
//   φ(T) = (ν(T) / ν(T_ref))^n                    n [-]: drag torque ∝ ν^n
//   T_drag(ω, T) = φ(T) T_drag,ref(ω)             φ(T_ref) = 1 exactly: the warm loss map
// Only the load-independent part scales; the load-dependent (mesh) part is kept as measured.
#pragma once

namespace hbt::vehicle {

/// Oil and thermal data of one driveline unit (config/vehicle.yaml, group driveline_oil/).
struct OilUnitParams {
  double heat_capacity_J_K;        // oil + wetted housing [J/K]
  double ua_ambient_W_K;           // housing to ambient air [W/K]
  double cooler_open_K;            // oil-to-coolant cooler holds T <= this [K]; 0 = none
  double reference_K;              // oil temperature of the (warm) loss data [K]
  double vogel_b_K;                // Vogel law of the oil [K]
  double vogel_c_K;                // [K]
  double drag_viscosity_exponent;  // n: drag torque ∝ ν^n [-]
  double warm_start_K;             // oil temperature at start:=warm [K]
  bool hasCooler() const { return cooler_open_K > 0.0; }
};

/// φ(T) = (ν(T)/ν(T_ref))^n of OilUnitParams; exactly 1 at T_ref.
double oilDragFactor(const OilUnitParams& p, double T_oil_K);

/// Lumped oil node of one unit; cumulative heat bookkeeping [J].
class OilThermalNode {
 public:
  OilThermalNode() = default;
  explicit OilThermalNode(const OilUnitParams& p) : p_(p) {}
  void reset(double T_K);
  /// Advances dt_s with the unit's loss heat heat_J (spread evenly over dt) and ambient T_amb_K.
  void step(double dt_s, double heat_J, double T_amb_K);
  double temperature_K() const { return T_; }
  double heatIn_J() const { return in_J_; }
  double toAmbient_J() const { return amb_J_; }
  double toCooler_J() const { return cooler_J_; }
  double stored_J() const { return p_.heat_capacity_J_K * (T_ - T0_); }
  /// heat in - (stored + to ambient + to cooler) [J]: round-off only.
  double balanceResidual_J() const { return in_J_ - (stored_J() + amb_J_ + cooler_J_); }
  double lastCoolerPower_W() const { return cooler_W_; }
  const OilUnitParams& params() const { return p_; }

 private:
  OilUnitParams p_;
  double T_ = 0.0, T0_ = 0.0;
  double in_J_ = 0.0, amb_J_ = 0.0, cooler_J_ = 0.0, cooler_W_ = 0.0;
};

}  // namespace hbt::vehicle
