// The aftertreatment's inputs over one of its macro steps from its producers' cumulative totals.
// The node steps every 0.1 s (brick time constants > 1 s), the engine and the vehicle every 10 ms:
// a point sample of their 10 ms signals would alias them, the difference of two samples of a
// cumulative total is their exact mean. Between the samples `prev` and `now`, Δt = t_now - t_prev:
//   ṁ = Δm / Δt                                 exhaust mass flow [kg/s]
//   T = Δ(∫ṁT dt) / Δm    (Δm = 0: Δ(∫T dt)/Δt)   mass-weighted exhaust temperature [K]
//   y_i = Δm_i / Δm       (Δm = 0: the point value) mass fractions O2, CO2, H2O [-]; N2 the rest
//   ṁ_j = Δm_j / Δt                             NOx (as NO2), HC, CO [kg/s]
//   v = Δx / Δt                                 vehicle speed [m/s] (can convection)
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
  bool started_ = false;
  InputTotals prev_;
};

}  // namespace hbt::aftertreatment
