#include "mission/driving_cycle.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::mission {
namespace {

// File line numbers of the data rows (same skipping rules as hbt::CsvTable: blank lines and
// '#' comments are skipped, the first remaining line is the header).
std::vector<std::size_t> dataRowLines(const std::string& path) {
  std::vector<std::size_t> lines;
  std::ifstream in(path);
  std::string line;
  std::size_t no = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++no;
    const auto b = line.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    if (b == std::string::npos || line[b] == '#') continue;
    if (!header) { header = true; continue; }
    lines.push_back(no);
  }
  return lines;
}

using RowLabel = std::function<std::string(std::size_t)>;

DrivingCycle validate(const std::string& source, const std::vector<double>& s,
                      const std::vector<double>& v_kmh, const std::vector<double>& grad,
                      const std::vector<double>& stop, const RowLabel& row) {
  const std::size_t n = s.size();
  if (v_kmh.size() != n || grad.size() != n || stop.size() != n)
    throw InputError(source, "(columns)", "columns s, v, grad, stop have different lengths");
  if (n < 2) throw InputError(source, "s", "a cycle needs at least 2 rows");
  auto fmt = [](double x) { std::ostringstream os; os << x; return os.str(); };
  for (std::size_t k = 0; k < n; ++k) {
    const char* names[4] = {"s", "v", "grad", "stop"};
    const double vals[4] = {s[k], v_kmh[k], grad[k], stop[k]};
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(vals[c]))
        throw InputError(source, names[c], row(k) + ": value is NaN or infinite");
    if (k > 0 && !(s[k] > s[k - 1]))
      throw InputError(source, "s", row(k) + ": distance " + fmt(s[k]) +
                                        " m is not greater than the previous " + fmt(s[k - 1]) +
                                        " m (must be strictly increasing)");
    if (v_kmh[k] < 0.0)
      throw InputError(source, "v", row(k) + ": negative target speed " + fmt(v_kmh[k]) + " km/h");
    if (v_kmh[k] > kMaxTargetSpeed_kmh)
      throw InputError(source, "v", row(k) + ": target speed " + fmt(v_kmh[k]) +
                                        " km/h above the sanity limit " +
                                        fmt(kMaxTargetSpeed_kmh) + " km/h");
    if (std::fabs(grad[k]) > kMaxAbsGrade_percent)
      throw InputError(source, "grad", row(k) + ": |gradient| " + fmt(grad[k]) +
                                           " % above the sanity limit " +
                                           fmt(kMaxAbsGrade_percent) + " %");
    if (stop[k] < 0.0)
      throw InputError(source, "stop", row(k) + ": negative stop time " + fmt(stop[k]) + " s");
    if (stop[k] > 0.0 && v_kmh[k] > 0.0)
      throw InputError(source, "stop", row(k) + ": stop time " + fmt(stop[k]) +
                                           " s on a row with target speed " + fmt(v_kmh[k]) +
                                           " km/h > 0 (stops need v = 0)");
  }
  DrivingCycle c;
  c.source = source;
  c.distance_m = s;
  c.grade_percent = grad;
  c.stop_time_s = stop;
  c.target_speed_m_s.resize(n);
  for (std::size_t k = 0; k < n; ++k) c.target_speed_m_s[k] = units::kmhToMps(v_kmh[k]);
  c.altitude_m.assign(n, 0.0);
  for (std::size_t k = 1; k < n; ++k)
    c.altitude_m[k] = c.altitude_m[k - 1] +
                      (s[k] - s[k - 1]) * grad[k - 1] / 100.0;
  return c;
}

}  // namespace

std::size_t DrivingCycle::stopCount() const {
  std::size_t n = 0;
  for (std::size_t k = 0; k < size(); ++k)
    if (isStopPoint(k) && stop_time_s[k] > 0.0) ++n;
  return n;
}

double DrivingCycle::totalStopTime_s() const {
  double t = 0.0;
  for (double x : stop_time_s) t += x;
  return t;
}

double DrivingCycle::intervalTarget_m_s(std::size_t k) const {
  if (!isStopPoint(k)) return target_speed_m_s[k];
  for (std::size_t j = k + 1; j < size(); ++j)  // drive off with the next positive target
    if (target_speed_m_s[j] > 0.0) return target_speed_m_s[j];
  return 0.0;
}

std::size_t DrivingCycle::intervalIndex(double s_m) const {
  if (s_m <= distance_m.front()) return 0;
  const auto it = std::upper_bound(distance_m.begin(), distance_m.end(), s_m);
  return static_cast<std::size_t>(it - distance_m.begin()) - 1;
}

double DrivingCycle::gradeAt(double s_m) const { return grade_percent[intervalIndex(s_m)]; }

double DrivingCycle::altitudeAt(double s_m) const {
  if (s_m <= distance_m.front()) return altitude_m.front();
  if (s_m >= distance_m.back()) return altitude_m.back();
  const std::size_t k = intervalIndex(s_m);
  const double w = (s_m - distance_m[k]) / (distance_m[k + 1] - distance_m[k]);
  return altitude_m[k] + w * (altitude_m[k + 1] - altitude_m[k]);
}

DrivingCycle readVdri(const std::string& path) {
  const CsvTable t = CsvTable::read(path);  // missing file, truncated rows, NaN -> InputError
  const auto& s = t.column("s");
  const auto& v = t.column("v");
  const auto& g = t.column("grad");
  const auto& st = t.column("stop");
  std::vector<std::size_t> lines;  // filled lazily, only when an error is reported
  const RowLabel row = [&](std::size_t k) {
    if (lines.empty()) lines = dataRowLines(path);
    return "line " + std::to_string(k < lines.size() ? lines[k] : k + 2);
  };
  return validate(path, s, v, g, st, row);
}

DrivingCycle makeCycle(const std::string& source, const std::vector<double>& s_m,
                       const std::vector<double>& v_kmh, const std::vector<double>& grad_percent,
                       const std::vector<double>& stop_s) {
  return validate(source, s_m, v_kmh, grad_percent, stop_s,
                  [](std::size_t k) { return "row " + std::to_string(k + 1); });
}

}  // namespace hbt::mission
