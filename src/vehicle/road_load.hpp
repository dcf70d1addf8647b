// Road loads of the bus (longitudinal, no wind):
//
//   F_roll  = f_t C_rr m g cos α                   (Coulomb: opposes the motion; held at v = 0)
//   C_rr    = Σ_axles s_i RRC_i (s_i m g / (n_i F_zISO))^(β-1)   (VECTO load-corrected RRC)
//   f_t     = 1 / (1 + K_t (t_amb - t_ref))        tyre temperature factor [-]: the UN R117 /
//             ISO 28580 correction F_r25 = F_rt (1 + K_t (t_amb - 25 °C)) solved for F_rt,
//             K_t = 0.006 1/K (C3); applied (extrapolated) at any ambient, see README
//   F_aero  = ½ ρ C_dA v |v|,  ρ = p_amb / (R_air T_amb)
//   F_grade = m g sin α,  α = atan(grade), grade = rise/run [-]
// m = curb + payload [kg], g = 9.81 m/s².
#pragma once
#include <cmath>

#include "common/units.hpp"
#include "vehicle/vehicle_params.hpp"

namespace hbt::vehicle {

class RoadLoad {
 public:
  RoadLoad() = default;
  explicit RoadLoad(const ChassisParams& c) : c_(c), m_(c.curb_mass_kg + c.payload_kg) {
    const double g = units::kGravity_m_s2;
    const double sf = c.front_axle_load_share, sr = 1.0 - sf;
    const double b1 = c.rrc_load_exponent - 1.0;
    crr_ = sf * c.rrc_front * std::pow(sf * m_ * g / (c.tyres_front * c.tyre_fz_iso_N), b1) +
           sr * c.rrc_rear * std::pow(sr * m_ * g / (c.tyres_rear * c.tyre_fz_iso_N), b1);
  }
  double mass_kg() const { return m_; }
  double rollingCoefficient() const { return crr_; }
  /// f_t [-] at the ambient temperature [K]: 1 at t_ref; > 1 colder, < 1 warmer.
  double rollingTemperatureFactor(double ambient_T_K) const {
    return 1.0 / (1.0 + c_.rrc_temperature_coefficient_per_K * (ambient_T_K - c_.rrc_reference_temperature_K));
  }
  double airDensity(double ambient_T_K) const {
    return c_.ambient_pressure_Pa / (c_.air_R_J_kgK * ambient_T_K);
  }
  /// Magnitude of the rolling resistance [N] on grade (rise/run) with the tyre temperature
  /// factor f_t [-] (rollingTemperatureFactor()).
  double rolling(double grade, double f_t) const {
    return f_t * crr_ * m_ * units::kGravity_m_s2 * std::cos(std::atan(grade));
  }
  double aero(double v_m_s, double rho) const { return 0.5 * rho * c_.cda_m2 * v_m_s * std::fabs(v_m_s); }
  double gradeForce(double grade) const { return m_ * units::kGravity_m_s2 * std::sin(std::atan(grade)); }

 private:
  ChassisParams c_;
  double m_ = 0.0, crr_ = 0.0;
};

}  // namespace hbt::vehicle
