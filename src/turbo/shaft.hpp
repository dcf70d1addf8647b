// Turbocharger rotor dynamics.
//
//   J ω dω/dt = η_m P_t − P_c − k_f ω²                                   [W]
// J [kg·m²] rotor polar inertia; η_m [-] mechanical efficiency applied to the turbine power
// (load-dependent bearing/thrust losses); k_f [W·s²] = P_f,ref/ω_ref² speed-dependent journal-
// bearing drag, so that a coasting rotor decelerates (free run-down ω = ω_0 exp(−k_f t/J)).
//
// Integration is done on the rotor kinetic energy E = ½ J ω² (no 1/ω singularity at standstill):
//   dE/dt = F − a E,  F = η_m P_t − P_c,  a = 2 k_f/J,
// exact for F constant over the step:  E⁺ = E e^(−a Δt) + F/a (1 − e^(−a Δt)),  E⁺ ≥ 0,
// ω = √(2E/J) ≥ 0. derivative() returns dω/dt with ω floored at ω_min for the 1/ω term.
#pragma once

namespace hbt::turbo {

struct ShaftParams {
  double inertia_kg_m2 = 1.5e-4;       // J
  double eta_mech = 0.97;              // η_m
  double friction_ref_power_W = 300.0; // P_f,ref at ω_ref
  double friction_ref_speed_rad_s = 10471.975511965978;  // 100 krpm
  double omega_min_rad_s = 100.0;      // guard for dω/dt at very low speed
};

class TurboShaft {
 public:
  TurboShaft() = default;
  explicit TurboShaft(const ShaftParams& p, double omega0_rad_s = 0.0);

  /// Advances by dt [s] with turbine power P_t [W] and compressor power P_c [W] held constant.
  void step(double dt_s, double turbine_power_W, double compressor_power_W);
  /// dω/dt [rad/s²] at the current state (explicit form; guarded at low ω).
  double derivative(double turbine_power_W, double compressor_power_W) const;
  /// Net power on the rotor [W] = η_m P_t − P_c − k_f ω².
  double netPower(double turbine_power_W, double compressor_power_W) const;
  double frictionPower() const { return kf_ * omega_ * omega_; }

  double omega() const { return omega_; }             // [rad/s]
  double speedRpm() const;                            // [rpm]
  void setOmega(double w_rad_s);
  double kineticEnergy() const { return 0.5 * p_.inertia_kg_m2 * omega_ * omega_; }  // [J]
  double frictionCoefficient() const { return kf_; }  // k_f [W·s²]
  const ShaftParams& params() const { return p_; }

 private:
  ShaftParams p_;
  double kf_ = 0.0;
  double omega_ = 0.0;
};

}  // namespace hbt::turbo
