#include "emachine/torque_envelope.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::emachine {

namespace {
double clamp01(double x) { return std::min(1.0, std::max(0.0, x)); }
}  // namespace

TorqueEnvelope::TorqueEnvelope(const std::string& vemp_path, double nominal_voltage_V,
                               double max_effective_voltage_V, double undervoltage_zero_V,
                               double undervoltage_full_V, double continuous_power_W,
                               double continuous_torque_Nm) {
  const CsvTable t = CsvTable::read(vemp_path);
  const auto& n = t.column("n");
  const auto& td = t.column("T_drive");
  const auto& tr = t.column("T_recuperation");
  std::vector<double> w(n.size());
  for (std::size_t i = 0; i < n.size(); ++i) w[i] = units::rpmToRadps(n[i]);
  *this = TorqueEnvelope(w, td, tr, vemp_path, nominal_voltage_V, max_effective_voltage_V,
                         undervoltage_zero_V, undervoltage_full_V, continuous_power_W,
                         continuous_torque_Nm);
}

TorqueEnvelope::TorqueEnvelope(std::vector<double> w, std::vector<double> drive,
                               std::vector<double> recup, const std::string& source,
                               double nominal_voltage_V, double max_effective_voltage_V,
                               double undervoltage_zero_V, double undervoltage_full_V,
                               double continuous_power_W, double continuous_torque_Nm)
    : V_nom_(nominal_voltage_V), V_max_(max_effective_voltage_V), V0_(undervoltage_zero_V),
      V1_(undervoltage_full_V), P_cont_(continuous_power_W), T_cont_(continuous_torque_Nm) {
  if (w.size() != drive.size() || w.size() != recup.size())
    throw InputError(source, "n", "columns of different length");
  for (std::size_t i = 0; i < w.size(); ++i) {
    if (!(w[i] >= 0.0)) throw InputError(source, "n", "negative speed in row " + std::to_string(i + 1));
    if (!(drive[i] >= 0.0))
      throw InputError(source, "T_drive", "negative drive torque in row " + std::to_string(i + 1));
    if (!(recup[i] <= 0.0))
      throw InputError(source, "T_recuperation", "positive recuperation torque in row " + std::to_string(i + 1));
  }
  std::vector<std::size_t> idx(w.size());
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return w[a] < w[b]; });
  for (std::size_t k = 0; k < idx.size(); ++k) {
    const std::size_t i = idx[k];
    if (!w_.empty() && w[i] == w_.back()) {
      if (drive[i] != drive_.back() || -recup[i] != recup_.back())
        throw InputError(source, "n", "the same speed is listed twice with different torques");
      continue;  // exact duplicate
    }
    w_.push_back(w[i]);
    drive_.push_back(drive[i]);
    recup_.push_back(-recup[i]);
  }
  if (w_.size() < 2) throw InputError(source, "n", "need at least two distinct speeds");
}

double TorqueEnvelope::speedScale(double V) const {
  return std::max(0.0, std::min(V, V_max_)) / V_nom_;
}

double TorqueEnvelope::undervoltageFactor(double V) const { return clamp01((V - V0_) / (V1_ - V0_)); }

double TorqueEnvelope::nominal(double w, const std::vector<double>& T) const {
  if (w <= w_.front()) return T.front();
  const std::size_t n = w_.size();
  if (w >= w_.back()) return T.back() * w_.back() / w;  // last power held
  const std::size_t i =
      static_cast<std::size_t>(std::upper_bound(w_.begin(), w_.end(), w) - w_.begin()) - 1;
  const std::size_t j = std::min(i + 1, n - 1);
  const double a = (w - w_[i]) / (w_[j] - w_[i]);
  if (w_[i] <= 0.0) return T[i] + a * (T[j] - T[i]);  // segment from standstill: torque
  const double Pi = T[i] * w_[i], Pj = T[j] * w_[j];
  return (Pi + a * (Pj - Pi)) / w;  // power linear in speed
}

double TorqueEnvelope::peak(double w, double V, const std::vector<double>& T) const {
  const double s = speedScale(V), u = undervoltageFactor(V);
  if (!(s > 0.0) || !(u > 0.0)) return 0.0;
  return u * nominal(std::max(0.0, w) / s, T);
}

double TorqueEnvelope::continuousMagnitude(double w, double V) const {
  const double s = speedScale(V), u = undervoltageFactor(V);
  if (!(s > 0.0) || !(u > 0.0)) return 0.0;
  double T = T_cont_;
  if (w > 0.0) T = std::min(T, s * P_cont_ / w);
  return u * T;
}

double TorqueEnvelope::continuousDrive(double w, double V) const {
  return std::min(continuousMagnitude(w, V), peakDrive(w, V));
}

double TorqueEnvelope::continuousRecup(double w, double V) const {
  return -std::min(continuousMagnitude(w, V), -peakRecup(w, V));
}

}  // namespace hbt::emachine
