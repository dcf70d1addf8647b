#include "engine_map/nox_map.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::engine_map {

Table2D readNoxMap(const std::string& path, const std::string& key) {
  CsvTable t = [&] {
    try {
      return CsvTable::read(path);
    } catch (const InputError& e) {
      throw InputError(path, key, std::string("cannot read the NOx map: ") + e.what());
    }
  }();
  for (const char* c : {"speed_rpm", "load", "ei_nox_g_per_kg"})
    if (!t.has(c)) throw InputError(path, key, std::string("NOx map has no column '") + c + "'");
  const auto& n = t.column("speed_rpm");
  const auto& l = t.column("load");
  const auto& ei = t.column("ei_nox_g_per_kg");
  auto axis = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end(), [](double a, double b) { return std::fabs(a - b) < 1e-9; }),
            v.end());
    return v;
  };
  const std::vector<double> ns = axis(n), ls = axis(l);
  if (ns.size() < 2 || ls.size() < 2)
    throw InputError(path, key, "NOx map needs >= 2 speeds and >= 2 loads");
  if (ns.size() * ls.size() != t.rows())
    throw InputError(path, key, "NOx map is not a complete speed x load grid (" +
                                    std::to_string(ns.size()) + " speeds x " + std::to_string(ls.size()) +
                                    " loads != " + std::to_string(t.rows()) + " rows)");
  std::vector<double> v(t.rows(), -1.0);
  for (std::size_t r = 0; r < t.rows(); ++r) {
    if (!(n[r] > 0.0) || !(l[r] >= 0.0) || !(l[r] <= 1.5))
      throw InputError(path, key, "NOx map row " + std::to_string(r + 1) + ": speed must be > 0 and load in [0, 1.5]");
    if (!(ei[r] >= 0.0) || !(ei[r] <= 200.0))
      throw InputError(path, key, "NOx map row " + std::to_string(r + 1) + ": ei_nox_g_per_kg outside [0, 200]");
    const auto i = std::lower_bound(ns.begin(), ns.end(), n[r] - 1e-9) - ns.begin();
    const auto j = std::lower_bound(ls.begin(), ls.end(), l[r] - 1e-9) - ls.begin();
    double& cell = v[static_cast<std::size_t>(i) * ls.size() + static_cast<std::size_t>(j)];
    if (cell >= 0.0)
      throw InputError(path, key, "NOx map has the point (" + std::to_string(n[r]) + " rpm, load " +
                                      std::to_string(l[r]) + ") twice");
    cell = ei[r] * 1e-3;  // g/kg -> kg/kg
  }
  std::vector<double> w(ns.size());
  for (std::size_t i = 0; i < ns.size(); ++i) w[i] = units::rpmToRadps(ns[i]);
  return Table2D(w, ls, v, path, key);
}

}  // namespace hbt::engine_map
