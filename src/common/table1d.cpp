#include "common/table1d.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace hbt {

Table1D::Table1D(std::vector<double> x, std::vector<double> y, const std::string& source,
                 const std::string& key)
    : x_(std::move(x)), y_(std::move(y)) {
  if (x_.size() != y_.size())
    throw InputError(source, key, "x and y have different lengths");
  if (x_.size() < 2) throw InputError(source, key, "a table needs at least 2 points");
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]))
      throw InputError(source, key, "non-finite value at point " + std::to_string(i));
    if (i > 0 && !(x_[i] > x_[i - 1]))
      throw InputError(source, key, "x must be strictly increasing (point " + std::to_string(i) + ")");
  }
}

std::size_t Table1D::segment(double x) const {
  const auto it = std::upper_bound(x_.begin(), x_.end(), x);
  std::size_t i = static_cast<std::size_t>(it - x_.begin());
  i = i == 0 ? 0 : i - 1;
  return std::min(i, x_.size() - 2);
}

double Table1D::operator()(double x) const {
  if (x <= x_.front()) return y_.front();
  if (x >= x_.back()) return y_.back();
  return extrapolated(x);
}

double Table1D::extrapolated(double x) const {
  const std::size_t i = segment(x);
  const double w = (x - x_[i]) / (x_[i + 1] - x_[i]);
  return y_[i] + w * (y_[i + 1] - y_[i]);
}

}  // namespace hbt
