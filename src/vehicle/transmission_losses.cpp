#include "vehicle/transmission_losses.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::vehicle {

GearLossMap::GearLossMap(const std::string& path) {
  const CsvTable t = CsvTable::read(path);
  const auto& n = t.column("input speed");
  const auto& T = t.column("input torque");
  const auto& L = t.column("torque loss");
  std::map<std::pair<double, double>, double> pts;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    if (L[i] < 0.0) throw InputError(path, "torqueloss", "data row " + std::to_string(i + 1) + ": negative loss");
    if (n[i] < 0.0) throw InputError(path, "inputspeed", "data row " + std::to_string(i + 1) + ": negative speed");
    pts[{n[i], T[i]}] = L[i];
  }
  std::vector<double> ns(n.begin(), n.end()), ts(T.begin(), T.end());
  std::sort(ns.begin(), ns.end());
  ns.erase(std::unique(ns.begin(), ns.end()), ns.end());
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  if (ns.size() < 2 || ts.size() < 2 || ts.front() != 0.0)
    throw InputError(path, "inputtorque", "need >= 2 speeds and >= 2 torques starting at 0 Nm");
  std::vector<double> loss, w;
  for (double a : ns)
    for (double b : ts) {
      const auto it = pts.find({a, b});
      if (it == pts.end())
        throw InputError(path, "torqueloss", "grid incomplete: no point at " + std::to_string(a) +
                                                 " rpm, " + std::to_string(b) + " Nm");
      loss.push_back(it->second);
    }
  for (double a : ns) w.push_back(units::rpmToRadps(a));
  loss_ = Table2D(w, ts, loss, path, "torqueloss");
}

double GearLossMap::total(double w_in, double T_in) const {
  return loss_(std::fabs(w_in), std::fabs(T_in));  // symmetric in the signs, clamped at the edges
}

RetarderLoss::RetarderLoss(const std::string& path) {
  if (path.empty()) return;
  const CsvTable t = CsvTable::read(path);
  const auto& n = t.column("retarder speed");
  const auto& L = t.column("torque loss");
  t.requireStrictlyIncreasing("retarder speed");
  std::vector<double> w;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    if (L[i] < 0.0) throw InputError(path, "torqueloss", "data row " + std::to_string(i + 1) + ": negative loss");
    w.push_back(units::rpmToRadps(n[i]));
  }
  tab_ = Table1D(w, L, path, "retarderspeed");
}

double RetarderLoss::torque(double w) const { return tab_.empty() ? 0.0 : tab_(std::fabs(w)); }

}  // namespace hbt::vehicle
