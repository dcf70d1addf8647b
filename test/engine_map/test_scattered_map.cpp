// Delaunay/barycentric scattered-point interpolation: exact on data points and on planes
// (inside and, by nearest-triangle extrapolation, outside the hull); the triangulation covers
// exactly the convex hull and satisfies the empty-circumcircle (Delaunay) property.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "common/errors.hpp"
#include "engine_map/scattered_map.hpp"
#include "engine_map/vecto_engine_files.hpp"

using namespace hbt;
using namespace hbt::engine_map;

namespace {

double plane(double x, double y) { return 3.5 - 0.25 * x + 7.0e-3 * y; }

// Checks the Delaunay property in normalised coordinates: no data point strictly inside the
// circumcircle of any triangle (relative tolerance for co-circular grid points).
void expectDelaunay(const ScatteredLinearMap& m, const std::vector<double>& x,
                    const std::vector<double>& y) {
  const auto [x0, x1] = std::minmax_element(x.begin(), x.end());
  const auto [y0, y1] = std::minmax_element(y.begin(), y.end());
  auto U = [&](std::size_t i) { return (x[i] - *x0) / (*x1 - *x0); };
  auto V = [&](std::size_t i) { return (y[i] - *y0) / (*y1 - *y0); };
  for (std::size_t k = 0; k < m.triangleCount(); ++k) {
    const auto& t = m.triangle(k);
    const double ax = U(t[0]), ay = V(t[0]), bx = U(t[1]), by = V(t[1]), cx = U(t[2]), cy = V(t[2]);
    const double d = 2.0 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by));
    const double ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) +
                       (cx * cx + cy * cy) * (ay - by)) / d;
    const double uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) +
                       (cx * cx + cy * cy) * (bx - ax)) / d;
    const double r2 = (ax - ux) * (ax - ux) + (ay - uy) * (ay - uy);
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (static_cast<int>(i) == t[0] || static_cast<int>(i) == t[1] || static_cast<int>(i) == t[2]) continue;
      const double d2 = (U(i) - ux) * (U(i) - ux) + (V(i) - uy) * (V(i) - uy);
      EXPECT_GE(d2, r2 * (1.0 - 1e-9)) << "point " << i << " inside circumcircle of triangle " << k;
    }
  }
}

}  // namespace

TEST(ScatteredMap, RandomPointsReproducePlaneEverywhere) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> ux(600.0, 2600.0), uy(-150.0, 1100.0);
  std::vector<double> x, y, z;
  for (int i = 0; i < 80; ++i) {
    x.push_back(ux(rng));
    y.push_back(uy(rng));
    z.push_back(plane(x.back(), y.back()));
  }
  const ScatteredLinearMap m(x, y, z, "random");
  EXPECT_NEAR(m.totalAreaNormalised(), m.hullAreaNormalised(), 1e-12);
  expectDelaunay(m, x, y);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(m(x[i], y[i]), z[i], 1e-12);
  std::uniform_real_distribution<double> qx(400.0, 2800.0), qy(-300.0, 1300.0);  // incl. outside
  for (int i = 0; i < 500; ++i) {
    const double a = qx(rng), b = qy(rng);
    EXPECT_NEAR(m(a, b), plane(a, b), 1e-9) << a << " " << b;
  }
}

TEST(ScatteredMap, RegularGridIsValidAndExact) {
  // Many collinear and co-circular points: the hard case for Delaunay insertion.
  std::vector<double> x, y, z;
  for (int i = 0; i <= 6; ++i)
    for (int j = 0; j <= 5; ++j) {
      x.push_back(100.0 * i);
      y.push_back(50.0 * j);
      z.push_back(plane(x.back(), y.back()));
    }
  const ScatteredLinearMap m(x, y, z, "grid");
  EXPECT_EQ(m.triangleCount(), 2u * 6u * 5u);
  EXPECT_NEAR(m.totalAreaNormalised(), 1.0, 1e-12);
  expectDelaunay(m, x, y);
  EXPECT_NEAR(m(333.0, 77.0), plane(333.0, 77.0), 1e-10);
  EXPECT_NEAR(m(-50.0, 300.0), plane(-50.0, 300.0), 1e-10);
}

TEST(ScatteredMap, LinearBetweenTwoPointsOfAnEdge) {
  // Square with values only at the corners: along an outer edge the value is the linear blend.
  const ScatteredLinearMap m({0, 1, 0, 1}, {0, 0, 1, 1}, {0.0, 2.0, 5.0, 11.0}, "square");
  EXPECT_NEAR(m(0.25, 0.0), 0.5, 1e-14);
  EXPECT_NEAR(m(0.0, 0.6), 3.0, 1e-14);
  EXPECT_NEAR(m(1.0, 0.5), 6.5, 1e-14);
}

TEST(ScatteredMap, VectoReferenceMapPointsExactAndTriangulationValid) {
  const auto pts = readFuelMap("config/data/engine/generic_primary_bus_7.7l_200kW/FCMap.vmap");
  const ScatteredLinearMap m(pts.speed_rad_s, pts.torque_Nm, pts.fuel_kg_s, pts.source);
  EXPECT_NEAR(m.totalAreaNormalised(), m.hullAreaNormalised(), 1e-12);
  expectDelaunay(m, pts.speed_rad_s, pts.torque_Nm);
  for (std::size_t i = 0; i < pts.fuel_kg_s.size(); ++i)
    EXPECT_NEAR(m(pts.speed_rad_s[i], pts.torque_Nm[i]), pts.fuel_kg_s[i],
                1e-18 + 1e-13 * pts.fuel_kg_s[i]) << "point " << i;
}

TEST(ScatteredMap, BadInputRejected) {
  EXPECT_THROW(ScatteredLinearMap({0, 1}, {0, 1}, {0, 1}, "two"), InputError);
  EXPECT_THROW(ScatteredLinearMap({0, 1, 2}, {0, 1, 2}, {0, 1, 2}, "collinear"), InputError);
  EXPECT_THROW(ScatteredLinearMap({0, 1, 0, 0}, {0, 0, 1, 0}, {0, 1, 2, 3}, "dup"), InputError);
  EXPECT_THROW(ScatteredLinearMap({0, 1, 0}, {0, 0, NAN}, {0, 1, 2}, "nan"), InputError);
}
