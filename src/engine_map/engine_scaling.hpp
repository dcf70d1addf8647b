// Scaling of a reference VECTO engine (full-load curve + fuel map) to the twin's engine.
//
// Rule (documented in config/engine_map.yaml and README.md): with the reference peak torque
// T_ref,max and peak power P_ref,max (exact maximum of ω·T_fl(ω) over the piecewise-linear
// curve),
//
//   torque factor  f_T = T_target / T_ref,max                          [-]
//   speed factor   f_n = P_target / (f_T · P_ref,max)   (or 1 if speed scaling is off)
//   fuel factor    f_F = f_T · f_n                                     [-]
//
//   ω' = f_n ω,  T'_fl = f_T T_fl,  T'_mot = f_T T_mot,  ṁ'_f(ω', T') = f_F ṁ_f(ω, T).
//
// Consequences (exact): peak torque' = T_target, peak power' = P_target (since
// P'(ω') = f_n f_T P(ω)), and the brake-specific fuel consumption at corresponding points
// (ω' = f_n ω, T' = f_T T) is unchanged: ṁ'_f/(ω'T') = ṁ_f/(ωT). The map's efficiency landscape
// is thus carried over unchanged, moved to the twin's speed/torque range. Motoring torque is
// scaled with f_T (same mean effective friction pressure × displacement ratio assumption).
#pragma once
#include "engine_map/vecto_engine_files.hpp"

namespace hbt::engine_map {

struct EngineScaling {
  double torque_factor = 1.0;  // f_T [-]
  double speed_factor = 1.0;   // f_n [-]
  double fuel_factor = 1.0;    // f_F = f_T f_n [-]
  double ref_peak_torque_Nm = 0.0;
  double ref_peak_power_W = 0.0;
  double ref_peak_power_speed_rad_s = 0.0;
};

/// Maximum of ω·T_fl(ω) on the piecewise-linear curve (vertices and interior stationary points).
double peakPower(const FullLoadCurve& c, double* speed_at_peak_rad_s = nullptr);
double peakTorque(const FullLoadCurve& c);

/// Throws InputError(c.source, ...) for non-positive targets or a curve without positive power.
EngineScaling computeScaling(const FullLoadCurve& ref, double target_peak_torque_Nm,
                             double target_peak_power_W, bool scale_speed);

FullLoadCurve applyScaling(const FullLoadCurve& c, const EngineScaling& s);
FuelMapPoints applyScaling(const FuelMapPoints& m, const EngineScaling& s);
/// PT1 table speed axis scaled by f_n (time constants kept: corresponding operating points).
Table1D applySpeedScaling(const Table1D& pt1, const EngineScaling& s);

}  // namespace hbt::engine_map
