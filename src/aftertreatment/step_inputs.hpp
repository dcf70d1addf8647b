// The aftertreatment's inputs over one of its macro steps from its producers' cumulative totals.
// The node steps every 0.1 s (brick time constants > 1 s), the engine and the vehicle every 10 ms:
// a point sample of their 10 ms signals would alias them, the difference of two samples of a
// cumulative total is their exact mean (common/step_mean.hpp: rounding bounds, resolution).
// Between the samples `prev` and `now`, Δt = t_now - t_prev:
//   ṁ = Δm / Δt                                 exhaust mass flow [kg/s] (0: Δm not resolved)
//   T = Δ(∫ṁT dt) / Δm                          mass-weighted exhaust temperature [K]
//   y_i = Δm_i / Δm                             mass fractions O2, CO2, H2O [-]; N2 the rest
//   ṁ_j = Δm_j / Δt                             NOx (as NO2), HC, CO [kg/s] (>= 0)
//   v = Δx / Δt                                 vehicle speed [m/s] (can convection, >= 0)
// No flow (the engine stopped, or its spin-down flow too small for the mass-weighted mean to be
// resolved to 1e-6): T = Δ(∫T dt)/Δt, the time mean of the temperature the engine publishes for
// no flow (the gas standing at the turbine outlet: map engine = ambient, engine_model.hpp), and
// the composition of the sample. With ṁ (near) 0 that temperature carries no enthalpy into the
// bricks (ṁ c_p T); it is defined, positive and finite, never a 0/0.
// Jacobi reading (participant.hpp): the step from t to t + Δt is fed the mean over [t - Δt, t] --
// the inputs lag by one ATS step (0.1 s), far below the bricks' time constants. The first step
// (no earlier sample) takes the point values of its sample.
#pragma once
#include "aftertreatment/aftertreatment.hpp"

namespace hbt::aftertreatment {

/// Cumulative totals since t = 0 as the producers publish them (ExhaustState, VehicleToCooling).
struct InputTotals {
  double exhaust_mass_kg = 0.0, exhaust_mass_T_kg_K = 0.0, exhaust_T_time_K_s = 0.0;
  double o2_kg = 0.0, co2_kg = 0.0, h2o_kg = 0.0;
  double nox_kg = 0.0, hc_kg = 0.0, co_kg = 0.0;
  double distance_m = 0.0;
};

class StepInputs {
 public:
  /// The inputs of the step that starts at the sample `now` taken dt_s [s] after the previous
  /// one; `point` = the instantaneous values of that sample (flows, T, composition, speed,
  /// ambient), used for the first step and where the mean is undefined (no flow). Ambient T and
  /// pressure are taken from `point` as they are.
  AtsInputs next(const InputTotals& now, const AtsInputs& point, double dt_s);
  void reset() { started_ = false; }

 private:
  /// Mass-weighted T and composition over the step, or the no-flow values (header).
  void exhaustGas(const InputTotals& now, double dt_s, AtsInputs& in) const;
  bool started_ = false;
  InputTotals prev_;
};

}  // namespace hbt::aftertreatment
