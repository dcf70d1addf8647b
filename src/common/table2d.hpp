// Bilinear table z(x, y) on a rectilinear grid (axes strictly increasing, values row-major:
// z[i * ny + j] at (x[i], y[j])), clamped at the grid edges. Look-up O(log n), no allocation.
// Used for speed x load calibration maps, the boost target and the gearbox loss map.
#pragma once
#include <string>
#include <vector>

namespace hbt {

class Table2D {
 public:
  Table2D() = default;
  /// Throws InputError(file, key) unless both axes have >= 2 strictly increasing finite points
  /// and values.size() == x.size() * y.size() with finite values.
  Table2D(std::vector<double> x, std::vector<double> y, std::vector<double> values,
          const std::string& file, const std::string& key);
  double operator()(double x, double y) const;
  bool empty() const { return v_.empty(); }
  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }

 private:
  std::vector<double> x_, y_, v_;
};

}  // namespace hbt
