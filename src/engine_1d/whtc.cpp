#include "engine_1d/whtc.hpp"

#include <algorithm>
#include <cmath>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::engine_1d {

GtrReferenceSpeeds gtrReferenceSpeeds(const std::function<double(double)>& fl, double n_idle,
                                      double n_max) {
  GtrReferenceSpeeds s;
  s.n_idle = n_idle;
  std::vector<double> n, P;
  for (double x = n_idle; x <= n_max + 1e-9; x += 1.0) {
    n.push_back(x);
    P.push_back(fl(x) * units::rpmToRadps(x));
  }
  if (n.size() < 10) throw InputError("whtc", "full load", "speed range too small");
  const auto it = std::max_element(P.begin(), P.end());
  s.p_max_W = *it;
  s.n_pmax = n[it - P.begin()];
  auto lowest = [&](double frac) {
    for (std::size_t i = 1; i < n.size(); ++i)
      if (P[i] >= frac * s.p_max_W) {
        const double f = (frac * s.p_max_W - P[i - 1]) / (P[i] - P[i - 1]);
        return n[i - 1] + std::clamp(f, 0.0, 1.0) * (n[i] - n[i - 1]);
      }
    return n.front();
  };
  auto highest = [&](double frac) {
    for (std::size_t i = n.size() - 1; i > 0; --i)
      if (P[i - 1] >= frac * s.p_max_W) {
        if (P[i] >= frac * s.p_max_W) return n[i];
        const double f = (P[i - 1] - frac * s.p_max_W) / (P[i - 1] - P[i]);
        return n[i - 1] + std::clamp(f, 0.0, 1.0) * (n[i] - n[i - 1]);
      }
    return n.back();
  };
  s.n_lo = lowest(0.55);
  s.n_hi = highest(0.70);
  s.n_95h = highest(0.95);
  // n_pref: 51 % of the torque integral between n_idle and n_95h (trapezoidal, 1 rpm steps)
  double total = 0.0;
  std::vector<double> cum(n.size(), 0.0);
  for (std::size_t i = 1; i < n.size() && n[i] <= s.n_95h; ++i) {
    total += 0.5 * (fl(n[i]) + fl(n[i - 1])) * (n[i] - n[i - 1]);
    cum[i] = total;
  }
  s.n_pref = n_idle;
  for (std::size_t i = 1; i < n.size(); ++i)
    if (cum[i] >= 0.51 * total) {
      const double f = (0.51 * total - cum[i - 1]) / (cum[i] - cum[i - 1]);
      s.n_pref = n[i - 1] + f * (n[i] - n[i - 1]);
      break;
    }
  return s;
}

std::vector<WhtcPoint> denormaliseWhtc(const std::string& path, const GtrReferenceSpeeds& s,
                                       const std::function<double(double)>& fl,
                                       const std::function<double(double)>& mot) {
  const CsvTable t = CsvTable::read(path);
  const auto& time = t.column("time");
  const auto& nn = t.column("n_norm");
  const auto& tn = t.column("T_norm");
  const double span = (0.45 * s.n_lo + 0.45 * s.n_pref + 0.1 * s.n_hi - s.n_idle) * 2.0327;
  std::vector<WhtcPoint> out(t.rows());
  for (std::size_t i = 0; i < t.rows(); ++i) {
    if (tn[i] < -1.0 || tn[i] > 100.0 || nn[i] < -5.0 || nn[i] > 110.0)
      throw InputError(path, "T_norm", "value out of range on row " + std::to_string(i + 1));
    WhtcPoint& p = out[i];
    p.t_s = time[i];
    p.n_rpm = nn[i] / 100.0 * span + s.n_idle;
    p.motoring = tn[i] == -1.0;
    p.torque_Nm = p.motoring ? mot(p.n_rpm) : tn[i] / 100.0 * fl(p.n_rpm);
  }
  return out;
}

Regression regress(const std::vector<double>& x, const std::vector<double>& y) {
  Regression r;
  r.n = static_cast<int>(std::min(x.size(), y.size()));
  if (r.n < 3) return r;
  double sx = 0, sy = 0;
  for (int i = 0; i < r.n; ++i) sx += x[i], sy += y[i];
  const double mx = sx / r.n, my = sy / r.n;
  double sxx = 0, sxy = 0, syy = 0;
  for (int i = 0; i < r.n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  r.slope = sxx > 0 ? sxy / sxx : 0.0;
  r.intercept = my - r.slope * mx;
  double sse = 0;
  for (int i = 0; i < r.n; ++i) {
    const double e = y[i] - (r.slope * x[i] + r.intercept);
    sse += e * e;
  }
  r.see = std::sqrt(sse / (r.n - 2));
  r.r2 = syy > 0 ? 1.0 - sse / syy : 1.0;
  return r;
}

RegressionLimits torqueLimits(double tmax) {
  return {0.10 * tmax, 0.83, 1.03, 0.850, std::max(20.0, 0.02 * tmax)};
}
RegressionLimits speedLimits(double nmax) { return {0.05 * nmax, 0.95, 1.03, 0.970, 10.0}; }
RegressionLimits powerLimits(double pmax) {
  return {0.10 * pmax, 0.83, 1.03, 0.910, std::max(4000.0, 0.02 * pmax)};
}

}  // namespace hbt::engine_1d
