#include "common/table2d.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace hbt {

Table2D::Table2D(std::vector<double> x, std::vector<double> y, std::vector<double> v,
                 const std::string& file, const std::string& key)
    : x_(std::move(x)), y_(std::move(y)), v_(std::move(v)) {
  if (x_.size() < 2 || y_.size() < 2) throw InputError(file, key, "axes need at least 2 points");
  auto increasing = [](const std::vector<double>& a) {
    for (std::size_t i = 0; i < a.size(); ++i)
      if (!std::isfinite(a[i]) || (i > 0 && !(a[i] > a[i - 1]))) return false;
    return true;
  };
  if (!increasing(x_)) throw InputError(file, key, "first axis must strictly increase");
  if (!increasing(y_)) throw InputError(file, key, "second axis must strictly increase");
  if (v_.size() != x_.size() * y_.size())
    throw InputError(file, key,
                     "table needs " + std::to_string(x_.size() * y_.size()) +
                         " values (rows x columns, row-major), got " + std::to_string(v_.size()));
  for (double z : v_)
    if (!std::isfinite(z)) throw InputError(file, key, "table value is NaN or infinite");
}

double Table2D::operator()(double x, double y) const {
  auto locate = [](const std::vector<double>& a, double q, std::size_t& i, double& f) {
    q = std::clamp(q, a.front(), a.back());
    i = static_cast<std::size_t>(std::upper_bound(a.begin(), a.end(), q) - a.begin());
    i = std::min(i == 0 ? 0 : i - 1, a.size() - 2);
    f = (q - a[i]) / (a[i + 1] - a[i]);
  };
  std::size_t i, j;
  double fx, fy;
  locate(x_, x, i, fx);
  locate(y_, y, j, fy);
  const std::size_t ny = y_.size();
  const double v00 = v_[i * ny + j], v01 = v_[i * ny + j + 1];
  const double v10 = v_[(i + 1) * ny + j], v11 = v_[(i + 1) * ny + j + 1];
  return (1 - fx) * ((1 - fy) * v00 + fy * v01) + fx * ((1 - fy) * v10 + fy * v11);
}

}  // namespace hbt
