#include "engine_map/scattered_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>

#include "common/errors.hpp"

namespace hbt::engine_map {
namespace {

struct P { double u, v; };

double orient(const P& a, const P& b, const P& c) {
  return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
}

// > 0 if d is strictly inside the circumcircle of the counter-clockwise triangle (a, b, c).
double inCircle(const P& a, const P& b, const P& c, const P& d) {
  const double adx = a.u - d.u, ady = a.v - d.v;
  const double bdx = b.u - d.u, bdy = b.v - d.v;
  const double cdx = c.u - d.u, cdy = c.v - d.v;
  const double ad = adx * adx + ady * ady, bd = bdx * bdx + bdy * bdy, cd = cdx * cdx + cdy * cdy;
  return adx * (bdy * cd - bd * cdy) - ady * (bdx * cd - bd * cdx) + ad * (bdx * cdy - bdy * cdx);
}

double distToSegment2(const P& p, const P& a, const P& b) {
  const double du = b.u - a.u, dv = b.v - a.v;
  const double l2 = du * du + dv * dv;
  double t = l2 > 0.0 ? ((p.u - a.u) * du + (p.v - a.v) * dv) / l2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double eu = a.u + t * du - p.u, ev = a.v + t * dv - p.v;
  return eu * eu + ev * ev;
}

using Tri = std::array<int, 3>;

// Orientation tolerance [-] (coordinates scaled to the unit square): a point this close to an
// edge's line counts as on it.
constexpr double kOrientEps = 1e-14;
// Half-width of the super-triangle enclosing the unit square [-] (a wide margin).
constexpr double kSuperTriangleSize = 1.0e3;
// pruneOffender() results besides a triangle index (>= 0, to leave the cavity) and
// -2 - j (neighbour j to join it): the cavity is star-shaped, or it is degenerate (p on the
// hull of the super-triangle).
constexpr int kStarShaped = -1;
constexpr int kDegenerateCavity = -1000000000;

bool sharesEdge(const Tri& a, const Tri& b) {
  int common = 0;
  for (int i : a)
    for (int j : b) common += (i == j);
  return common == 2;
}

// Index of the first triangle containing p (on an edge counts as inside), -1 if none.
int locateTriangle(const std::vector<P>& pts, const std::vector<Tri>& tris, const P& p) {
  int seed = -1;
  for (std::size_t k = 0; k < tris.size() && seed < 0; ++k) {
    const auto& t = tris[k];
    if (orient(pts[t[0]], pts[t[1]], p) >= -kOrientEps &&
        orient(pts[t[1]], pts[t[2]], p) >= -kOrientEps &&
        orient(pts[t[2]], pts[t[0]], p) >= -kOrientEps)
      seed = static_cast<int>(k);
  }
  return seed;
}

// Cavity: triangles connected to the seed (through shared edges) whose circumcircle
// contains p. Candidates first (few), then connectivity among them. 1 marks a cavity triangle.
std::vector<char> cavity(const std::vector<P>& pts, const std::vector<Tri>& tris, const P& p,
                         int seed) {
  std::vector<char> bad(tris.size(), 0);
  std::vector<int> cand;
  for (std::size_t k = 0; k < tris.size(); ++k) {
    const auto& t = tris[k];
    if (static_cast<int>(k) != seed && inCircle(pts[t[0]], pts[t[1]], pts[t[2]], p) > 0.0)
      cand.push_back(static_cast<int>(k));
  }
  bad[seed] = 1;
  std::vector<int> stack{seed};
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    for (int c : cand)
      if (!bad[c] && sharesEdge(tris[c], tris[k])) { bad[c] = 1; stack.push_back(c); }
  }
  return bad;
}

// The cavity's boundary edges (into `boundary`) up to the first one that does not see p strictly
// on its inner side; returns what to change (see kStarShaped) or kStarShaped if none.
int pruneOffender(const std::vector<P>& pts, const std::vector<Tri>& tris, const P& p, int seed,
                  const std::vector<char>& bad, std::vector<std::pair<int, int>>& boundary) {
  std::map<std::pair<int, int>, int> edgeCount;
  for (std::size_t k = 0; k < tris.size(); ++k) {
    if (!bad[k]) continue;
    for (int e = 0; e < 3; ++e) {
      const int a = tris[k][e], b = tris[k][(e + 1) % 3];
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      ++edgeCount[key];
    }
  }
  boundary.clear();
  int offender = kStarShaped;
  for (std::size_t k = 0; k < tris.size() && offender < 0; ++k) {
    if (!bad[k]) continue;
    for (int e = 0; e < 3; ++e) {
      const int a = tris[k][e], b = tris[k][(e + 1) % 3];
      if (edgeCount[{std::min(a, b), std::max(a, b)}] != 1) continue;
      if (orient(pts[a], pts[b], p) <= kOrientEps) {
        if (static_cast<int>(k) != seed) { offender = static_cast<int>(k); break; }
        // p on a boundary edge of its own triangle: the neighbour across that edge must be
        // in the cavity too (p lies strictly inside its circumcircle); add it.
        for (std::size_t j = 0; j < tris.size(); ++j)
          if (!bad[j] && sharesEdge(tris[j], tris[k])) {
            const auto& tj = tris[j];
            bool hasA = false, hasB = false;
            for (int q : tj) { hasA |= q == a; hasB |= q == b; }
            if (hasA && hasB) { offender = -2 - static_cast<int>(j); break; }
          }
        if (offender == kStarShaped) offender = kDegenerateCavity;
        break;
      }
      boundary.push_back({a, b});
    }
  }
  return offender;
}

// Prunes the cavity until every boundary edge sees p strictly on its inner side (star-shaped
// cavity); returns its boundary edges.
std::vector<std::pair<int, int>> starShapedCavity(const std::vector<P>& pts,
                                                  const std::vector<Tri>& tris, const P& p,
                                                  int seed, std::vector<char>& bad,
                                                  const std::string& source) {
  std::vector<std::pair<int, int>> boundary;
  for (int iter = 0;; ++iter) {
    if (iter > 10000) throw InputError(source, "points", "triangulation failed (cavity)");
    const int offender = pruneOffender(pts, tris, p, seed, bad, boundary);
    if (offender == kStarShaped) break;
    if (offender >= 0) bad[offender] = 0;
    else if (offender > kDegenerateCavity) bad[-2 - offender] = 1;
    else throw InputError(source, "points", "triangulation failed (degenerate cavity)");
  }
  return boundary;
}

}  // namespace

