// One steady operating point of the 1D engine against the reference (bench) map, and the BSFC
// validation region (engine_1d README, "BSFC against the reference"). Used by the steady tool
// (tools/engine_1d_steady.cpp) and the region gtest (test/engine_1d/test_bsfc_region.cpp).
//
// runSteadyPoint: speed imposed, torque requested through the PIDs, macro step dt, run to periodic
// steady state. Convergence: after >= 1.0 s, the averages of the one-cycle means over the last
// 0.2 s and over the 0.2 s before differ by less than 0.3 % or 1 Nm (brake torque), 0.3 % (fuel
// flow), 0.5 % (boost, turbo speed), and the brake torque is within 1 % (or 3 Nm) of the
// request. Reported values: averages over the last 0.2 s. The engine is NOT reset (the steady
// tool starts each point from the previous one at the same speed).
#pragma once

#include <string>

#include "engine_1d/engine_1d.hpp"

namespace hbt::engine_1d {

struct SteadyPointOptions {
  double dt_s = 0.02;             // macro step [s]
  double max_time_s = 8.0;        // give up after this simulated time [s]
  double ambient_T_K = 298.15;    // ambient (compressor inlet, charge-air-cooler cold side) [K]
};

struct SteadyPointResult {
  Engine1DOutputs mean;           // outputs averaged over the last 0.2 s (selected fields)
  bool converged = false;
  double sim_s = 0.0, cpu_s = 0.0;
  double fuel_ref_kg_s = 0.0;     // reference map fuel at (ω, T_b) [kg/s]
  double bsfc_g_kWh = 0.0, bsfc_ref_g_kWh = 0.0, bsfc_err_pct = 0.0;
  double nox_g_kWh = 0.0;         // engine-out NOx (as NO2) per brake kWh
};

/// Runs the engine at `rpm` with `torque_req_Nm` requested until steady (see header comment).
SteadyPointResult runSteadyPoint(Engine1D& eng, double rpm, double torque_req_Nm,
                                 const SteadyPointOptions& opt = {});

/// The BSFC validation region (config engine_1d/validation/*): where the reference fuel map and
/// its own motoring (drag) curve agree. Points outside stay in the tables and plots, flagged.
struct BsfcValidationRegion {
  double min_speed_rpm = 1100.0;  // engine_1d/validation/min_speed_rpm
  double min_load = 0.35;         // engine_1d/validation/min_load (T_req / T_full-load)
  /// True inside; otherwise `reason` (if given) says why the point is excluded.
  bool contains(double rpm, double load, std::string* reason = nullptr) const;
};

}  // namespace hbt::engine_1d
