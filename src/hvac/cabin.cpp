#include "hvac/cabin.hpp"

#include <cmath>

namespace hbt::hvac {

namespace {
constexpr double kReferenceAir_K = 293.15;  // air density of the cabin's heat capacity: 20 °C, 1 atm
}

Cabin::Cabin(const CabinParams& c, const DoorParams& d, const AirParams& a) : c_(c), d_(d), a_(a) {
  const double rho_ref = units::kStandardAtmosphere_Pa / (a_.R_J_kgK * kReferenceAir_K);
  C_J_K_ = rho_ref * c_.air_volume_m3 * a_.cp_J_kgK + c_.interior_heat_capacity_J_K;
  const double area_m2 = 2.0 * (c_.length_m * c_.width_m + c_.length_m * c_.height_m + c_.width_m * c_.height_m);
  UA_W_K_ = c_.u_value_W_m2K * area_m2;
}

double Cabin::freshAirMassFlow_kg_s(const CabinInputs& in) const {
  const double rho_a = in.ambient_p_Pa / (a_.R_J_kgK * in.ambient_T_K);
  return rho_a * c_.fresh_air_changes_per_h * c_.air_volume_m3 / 3600.0;
}

double Cabin::doorMassFlow_kg_s(const CabinInputs& in, double T_K) const {
  if (!in.doors_open) return 0.0;
  const double rho_a = in.ambient_p_Pa / (a_.R_J_kgK * in.ambient_T_K);
  const double T_mean = 0.5 * (T_K + in.ambient_T_K);
  const double dT = std::fabs(T_K - in.ambient_T_K);
  const double per_door_m3_s = d_.discharge_coefficient / 3.0 * d_.width_m * d_.height_m *
                               std::sqrt(units::kGravity_m_s2 * d_.height_m * dT / T_mean);
  return rho_a * d_.count * per_door_m3_s;
}

CabinConductance Cabin::conductance(const CabinInputs& in, double T_K) const {
  CabinConductance g;
  g.body_W_K = UA_W_K_;
  g.fresh_air_W_K = freshAirMassFlow_kg_s(in) * a_.cp_J_kgK;
  g.doors_W_K = doorMassFlow_kg_s(in, T_K) * a_.cp_J_kgK;
  return g;
}

CabinFlows Cabin::step(double h, const CabinInputs& in) {
  const CabinConductance g = conductance(in, T_K_);
  const double G = g.total();
  const double Q_net = in.heat_W - in.cool_W + in.gain_W;
  const double T0 = T_K_;
  if (G > 0.0) {
    const double T_eq = in.ambient_T_K + Q_net / G;
    T_K_ = T_eq + (T0 - T_eq) * std::exp(-h * G / C_J_K_);
  } else {
    T_K_ = T0 + Q_net * h / C_J_K_;
  }
  // Exact loss integral of the step, split by conductance; mean flows = integral / h.
  const double theta_dt = G > 0.0 ? (Q_net * h - C_J_K_ * (T_K_ - T0)) / G : 0.0;  // ∫(T - T_a)dt [K s]
  CabinFlows f;
  f.body_W = g.body_W_K * theta_dt / h;
  f.fresh_air_W = g.fresh_air_W_K * theta_dt / h;
  f.doors_W = g.doors_W_K * theta_dt / h;
  f.fresh_air_mass_flow_kg_s = g.fresh_air_W_K / a_.cp_J_kgK;
  f.door_mass_flow_kg_s = g.doors_W_K / a_.cp_J_kgK;
  return f;
}

}  // namespace hbt::hvac