ScatteredLinearMap::ScatteredLinearMap(std::vector<double> x, std::vector<double> y,
                                       std::vector<double> z, const std::string& source)
    : x_(std::move(x)), y_(std::move(y)), z_(std::move(z)) {
  const std::size_t n = x_.size();
  if (y_.size() != n || z_.size() != n)
    throw InputError(source, "points", "x, y and z have different lengths");
  if (n < 3) throw InputError(source, "points", "at least 3 points are needed");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x_[i]) || !std::isfinite(y_[i]) || !std::isfinite(z_[i]))
      throw InputError(source, "points", "non-finite value at point " + std::to_string(i + 1));
  const auto [xmin, xmax] = std::minmax_element(x_.begin(), x_.end());
  const auto [ymin, ymax] = std::minmax_element(y_.begin(), y_.end());
  if (!(*xmax > *xmin) || !(*ymax > *ymin))
    throw InputError(source, "points", "points are collinear (no 2-D extent)");
  x0_ = *xmin;
  y0_ = *ymin;
  sx_ = 1.0 / (*xmax - *xmin);
  sy_ = 1.0 / (*ymax - *ymin);
  pu_.resize(n);
  pv_.resize(n);
  std::set<std::pair<double, double>> seen;
  for (std::size_t i = 0; i < n; ++i) {
    pu_[i] = u(x_[i]);
    pv_[i] = v(y_[i]);
    if (!seen.insert({x_[i], y_[i]}).second)
      throw InputError(source, "points", "duplicate point " + std::to_string(i + 1));
  }
  triangulate(source);
  buildBaryTerms();
  buildCellIndex();
  buildOuterIndex();
}

void ScatteredLinearMap::triangulate(const std::string& source) {
  const int n = static_cast<int>(pu_.size());
  std::vector<P> pts(n + 3);
  for (int i = 0; i < n; ++i) pts[i] = {pu_[i], pv_[i]};
  // Super-triangle enclosing [0,1]^2 with a wide margin.
  const double M = kSuperTriangleSize;
  pts[n] = {-M, -M};
  pts[n + 1] = {M, -M};
  pts[n + 2] = {0.5, M};
  std::vector<Tri> tris{{n, n + 1, n + 2}};

  // Bowyer-Watson: each point replaces its cavity by the fan of the cavity's boundary edges.
  for (int ip = 0; ip < n; ++ip) {
    const P& p = pts[ip];
    const int seed = locateTriangle(pts, tris, p);
    if (seed < 0) throw InputError(source, "points", "triangulation failed (point location)");
    std::vector<char> bad = cavity(pts, tris, p, seed);
    const std::vector<std::pair<int, int>> boundary = starShapedCavity(pts, tris, p, seed, bad, source);
    std::vector<Tri> next;
    next.reserve(tris.size() + 2);
    for (std::size_t k = 0; k < tris.size(); ++k)
      if (!bad[k]) next.push_back(tris[k]);
    for (const auto& e : boundary) next.push_back({e.first, e.second, ip});
    tris.swap(next);
  }
  tri_.clear();
  for (const auto& t : tris)
    if (t[0] < n && t[1] < n && t[2] < n) {
      if (orient(pts[t[0]], pts[t[1]], pts[t[2]]) <= 1e-15) continue;  // sliver of collinear pts
      tri_.push_back(t);
    }
  if (tri_.empty()) throw InputError(source, "points", "no triangle (points collinear)");
}

