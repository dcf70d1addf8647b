// Vehicle-level limits of the mission pre-processor (independent of the powertrain variant).
//
// 1. Driver acceleration/deceleration limits vs speed, VECTO .vacc format
//    (columns "v [km/h], acc [m/s2], dec [m/s2]", dec < 0), linearly interpolated in speed,
//    constant beyond the table:  a_min(v) = dec(v) [m/s^2] <= a <= a_max(v) = acc(v) [m/s^2].
// 2. Road load of a simplified vehicle (longitudinal, rigid, no slip), road angle
//    alpha = atan(grade/100):
//      F_res(v, grade) = m g (RRC cos(alpha) + sin(alpha)) + 0.5 rho CdA v^2          [N]
//      a_coast(v, grade) = -F_res / (m + m_rot)        (no traction, no brake)          [m/s^2]
//      a_power(v, grade) = (P_wheel_max / v - F_res) / (m + m_rot)                      [m/s^2]
//    m [kg] vehicle mass, m_rot [kg] equivalent mass of the wheels' inertia (sum J / r^2),
//    RRC [-] rolling-resistance coefficient, CdA [m^2], rho [kg/m^3], g = 9.81 m/s^2,
//    P_wheel_max [W] maximum traction power at the wheels (<= 0: no power limit).
#pragma once
#include <string>

#include "common/table1d.hpp"

namespace hbt::mission {

class AccelerationLimits {
 public:
  AccelerationLimits() = default;
  /// Tables vs speed [m/s]; acc > 0, dec < 0 [m/s^2]. Throws InputError(source, ...).
  AccelerationLimits(Table1D acc_vs_v_m_s, Table1D dec_vs_v_m_s, const std::string& source);
  /// Reads a VECTO .vacc file (v in km/h). Throws InputError naming file and column.
  static AccelerationLimits readVacc(const std::string& path);
  /// Constant limits (tests, simple studies).
  static AccelerationLimits constant(double acc_m_s2, double dec_m_s2);

  double maxAccel_m_s2(double v_m_s) const { return acc_(v_m_s); }  // > 0
  double maxDecel_m_s2(double v_m_s) const { return dec_(v_m_s); }  // < 0
  const std::string& source() const { return source_; }

 private:
  Table1D acc_, dec_;
  std::string source_;
};

struct RoadLoadParams {
  double mass_kg = 16660.0;            // curb 15,160 kg + payload 1,500 kg (SPEC §2)
  double rotating_mass_kg = 349.0;     // 6 tyres 315/70 R22.5, J = 14.9 kgm2, r = 0.506 m
  double rrc = 0.0060;                 // [-] axle-load weighted 0.0055 / 0.0063
  double cda_m2 = 4.25;                // [m^2] VECTO Citybus_P1 CdA
  double air_density_kg_m3 = 1.188;    // VECTO declaration air density
  double max_wheel_power_W = 160e3;    // <= 0 disables the power limit
};

class RoadLoad {
 public:
  explicit RoadLoad(const RoadLoadParams& p) : p_(p) {}
  double effectiveMass_kg() const { return p_.mass_kg + p_.rotating_mass_kg; }
  /// Total driving resistance [N] at speed v [m/s] on grade [%].
  double resistance_N(double v_m_s, double grade_percent) const;
  /// Acceleration with neither traction nor brake [m/s^2] (> 0 on a steep enough downhill).
  double coastingAccel_m_s2(double v_m_s, double grade_percent) const;
  /// Largest acceleration the wheel power allows [m/s^2]; +inf when the limit is disabled.
  double powerLimitedAccel_m_s2(double v_m_s, double grade_percent) const;
  const RoadLoadParams& params() const { return p_; }

 private:
  RoadLoadParams p_;
};

}  // namespace hbt::mission
