#include "gasdyn/pipe_config.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::gasdyn {

PipeGeometry PipeGeometry::build(const PipeConfig& c) {
  const std::string src = "pipe " + c.name;
  if (!(c.length > 0.0) || !std::isfinite(c.length))
    throw InputError(src, "length", "must be > 0 m");
  // FSM: one cell is a valid staggered element (both ports are boundary faces: the pipe is then
  // a small volume whose ends see it through the characteristics); TVD needs a cell stencil.
  if (c.cells < (c.solver == SolverKind::FSM ? 1 : 2))
    throw InputError(src, "cells", c.solver == SolverKind::FSM ? "need at least 1 cell (FSM)"
                                                               : "need at least 2 cells (TVD)");
  if (!(c.friction_darcy >= 0.0)) throw InputError(src, "friction_darcy", "must be >= 0");
  if (!(c.cfl > 0.0 && c.cfl <= 1.0)) throw InputError(src, "cfl", "must be in (0, 1]");
  if (c.heat == WallHeat::GivenCoefficient && !(c.h_wall >= 0.0))
    throw InputError(src, "h_wall", "must be >= 0");
  if (c.heat != WallHeat::None && !(c.T_wall > 0.0))
    throw InputError(src, "T_wall", "must be > 0 K");
  PipeGeometry g;
  g.n = c.cells;
  g.dx = c.length / c.cells;
  g.D_face.resize(g.n + 1);
  if (!c.face_diameters.empty()) {
    if (static_cast<int>(c.face_diameters.size()) != g.n + 1)
      throw InputError(src, "face_diameters", "need cells+1 values");
    g.D_face = c.face_diameters;
  } else {
    for (int j = 0; j <= g.n; ++j) {
      const double s = static_cast<double>(j) / g.n;
      g.D_face[j] = c.diameter_left + s * (c.diameter_right - c.diameter_left);
    }
  }
  g.A_face.resize(g.n + 1);
  for (int j = 0; j <= g.n; ++j) {
    if (!(g.D_face[j] > 0.0)) throw InputError(src, "diameter", "must be > 0 m");
    g.A_face[j] = 0.25 * units::kPi * g.D_face[j] * g.D_face[j];
  }
  g.A_cell.resize(g.n);
  g.D_cell.resize(g.n);
  g.V_cell.resize(g.n);
  for (int i = 0; i < g.n; ++i) {
    g.A_cell[i] = 0.5 * (g.A_face[i] + g.A_face[i + 1]);
    g.D_cell[i] = std::sqrt(4.0 * g.A_cell[i] / units::kPi);
    g.V_cell[i] = g.A_cell[i] * g.dx;
  }
  return g;
}

}  // namespace hbt::gasdyn