void ScatteredLinearMap::buildBaryTerms() {
  bary_.resize(tri_.size());
  for (std::size_t k = 0; k < tri_.size(); ++k) {
    const auto& t = tri_[k];
    const double ax = pu_[t[0]], ay = pv_[t[0]], bx = pu_[t[1]], by = pv_[t[1]];
    const double cx = pu_[t[2]], cy = pv_[t[2]];
    BaryTerms& b = bary_[k];
    b.ax = ax;
    b.ay = ay;
    b.bx_ax = bx - ax;
    b.by_ay = by - ay;
    b.cx_ax = cx - ax;
    b.cy_ay = cy - ay;
    b.det = b.bx_ax * b.cy_ay - b.by_ay * b.cx_ax;
  }
}

std::array<double, 3> ScatteredLinearMap::bary(std::size_t k, double qu, double qv) const {
  // the same operations in the same order as from the vertices: the terms are exact copies
  const BaryTerms& b = bary_[k];
  const double lb = ((qu - b.ax) * b.cy_ay - (qv - b.ay) * b.cx_ax) / b.det;
  const double lc = (b.bx_ax * (qv - b.ay) - b.by_ay * (qu - b.ax)) / b.det;
  return {1.0 - lb - lc, lb, lc};
}

bool ScatteredLinearMap::inside(double x, double y) const {
  return containingTriangle(u(x), v(y)) >= 0;
}

void ScatteredLinearMap::buildCellIndex() {
  const int g = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(tri_.size())))));
  inner_.lo = 0.0;
  inner_.width = 1.0 / g;
  inner_.cells = g;
  inner_.start.assign(static_cast<std::size_t>(g) * g + 1, 0);
  // each triangle's bounding box, widened by kCellMargin, as a range of cells
  std::vector<std::array<int, 4>> span(tri_.size());
  for (std::size_t k = 0; k < tri_.size(); ++k) {
    const auto b = boundingBox(k);
    span[k] = {inner_.cellOf(b[0] - kCellMargin), inner_.cellOf(b[1] + kCellMargin),
               inner_.cellOf(b[2] - kCellMargin), inner_.cellOf(b[3] + kCellMargin)};
  }
  const auto touches = [&](std::size_t k, int i, int j) {
    return i >= span[k][0] && i <= span[k][1] && j >= span[k][2] && j <= span[k][3];
  };
  inner_.fill(tri_.size(), touches);
}

void ScatteredLinearMap::buildOuterIndex() {
  // For a cell B: every point of B is within D = min over the vertices m of (max over B's corners
  // of |corner - m|) of some triangle (the one holding m), and at least d_k = the distance between
  // B and k's bounding box from triangle k. The nearest triangle of any point in B is therefore
  // among the k with d_k <= D (a small relative margin keeps rounding ties in).
  const int g = 2 * inner_.cells;
  outer_.lo = -kOuterReach;
  outer_.width = (1.0 + 2.0 * kOuterReach) / g;
  outer_.cells = g;
  outer_.start.assign(static_cast<std::size_t>(g) * g + 1, 0);
  std::vector<std::array<double, 4>> box(tri_.size());
  for (std::size_t k = 0; k < tri_.size(); ++k) box[k] = boundingBox(k);
  std::vector<double> bound2(static_cast<std::size_t>(g) * g);
  for (int j = 0; j < g; ++j)
    for (int i = 0; i < g; ++i) {
      const double u0 = outer_.lo + i * outer_.width, u1 = u0 + outer_.width;
      const double v0 = outer_.lo + j * outer_.width, v1 = v0 + outer_.width;
      double best = std::numeric_limits<double>::infinity();
      for (const auto& t : tri_)
        for (int m : t) {
          double far2 = 0.0;  // the farthest point of B from vertex m is a corner (convexity)
          for (const double cu : {u0, u1})
            for (const double cv : {v0, v1})
              far2 = std::max(far2, (pu_[m] - cu) * (pu_[m] - cu) + (pv_[m] - cv) * (pv_[m] - cv));
          best = std::min(best, far2);
        }
      bound2[static_cast<std::size_t>(j) * g + i] = best * (1.0 + 1e-9) + 1e-18;
    }
  const auto candidate = [&](std::size_t k, int i, int j) {
    const double u0 = outer_.lo + i * outer_.width, u1 = u0 + outer_.width;
    const double v0 = outer_.lo + j * outer_.width, v1 = v0 + outer_.width;
    const double du = std::max({0.0, box[k][0] - u1, u0 - box[k][1]});
    const double dv = std::max({0.0, box[k][2] - v1, v0 - box[k][3]});
    return du * du + dv * dv <= bound2[static_cast<std::size_t>(j) * g + i];
  };
  outer_.fill(tri_.size(), candidate);
}

