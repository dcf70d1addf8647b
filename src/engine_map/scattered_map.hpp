// Piecewise-linear interpolation on scattered points: Delaunay triangulation + barycentric
// interpolation, as VECTO does for its fuel maps (VectoCore "DelaunayMap").
//
// Let (x_i, y_i, z_i) be N scattered points. The axes are first normalised to [0, 1]
// (u = (x - x_min)/(x_max - x_min), v likewise) so that the triangulation does not depend on
// the units of the axes (rpm vs Nm); any per-axis affine scaling of the data (e.g. the engine
// scaling) therefore yields the same triangles. Inside a triangle (a, b, c)
//
//     z(x, y) = λ_a z_a + λ_b z_b + λ_c z_c,   λ = barycentric coordinates, Σλ = 1, λ >= 0,
//
// so every data point is reproduced exactly and any plane z = p0 + p1 x + p2 y is reproduced
// exactly everywhere. Outside the convex hull the plane of the nearest triangle (Euclidean
// distance in normalised coordinates) is continued linearly (λ may be negative): this
// reproduces a plane exactly also outside, and is continuous across the hull boundary of that
// triangle. Callers clamp their queries to the physical range (engine: speed range of the map,
// torque between motoring and full load), so extrapolation only covers thin edge slivers.
//
// Triangulation: Bowyer-Watson insertion in a large super-triangle, with the cavity grown as a
// connected set from the triangle containing the new point and pruned until it is star-shaped
// as seen from that point (robust with the many collinear and co-circular points of gridded
// VECTO maps). Built once in the constructor (allocates); look-ups do not allocate.
//
// Look-up: a uniform grid of about √(triangles) x √(triangles) cells over the unit square lists,
// per cell, the triangles whose bounding box (widened by a margin far above the barycentric
// tolerance) touches it, in increasing triangle order. A query tests only its cell's list and
// takes the first triangle that contains it: the same triangle a scan of all triangles in order
// finds, so the value is bit-identical to the plain scan, at a few triangles per query instead of
// all of them. Outside the hull a second grid over [-0.5, 1.5]^2 lists, per cell, the triangles
// that can be the nearest to some point of the cell (a distance bound), scanned in order with
// the same strict comparison as a scan of all triangles; farther queries scan all triangles.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace hbt::engine_map {

class ScatteredLinearMap {
 public:
  ScatteredLinearMap() = default;
  /// Throws InputError(source, "points", ...) for < 3 points, different lengths, non-finite
  /// values, duplicate points or all points collinear.
  ScatteredLinearMap(std::vector<double> x, std::vector<double> y, std::vector<double> z,
                     const std::string& source = "scattered map");

  /// Interpolated (inside the hull) or nearest-triangle extrapolated (outside) value.
  double operator()(double x, double y) const;
  /// True if (x, y) lies in (or on the boundary of) a triangle of the triangulation.
  bool inside(double x, double y) const;

  std::size_t triangleCount() const { return tri_.size(); }
  /// Vertex indices (into the input point list) of triangle k, counter-clockwise.
  const std::array<int, 3>& triangle(std::size_t k) const { return tri_[k]; }
  /// Sum of triangle areas in normalised coordinates (equals the convex-hull area).
  double totalAreaNormalised() const;
  /// Convex-hull area of the input points in normalised coordinates (independent check).
  double hullAreaNormalised() const;

 private:
  double u(double x) const { return (x - x0_) * sx_; }
  double v(double y) const { return (y - y0_) * sy_; }
  void triangulate(const std::string& source);
  /// Cells of a uniform grid over [lo, lo + cells*width]^2 (normalised coordinates), each with a
  /// list of triangle indices in increasing order: tris[start[c] .. start[c + 1]).
  struct CellIndex {
    double lo = 0.0, width = 1.0;
    int cells = 1;
    std::vector<int> start, tris;
    int cellOf(double c) const { return std::clamp(static_cast<int>(std::floor((c - lo) / width)), 0, cells - 1); }
    /// Cell of (qu, qv), -1 beyond the grid by more than margin.
    int cellIndex(double qu, double qv, double margin) const {
      const double hi = lo + cells * width;
      if (!(qu >= lo - margin && qu <= hi + margin && qv >= lo - margin && qv <= hi + margin)) return -1;
      return cellOf(qv) * cells + cellOf(qu);
    }
    /// Lists, per cell (i, j), the triangles k with member(k, i, j).
    template <class Member>
    void fill(std::size_t n_tri, const Member& member);
  };
  /// Triangles by cell of the unit square whose bounding box touches the cell (look-up inside).
  void buildCellIndex();
  /// Triangles by cell of [-kOuterReach, 1 + kOuterReach]^2 that can be the nearest to a point of
  /// the cell (look-up outside the hull).
  void buildOuterIndex();
  /// (u_min, u_max, v_min, v_max) of triangle k.
  std::array<double, 4> boundingBox(std::size_t k) const;
  /// Index of the first triangle containing (qu, qv) within the barycentric tolerance, -1 if none.
  int containingTriangle(double qu, double qv) const;
  /// Index of the first triangle at the least distance from (qu, qv).
  int nearestTriangle(double qu, double qv) const;
  /// The vertex differences and determinant of every triangle, for bary().
  void buildBaryTerms();
  /// Barycentric coordinates of (pu, pv) in triangle k.
  std::array<double, 3> bary(std::size_t k, double pu, double pv) const;

  std::vector<double> x_, y_, z_, pu_, pv_;
  std::vector<std::array<int, 3>> tri_;
  double x0_ = 0.0, y0_ = 0.0, sx_ = 1.0, sy_ = 1.0;
  CellIndex inner_, outer_;
  // per triangle (a, b, c) in normalised coordinates: a, b - a, c - a and the determinant
  struct BaryTerms { double ax, ay, bx_ax, by_ay, cx_ax, cy_ay, det; };
  std::vector<BaryTerms> bary_;
  // a point counts as inside a triangle when every barycentric coordinate is >= -this [-]
  static constexpr double kBaryTolerance = 1e-12;
  // widening of a triangle's bounding box in the inner index [-] (normalised; >> kBaryTolerance)
  static constexpr double kCellMargin = 1e-9;
  // how far beyond the unit square the outer index reaches [-] (normalised; farther: all triangles)
  static constexpr double kOuterReach = 0.5;
};

}  // namespace hbt::engine_map
