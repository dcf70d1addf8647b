// Readers for the VECTO engine files used by the map-based engine, in SI units.
//
//   .vfld  "engine speed [rpm], full load torque [Nm], motoring torque [Nm]"  (full-load and
//          motoring/drag curve, piecewise linear in speed)
//   .vmap  "engine speed [rpm], torque [Nm], fuel consumption [g/h]"  (steady-state fuel map on
//          scattered points; motoring rows carry FC = 0)
//   PT1.csv "rpm, PT1" (VECTO declaration 2015: time constant [s] of the full-load torque
//          build-up vs engine speed)
//
// Every reader converts to SI (rad/s, Nm, kg/s, s) and validates the physics that later code
// relies on; any violation throws hbt::InputError naming the file and the column (key).
#pragma once
#include <string>
#include <vector>

#include "common/table1d.hpp"

namespace hbt::engine_map {

/// Full-load and motoring curve (from a .vfld). Speeds strictly increasing.
struct FullLoadCurve {
  std::vector<double> speed_rad_s;   // engine speed [rad/s]
  std::vector<double> full_load_Nm;  // maximum brake torque [Nm], >= motoring
  std::vector<double> motoring_Nm;   // motoring (drag) torque [Nm], <= 0
  std::string source;                // file it came from (for messages)
};

/// Scattered steady-state fuel map (from a .vmap).
struct FuelMapPoints {
  std::vector<double> speed_rad_s;  // [rad/s]
  std::vector<double> torque_Nm;    // brake torque [Nm]
  std::vector<double> fuel_kg_s;    // fuel mass flow [kg/s], >= 0
  std::string source;
};

/// Reads a .vfld. Checks: >= 2 rows, speed strictly increasing and >= 0, motoring <= 0,
/// full load >= motoring.
FullLoadCurve readFullLoadCurve(const std::string& path);

/// Reads a .vmap. Checks: >= 3 points, speed >= 0, fuel >= 0, no duplicate (speed, torque).
FuelMapPoints readFuelMap(const std::string& path);

/// Reads a VECTO PT1 table -> time constant [s] vs engine speed [rad/s]. Checks: speed strictly
/// increasing, tau >= 0.
Table1D readPt1Table(const std::string& path);

}  // namespace hbt::engine_map
