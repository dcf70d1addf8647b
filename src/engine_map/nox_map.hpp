// Engine-out NOx map of the map engine: emission index EI_NOx [kg NO2 / kg fuel] over engine
// speed x load (load = brake torque / full-load torque at that speed), bilinear on the grid,
// clamped at its edges (below the lowest speed/load the edge value, above the highest likewise).
// ṁ_NOx = EI_NOx(ω, load) · ṁ_fuel, so a fuel cut (motoring, engine off) gives exactly 0.
//
// File (CSV, '#' comment lines): columns speed_rpm, load, ei_nox_g_per_kg (other columns are
// ignored); every (speed, load) of the grid must appear exactly once (any order). Speeds are the
// twin's engine speeds (the scaled engine: the 1D engine runs the twin's engine directly).
// The file of the twin (config/data/engine/nox_map_1d.csv) is generated from the calibrated 1D
// engine's steady points (src/engine_1d/tools/make_nox_map.py; how: the file's header).
#pragma once
#include <string>

#include "common/table2d.hpp"

namespace hbt::engine_map {

/// Reads the NOx map -> Table2D over (speed [rad/s], load [-]) of EI [kg/kg]. Throws
/// InputError naming `path` and `key` (the config key that named the file) on a missing or
/// malformed file, an incomplete grid, a duplicate point, or an EI outside [0, 0.2] kg/kg.
Table2D readNoxMap(const std::string& path, const std::string& key);

}  // namespace hbt::engine_map
