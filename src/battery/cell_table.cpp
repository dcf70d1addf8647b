#include "battery/cell_table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "common/csv_table.hpp"
#include "common/errors.hpp"

namespace hbt::battery {

namespace {
std::vector<double> uniqueSorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}
std::size_t indexOf(const std::vector<double>& axis, double q) {
  return static_cast<std::size_t>(std::lower_bound(axis.begin(), axis.end(), q) - axis.begin());
}
}  // namespace

double CellTable::arrhenius(double r1, double r2, double T1_K, double T2_K, double T_K) {
  const double theta_K = std::max(0.0, std::log(r1 / r2) / (1.0 / T1_K - 1.0 / T2_K));
  return r1 * std::exp(theta_K * (1.0 / T_K - 1.0 / T1_K));
}

CellPoint CellTable::at(double soc, double T_K) const {
  const std::vector<double>& T = ocv_.y();
  const double T1 = T[0];
  if (T_K >= T1) return {ocv_(soc, T_K), r0_(soc, T_K), r1_(soc, T_K), tau_(soc, T_K)};
  const double T2 = T[1];
  return {ocv_(soc, T1), arrhenius(r0_(soc, T1), r0_(soc, T2), T1, T2, T_K),
          arrhenius(r1_(soc, T1), r1_(soc, T2), T1, T2, T_K), tau_(soc, T1)};
}

CellTable CellTable::read(const std::string& path) {
  const CsvTable t = CsvTable::read(path);
  const auto& s = t.column("SOC");
  const auto& T = t.column("T");
  const auto& ocv = t.column("OCV");
  const auto& r0 = t.column("R0");
  const auto& r1 = t.column("R1");
  const auto& tau = t.column("tau1");
  const std::vector<double> sa = uniqueSorted(s), ta = uniqueSorted(T);
  if (sa.size() < 2) throw InputError(path, "SOC", "needs at least 2 distinct SOC values");
  if (ta.size() < 2) throw InputError(path, "T", "needs at least 2 distinct temperatures");
  if (sa.front() < 0.0 || sa.back() > 1.0) throw InputError(path, "SOC", "values must lie in [0, 1]");
  if (!(ta.front() > 0.0)) throw InputError(path, "T", "temperatures must be > 0 K");
  const std::size_t ns = sa.size(), nt = ta.size();
  if (t.rows() != ns * nt) {
    std::ostringstream os;
    os << "expected a full grid of " << ns << " SOC x " << nt << " T = " << ns * nt << " rows, got " << t.rows();
    throw InputError(path, "SOC", os.str());
  }
  std::vector<double> vo(ns * nt), v0(ns * nt), v1(ns * nt), vt(ns * nt);
  std::vector<char> seen(ns * nt, 0);
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::size_t k = indexOf(sa, s[r]) * nt + indexOf(ta, T[r]);
    if (seen[k]) {
      std::ostringstream os;
      os << "grid point SOC " << s[r] << ", T " << T[r] << " K appears twice (data row " << r + 1 << ")";
      throw InputError(path, "SOC", os.str());
    }
    seen[k] = 1;
    auto positive = [&](double v, const char* col) {
      if (!(v > 0.0)) {
        std::ostringstream os;
        os << "must be > 0 (data row " << r + 1 << ": " << v << ")";
        throw InputError(path, col, os.str());
      }
    };
    positive(ocv[r], "OCV");
    positive(r0[r], "R0");
    positive(r1[r], "R1");
    positive(tau[r], "tau1");
    vo[k] = ocv[r];
    v0[k] = r0[r];
    v1[k] = r1[r];
    vt[k] = tau[r];
  }
  for (std::size_t j = 0; j < nt; ++j)
    for (std::size_t i = 1; i < ns; ++i)
      if (!(vo[i * nt + j] > vo[(i - 1) * nt + j])) {
        std::ostringstream os;
        os << "OCV must increase strictly with SOC (T " << ta[j] << " K, SOC " << sa[i - 1] << " -> " << sa[i] << ")";
        throw InputError(path, "OCV", os.str());
      }
  CellTable c;
  c.ocv_ = Table2D(sa, ta, vo, path, "OCV");
  c.r0_ = Table2D(sa, ta, v0, path, "R0");
  c.r1_ = Table2D(sa, ta, v1, path, "R1");
  c.tau_ = Table2D(sa, ta, vt, path, "tau1");
  return c;
}

}  // namespace hbt::battery
