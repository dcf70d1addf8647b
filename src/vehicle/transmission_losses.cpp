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
  for (double a : ns)
    for (double b : ts) {
      const auto it = pts.find({a, b});
      if (it == pts.end())
        throw InputError(path, "torqueloss", "grid incomplete: no point at " + std::to_string(a) +
                                                 " rpm, " + std::to_string(b) + " Nm");
      loss_.push_back(it->second);
    }
  for (double a : ns) w_.push_back(units::rpmToRadps(a));
  t_ = ts;
}

double GearLossMap::total(double w_in, double T_in) const {
  const double w = std::clamp(std::fabs(w_in), w_.front(), w_.back());
  const double T = std::clamp(std::fabs(T_in), t_.front(), t_.back());
  const std::size_t i = std::min<std::size_t>(
      std::upper_bound(w_.begin(), w_.end(), w) - w_.begin(), w_.size() - 1) - 1;
  const std::size_t j = std::min<std::size_t>(
      std::upper_bound(t_.begin(), t_.end(), T) - t_.begin(), t_.size() - 1) - 1;
  const double a = (w - w_[i]) / (w_[i + 1] - w_[i]);
  const double b = (T - t_[j]) / (t_[j + 1] - t_[j]);
  const std::size_t nt = t_.size();
  const double l00 = loss_[i * nt + j], l01 = loss_[i * nt + j + 1];
  const double l10 = loss_[(i + 1) * nt + j], l11 = loss_[(i + 1) * nt + j + 1];
  return (1 - a) * ((1 - b) * l00 + b * l01) + a * ((1 - b) * l10 + b * l11);
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
