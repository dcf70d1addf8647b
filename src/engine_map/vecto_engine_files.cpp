#include "engine_map/vecto_engine_files.hpp"

#include <cmath>
#include <map>
#include <utility>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::engine_map {
namespace {

constexpr double kKgS_per_gH = 1.0 / 3.6e6;  // 1 g/h = 1/3.6e6 kg/s

std::string row(std::size_t i) { return "data row " + std::to_string(i + 1); }

}  // namespace

FullLoadCurve readFullLoadCurve(const std::string& path) {
  const CsvTable t = CsvTable::read(path);
  const auto& n = t.column("engine speed");
  const auto& tfl = t.column("full load torque");
  const auto& tm = t.column("motoring torque");
  if (t.rows() < 2) throw InputError(path, "engine speed", "a full-load curve needs >= 2 rows");
  t.requireStrictlyIncreasing("engine speed");
  FullLoadCurve c;
  c.source = path;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    if (n[i] < 0.0) throw InputError(path, "engine speed", row(i) + ": negative speed");
    if (tm[i] > 0.0)
      throw InputError(path, "motoring torque", row(i) + ": motoring torque must be <= 0 Nm");
    if (tfl[i] < tm[i])
      throw InputError(path, "full load torque", row(i) + ": full load below motoring torque");
    c.speed_rad_s.push_back(units::rpmToRadps(n[i]));
    c.full_load_Nm.push_back(tfl[i]);
    c.motoring_Nm.push_back(tm[i]);
  }
  return c;
}

FuelMapPoints readFuelMap(const std::string& path) {
  const CsvTable t = CsvTable::read(path);
  const auto& n = t.column("engine speed");
  const auto& tq = t.column("torque");
  const auto& fc = t.column("fuel consumption");
  if (t.rows() < 3) throw InputError(path, "engine speed", "a fuel map needs >= 3 points");
  FuelMapPoints m;
  m.source = path;
  std::map<std::pair<double, double>, std::size_t> seen;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    if (n[i] < 0.0) throw InputError(path, "engine speed", row(i) + ": negative speed");
    if (fc[i] < 0.0)
      throw InputError(path, "fuel consumption", row(i) + ": negative fuel consumption");
    const auto key = std::make_pair(n[i], tq[i]);
    if (seen.count(key))
      throw InputError(path, "torque", row(i) + ": duplicate (speed, torque) point of " +
                                           row(seen[key]));
    seen[key] = i;
    m.speed_rad_s.push_back(units::rpmToRadps(n[i]));
    m.torque_Nm.push_back(tq[i]);
    m.fuel_kg_s.push_back(fc[i] * kKgS_per_gH);
  }
  return m;
}

Table1D readPt1Table(const std::string& path) {
  const CsvTable t = CsvTable::read(path);
  const auto& n = t.column("rpm");
  const auto& tau = t.column("PT1");
  t.requireStrictlyIncreasing("rpm");
  std::vector<double> w, s;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    if (tau[i] < 0.0) throw InputError(path, "PT1", row(i) + ": negative time constant");
    w.push_back(units::rpmToRadps(n[i]));
    s.push_back(tau[i]);
  }
  return Table1D(w, s, path, "rpm");
}

}  // namespace hbt::engine_map
