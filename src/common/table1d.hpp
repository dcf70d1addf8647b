// Piecewise-linear table y(x) with x strictly increasing; constant extrapolation at both ends
// (or linear extrapolation when asked). Look-up is O(log n) with no allocation.
#pragma once
#include <string>
#include <vector>

namespace hbt {

class Table1D {
 public:
  Table1D() = default;
  /// Throws InputError(source, key, ...) if sizes differ, fewer than 2 points, x not increasing.
  Table1D(std::vector<double> x, std::vector<double> y, const std::string& source = "table",
          const std::string& key = "x");
  double operator()(double x) const;          // clamped at the ends
  double extrapolated(double x) const;        // linear continuation of the end segments
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  bool empty() const { return x_.empty(); }
  double xMin() const { return x_.front(); }
  double xMax() const { return x_.back(); }

 private:
  std::size_t segment(double x) const;  // i with x_[i] <= x < x_[i+1], clamped to [0, n-2]
  std::vector<double> x_, y_;
};

}  // namespace hbt
