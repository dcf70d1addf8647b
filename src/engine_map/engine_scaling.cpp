#include "engine_map/engine_scaling.hpp"

#include <algorithm>
#include <limits>

#include "common/errors.hpp"

namespace hbt::engine_map {

double peakTorque(const FullLoadCurve& c) {
  return *std::max_element(c.full_load_Nm.begin(), c.full_load_Nm.end());
}

double peakPower(const FullLoadCurve& c, double* speed_at_peak_rad_s) {
  double best = -std::numeric_limits<double>::infinity(), wbest = 0.0;  // peak power [W] so far
  auto consider = [&](double w, double p) {
    if (p > best) { best = p; wbest = w; }
  };
  const auto& w = c.speed_rad_s;
  const auto& t = c.full_load_Nm;
  for (std::size_t i = 0; i < w.size(); ++i) consider(w[i], w[i] * t[i]);
  for (std::size_t i = 0; i + 1 < w.size(); ++i) {
    // P(ω) = ω (t_i + s (ω - ω_i)); dP/dω = t_i + s (2ω - ω_i) = 0.
    const double s = (t[i + 1] - t[i]) / (w[i + 1] - w[i]);
    if (s >= 0.0) continue;  // P increasing on the segment: maximum at a vertex
    const double ws = (s * w[i] - t[i]) / (2.0 * s);
    if (ws > w[i] && ws < w[i + 1]) consider(ws, ws * (t[i] + s * (ws - w[i])));
  }
  if (speed_at_peak_rad_s) *speed_at_peak_rad_s = wbest;
  return best;
}

EngineScaling computeScaling(const FullLoadCurve& ref, double target_peak_torque_Nm,
                             double target_peak_power_W, bool scale_speed) {
  EngineScaling s;
  s.ref_peak_torque_Nm = peakTorque(ref);
  s.ref_peak_power_W = peakPower(ref, &s.ref_peak_power_speed_rad_s);
  if (!(s.ref_peak_torque_Nm > 0.0) || !(s.ref_peak_power_W > 0.0))
    throw InputError(ref.source, "full load torque", "no positive full-load torque/power");
  if (!(target_peak_torque_Nm > 0.0))
    throw InputError(ref.source, "target_peak_torque_Nm", "must be > 0");
  s.torque_factor = target_peak_torque_Nm / s.ref_peak_torque_Nm;
  if (scale_speed) {
    if (!(target_peak_power_W > 0.0))
      throw InputError(ref.source, "target_peak_power_W", "must be > 0");
    s.speed_factor = target_peak_power_W / (s.torque_factor * s.ref_peak_power_W);
  }
  s.fuel_factor = s.torque_factor * s.speed_factor;
  return s;
}

FullLoadCurve applyScaling(const FullLoadCurve& c, const EngineScaling& s) {
  FullLoadCurve o = c;
  for (auto& w : o.speed_rad_s) w *= s.speed_factor;
  for (auto& t : o.full_load_Nm) t *= s.torque_factor;
  for (auto& t : o.motoring_Nm) t *= s.torque_factor;
  return o;
}

FuelMapPoints applyScaling(const FuelMapPoints& m, const EngineScaling& s) {
  FuelMapPoints o = m;
  for (auto& w : o.speed_rad_s) w *= s.speed_factor;
  for (auto& t : o.torque_Nm) t *= s.torque_factor;
  for (auto& f : o.fuel_kg_s) f *= s.fuel_factor;
  return o;
}

Table1D applySpeedScaling(const Table1D& pt1, const EngineScaling& s) {
  std::vector<double> w = pt1.x();
  for (auto& x : w) x *= s.speed_factor;
  return Table1D(w, pt1.y(), "PT1 (scaled)", "rpm");
}

}  // namespace hbt::engine_map
