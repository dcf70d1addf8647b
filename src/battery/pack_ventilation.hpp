// Forced ventilation of the battery enclosure: the thermostat fans draw ambient air through a
// filtered inlet, the cell gaps and the outlet. ROS-free, deterministic.
//
// Operating point (volume flow V [m^3/s]) = the fans' pressure-flow line against the system
// resistance:
//   fan line, n fans in parallel:  dp_fan = p_max (1 - V/(n V_free))       [Pa]
//     (linear between the datasheet's free-air flow V_free (dp = 0) and its maximum static
//     pressure p_max (V = 0); in parallel the flows add at equal pressure)
//   system:                         dp_sys = R V + K V^2                     [Pa]
//     R [Pa s/m^3]: laminar parts (filter medium, Darcy flow; the 3 mm cell gaps, plane
//       Poiseuille flow); K [Pa s^2/m^6]: minor losses (entry, exit jet), config/battery.yaml.
//   dp_fan = dp_sys  ->  K V^2 + (R + p_max/(n V_free)) V - p_max = 0, the positive root
//     V = 2 p_max / (b + sqrt(b^2 + 4 K p_max)),  b = R + p_max/(n V_free)   (no cancellation).
// The fan's pressure and the quadratic losses both scale with the air density (fan laws at fixed
// speed; dp = zeta rho v^2/2), so V is taken at the datasheet's density and does not depend on it
// (the laminar part scales with the viscosity instead: +-6 % over 0-40 degC, not modelled).
// Mass flow and the ventilation conductance [W/K] at the ambient temperature T_amb:
//   rho = p_amb/(R_air T_amb),  G_v = rho V c_p,air
// The heat carried out is G_v (T_air - T_amb) with the enclosure air well mixed (outlet air =
// enclosure air; pack_thermal.hpp). Fan off: no flow (a buoyancy-driven flow through the filter
// and the stopped fans is not modelled; README "Not modelled").
#pragma once

namespace hbt::battery {

struct PackVentilationParams {
  double fan_free_flow_m3_s = 0.0267;        // V_free of one fan at dp = 0 [m^3/s]
  double fan_max_pressure_Pa = 38.8;         // p_max of one fan at V = 0 [Pa]
  int fan_count = 2;                         // n, in parallel
  double linear_resistance_Pa_s_m3 = 435.0;  // R
  double quadratic_resistance_Pa_s2_m6 = 5.1e3;  // K
  double air_pressure_Pa = 101325.0;         // p_amb
  double air_cp_J_kgK = 1007.0;              // c_p of air
};

class PackVentilation {
 public:
  static constexpr double kAirGasConstant_J_kgK = 287.05;  // R_air = R/M, dry air (M = 28.965 g/mol)
  explicit PackVentilation(const PackVentilationParams& p);
  /// Volume flow at the operating point with the fans on [m^3/s].
  double flow_m3_s() const { return flow_m3_s_; }
  /// Pressure rise of the fans at that flow = system pressure drop [Pa].
  double pressure_Pa() const;
  /// Air density at the ambient temperature [kg/m^3].
  double density_kg_m3(double T_amb_K) const { return p_.air_pressure_Pa / (kAirGasConstant_J_kgK * T_amb_K); }
  /// Ventilation conductance G_v = rho V c_p [W/K]; 0 with the fans off.
  double conductance_W_K(bool fan_on, double T_amb_K) const {
    return fan_on ? density_kg_m3(T_amb_K) * flow_m3_s_ * p_.air_cp_J_kgK : 0.0;
  }
  const PackVentilationParams& params() const { return p_; }

 private:
  PackVentilationParams p_;
  double flow_m3_s_ = 0.0;
};

}  // namespace hbt::battery
