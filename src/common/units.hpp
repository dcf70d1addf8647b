// Unit conversions used only at the edges (SI inside every model).
#pragma once

namespace hbt::units {

constexpr double kPi = 3.14159265358979323846;
constexpr double kZeroCelsius_K = 273.15;
constexpr double kKmh_per_mps = 3.6;
constexpr double kRadps_per_rpm = 2.0 * kPi / 60.0;
// Angles: crank angles, valve events and phasing are in degrees at the edges (configuration,
// tables), radians in the kinematics. Bits: kPi is the value of M_PI, and these are the former
// `M_PI / 180.0` / `180.0 / M_PI` of each model (test_common: Units); a site that divided by
// M_PI / 180.0 divides by kRad_per_deg, so its result keeps its bits.
constexpr double kRad_per_deg = kPi / 180.0;
constexpr double kDeg_per_rad = 180.0 / kPi;
constexpr double kJ_per_kWh = 3.6e6;
// Molar gas constant [J/(mol K)] (CODATA 2018: R = N_A k, exact since the 2019 SI): the one value
// of the cylinder's thermodynamics and the aftertreatment's gas.
constexpr double kUniversalGas_J_molK = 8.314462618;
constexpr double kGravity_m_s2 = 9.81;  // VECTO uses 9.81 m/s^2
// Standard atmosphere at sea level [Pa] (ISO 2533:1975 / ICAO; = 1 atm): the ambient pressure
// wherever a scenario or an input gives none (the engine's reset and its command fallback).
constexpr double kStandardAtmosphere_Pa = 101325.0;
// Diesel fuel, the one definition for the models, the tools and the Python scripts
// (python/twin_tools/units.py reads these lines: keep each as `constexpr double NAME = NUMBER;`).
// Lower heating value (net calorific value): the VECTO declaration value for diesel B7.
constexpr double kDieselLhv_J_kg = 42.7e6;
// Density at 15 degC: EN 590 allows 0.820-0.845 kg/L (VECTO's reference fuel B7 has 0.836 kg/L);
// 0.835 kg/L used.
constexpr double kDieselDensity_kg_m3 = 835.0;
constexpr double kM3_per_litre = 1e-3;

constexpr double rpmToRadps(double rpm) { return rpm * kRadps_per_rpm; }
constexpr double radpsToRpm(double w_rad_s) { return w_rad_s / kRadps_per_rpm; }
constexpr double degToRad(double deg) { return deg * kRad_per_deg; }
constexpr double radToDeg(double rad) { return rad * kDeg_per_rad; }
constexpr double kmhToMps(double v_kmh) { return v_kmh / kKmh_per_mps; }
constexpr double mpsToKmh(double v_m_s) { return v_m_s * kKmh_per_mps; }
constexpr double celsiusToK(double t_c) { return t_c + kZeroCelsius_K; }
constexpr double kToCelsius(double t_k) { return t_k - kZeroCelsius_K; }
constexpr double dieselLitres(double fuel_kg) {
  return fuel_kg / (kDieselDensity_kg_m3 * kM3_per_litre);  // [L]
}

}  // namespace hbt::units