std::array<double, 4> ScatteredLinearMap::boundingBox(std::size_t k) const {
  double umin = pu_[tri_[k][0]], umax = umin, vmin = pv_[tri_[k][0]], vmax = vmin;
  for (int i : tri_[k]) {
    umin = std::min(umin, pu_[i]); umax = std::max(umax, pu_[i]);
    vmin = std::min(vmin, pv_[i]); vmax = std::max(vmax, pv_[i]);
  }
  return {umin, umax, vmin, vmax};
}

template <class Member>
void ScatteredLinearMap::CellIndex::fill(std::size_t n_tri, const Member& member) {
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const std::size_t c = static_cast<std::size_t>(j) * cells + i;
      for (std::size_t k = 0; k < n_tri; ++k)
        if (member(k, i, j)) tris.push_back(static_cast<int>(k));
      start[c + 1] = static_cast<int>(tris.size());
    }
}

int ScatteredLinearMap::containingTriangle(double qu, double qv) const {
  const int c = inner_.cellIndex(qu, qv, kCellMargin);
  if (c < 0) return -1;  // outside the unit square: outside every triangle
  for (int m = inner_.start[c]; m < inner_.start[c + 1]; ++m) {
    const auto l = bary(inner_.tris[m], qu, qv);
    if (l[0] >= -kBaryTolerance && l[1] >= -kBaryTolerance && l[2] >= -kBaryTolerance) return inner_.tris[m];
  }
  return -1;
}

int ScatteredLinearMap::nearestTriangle(double qu, double qv) const {
  const P q{qu, qv};
  const int c = outer_.cellIndex(qu, qv, 0.0);
  const int m0 = c < 0 ? 0 : outer_.start[c], m1 = c < 0 ? static_cast<int>(tri_.size()) : outer_.start[c + 1];
  int best = -1;
  double bestDist = std::numeric_limits<double>::infinity();
  for (int m = m0; m < m1; ++m) {
    const int k = c < 0 ? m : outer_.tris[m];  // beyond the outer grid: every triangle
    const auto& t = tri_[k];
    double d = std::numeric_limits<double>::infinity();
    for (int e = 0; e < 3; ++e)
      d = std::min(d, distToSegment2(q, {pu_[t[e]], pv_[t[e]]},
                                     {pu_[t[(e + 1) % 3]], pv_[t[(e + 1) % 3]]}));
    if (d < bestDist) { bestDist = d; best = k; }
  }
  return best;
}

double ScatteredLinearMap::operator()(double x, double y) const {
  const double qu = u(x), qv = v(y);
  int k = containingTriangle(qu, qv);
  if (k < 0) k = nearestTriangle(qu, qv);  // outside the hull: the plane of the nearest triangle
  const auto l = bary(k, qu, qv);
  return l[0] * z_[tri_[k][0]] + l[1] * z_[tri_[k][1]] + l[2] * z_[tri_[k][2]];
}

double ScatteredLinearMap::totalAreaNormalised() const {
  double a = 0.0;
  for (const auto& t : tri_)
    a += 0.5 * orient({pu_[t[0]], pv_[t[0]]}, {pu_[t[1]], pv_[t[1]]}, {pu_[t[2]], pv_[t[2]]});
  return a;
}

double ScatteredLinearMap::hullAreaNormalised() const {
  // Andrew's monotone chain.
  std::vector<P> p(pu_.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = {pu_[i], pv_[i]};
  std::sort(p.begin(), p.end(), [](const P& a, const P& b) {
    return a.u < b.u || (a.u == b.u && a.v < b.v);
  });
  std::vector<P> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && orient(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && orient(h[k - 2], h[k - 1], p[i - 1]) <= 0.0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  double a = 0.0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const P& q = h[i];
    const P& r = h[(i + 1) % h.size()];
    a += q.u * r.v - r.u * q.v;
  }
  return 0.5 * a;
}

}  // namespace hbt::engine_map
