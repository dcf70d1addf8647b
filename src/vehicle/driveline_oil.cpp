#include "vehicle/driveline_oil.hpp"

#include <cmath>

#include "common/oil_viscosity.hpp"

namespace hbt::vehicle {

double oilDragFactor(const OilUnitParams& p, double T_oil_K) {
  return oilViscosityFactor(T_oil_K, p.reference_K, p.vogel_b_K, p.vogel_c_K,
                            p.drag_viscosity_exponent);
}

void OilThermalNode::reset(double T_K) {
  T_ = T0_ = T_K;
  in_J_ = amb_J_ = cooler_J_ = cooler_W_ = 0.0;
}

void OilThermalNode::step(double dt_s, double heat_J, double T_amb_K) {
  const double C = p_.heat_capacity_J_K, UA = p_.ua_ambient_W_K, tau = C / UA;
  const double P = heat_J / dt_s;
  const double T_eq = T_amb_K + P / UA;
  in_J_ += heat_J;
  cooler_W_ = 0.0;
  const double T_open = p_.cooler_open_K;
  double t_free = dt_s;  // time of the step with the cooler closed
  if (p_.hasCooler() && T_eq > T_open) {
    // reaches T_open at t* (0 if already there), then the thermostat holds it
    t_free = T_ >= T_open ? 0.0 : std::min(dt_s, tau * std::log((T_ - T_eq) / (T_open - T_eq)));
  }
  const double T1 = T_eq + (T_ - T_eq) * std::exp(-t_free / tau);
  amb_J_ += P * t_free - C * (T1 - T_);  // the exact integral of UA (T - T_amb) over t_free
  T_ = T1;
  if (t_free < dt_s) {  // held at T_open for the rest of the step
    const double t_held = dt_s - t_free;
    const double q_drop_J = C * (T_ - T_open);  // > 0 only when starting above T_open
    T_ = T_open;
    amb_J_ += UA * (T_open - T_amb_K) * t_held;
    const double q_J = (P - UA * (T_open - T_amb_K)) * t_held + q_drop_J;
    cooler_J_ += q_J;
    cooler_W_ = q_J / dt_s;
  }
}

}  // namespace hbt::vehicle
