// Delaunay/barycentric scattered-point interpolation: exact on data points and on planes
// (inside and, by nearest-triangle extrapolation, outside the hull); the triangulation covers
// exactly the convex hull and satisfies the empty-circumcircle (Delaunay) property; the cell
// index of the look-up finds the triangle an ordered scan finds.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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

TEST(ScatteredMap, CellIndexFindsTheTriangleAnOrderedScanFinds) {
  // The look-up's cell indices against a plain scan of all triangles in order (the same
  // normalisation and arithmetic, written out here): bit-identical values on the reference
  // map's points, on the midpoints of every edge (shared by two triangles: the first in order
  // wins), on a dense grid reaching beyond the hull (nearest-triangle extrapolation) and on
  // random points near and far; inside() agrees.
  const auto pts = readFuelMap("config/data/engine/generic_primary_bus_7.7l_200kW/FCMap.vmap");
  const ScatteredLinearMap m(pts.speed_rad_s, pts.torque_Nm, pts.fuel_kg_s, pts.source);
  const auto& X = pts.speed_rad_s;
  const auto& Y = pts.torque_Nm;
  const auto& Z = pts.fuel_kg_s;
  const auto [x0, x1] = std::minmax_element(X.begin(), X.end());
  const auto [y0, y1] = std::minmax_element(Y.begin(), Y.end());
  const double sx = 1.0 / (*x1 - *x0), sy = 1.0 / (*y1 - *y0);
  const auto U = [&](double x) { return (x - *x0) * sx; };
  const auto V = [&](double y) { return (y - *y0) * sy; };
  const auto bary = [&](std::size_t k, double qu, double qv) {
    const auto& t = m.triangle(k);
    const double ax = U(X[t[0]]), ay = V(Y[t[0]]), bx = U(X[t[1]]), by = V(Y[t[1]]), cx = U(X[t[2]]);
    const double cy = V(Y[t[2]]);
    const double det = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    const double lb = ((qu - ax) * (cy - ay) - (qv - ay) * (cx - ax)) / det;
    const double lc = ((bx - ax) * (qv - ay) - (by - ay) * (qu - ax)) / det;
    return std::array<double, 3>{1.0 - lb - lc, lb, lc};
  };
  const auto seg2 = [](double pu, double pv, double au, double av, double bu, double bv) {
    const double du = bu - au, dv = bv - av, l2 = du * du + dv * dv;
    const double t = std::clamp(l2 > 0.0 ? ((pu - au) * du + (pv - av) * dv) / l2 : 0.0, 0.0, 1.0);
    const double eu = au + t * du - pu, ev = av + t * dv - pv;
    return eu * eu + ev * ev;
  };
  // (value, inside) by an ordered scan: the first containing triangle, else the first nearest
  auto scan = [&](double x, double y, bool& in) {
    const double qu = U(x), qv = V(y);
    std::size_t hit = 0;
    in = false;
    for (std::size_t k = 0; k < m.triangleCount() && !in; ++k) {
      const auto l = bary(k, qu, qv);
      if (l[0] >= -1e-12 && l[1] >= -1e-12 && l[2] >= -1e-12) { hit = k; in = true; }
    }
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < m.triangleCount() && !in; ++k) {
      const auto& t = m.triangle(k);
      double d = std::numeric_limits<double>::infinity();
      for (int e = 0; e < 3; ++e) {
        const int a = t[e], b = t[(e + 1) % 3];
        d = std::min(d, seg2(qu, qv, U(X[a]), V(Y[a]), U(X[b]), V(Y[b])));
      }
      if (d < best) { best = d; hit = k; }
    }
    const auto l = bary(hit, qu, qv);
    const auto& t = m.triangle(hit);
    return l[0] * Z[t[0]] + l[1] * Z[t[1]] + l[2] * Z[t[2]];
  };
  std::vector<std::pair<double, double>> q;
  for (std::size_t i = 0; i < X.size(); ++i) q.emplace_back(X[i], Y[i]);
  for (std::size_t k = 0; k < m.triangleCount(); ++k)
    for (int e = 0; e < 3; ++e) {
      const int a = m.triangle(k)[e], b = m.triangle(k)[(e + 1) % 3];
      q.emplace_back(0.5 * (X[a] + X[b]), 0.5 * (Y[a] + Y[b]));
    }
  const double wx = *x1 - *x0, wy = *y1 - *y0;
  for (int i = 0; i <= 240; ++i)  // -0.7 .. 1.7 of the map's extent: inside, outer grid, beyond
    for (int j = 0; j <= 240; ++j) q.emplace_back(*x0 + wx * (-0.7 + i / 100.0), *y0 + wy * (-0.7 + j / 100.0));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> f(-0.6, 1.6);
  for (int i = 0; i < 20000; ++i) q.emplace_back(*x0 + wx * f(rng), *y0 + wy * f(rng));
  int inside = 0, outside = 0;
  for (const auto& [x, y] : q) {
    bool in = false;
    const double z = scan(x, y, in);
    ASSERT_EQ(m.inside(x, y), in) << "at " << x << ", " << y;
    ASSERT_EQ(m(x, y), z) << "at " << x << ", " << y << (in ? " (inside)" : " (outside)");
    ++(in ? inside : outside);
  }
  EXPECT_GT(inside, 10000);
  EXPECT_GT(outside, 30000);
}

TEST(ScatteredMap, BadInputRejected) {
  EXPECT_THROW(ScatteredLinearMap({0, 1}, {0, 1}, {0, 1}, "two"), InputError);
  EXPECT_THROW(ScatteredLinearMap({0, 1, 2}, {0, 1, 2}, {0, 1, 2}, "collinear"), InputError);
  EXPECT_THROW(ScatteredLinearMap({0, 1, 0, 0}, {0, 0, 1, 0}, {0, 1, 2, 3}, "dup"), InputError);
  EXPECT_THROW(ScatteredLinearMap({0, 1, 0}, {0, 0, NAN}, {0, 1, 2}, "nan"), InputError);
}
