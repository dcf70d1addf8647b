#include "gasdyn/pipe.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.hpp"
#include "gasdyn/fsm_solver.hpp"
#include "gasdyn/tvd_solver.hpp"

namespace hbt::gasdyn {

Pipe::Pipe(const PerfectGas& gas, PipeConfig cfg)
    : gas_(gas), cfg_(std::move(cfg)), geo_(PipeGeometry::build(cfg_)) {
  if (cfg_.solver == SolverKind::FSM)
    solver_ = std::make_unique<FsmSolver>(gas_, cfg_, geo_);
  else
    solver_ = std::make_unique<TvdSolver>(gas_, cfg_, geo_);
}

void Pipe::setUniform(double p, double T, double u) {
  if (!(p > 0.0)) throw InputError("pipe " + cfg_.name, "p", "initial pressure must be > 0");
  if (!(T > 0.0)) throw InputError("pipe " + cfg_.name, "T", "initial temperature must be > 0");
  for (int i = 0; i < geo_.n; ++i) solver_->setState(i, p / (gas_.R * T), u, p);
}

double Pipe::mach(int i) const {
  return u(i) / std::sqrt(gas_.gamma * p(i) / rho(i));
}

void Pipe::attach(End e, const std::string& boundary) {
  auto& o = owner_[static_cast<int>(e)];
  if (!o.empty())
    throw InputError("pipe " + cfg_.name, e == End::Left ? "left end" : "right end",
                     "already connected to '" + o + "', cannot also connect '" + boundary + "'");
  o = boundary;
}

double Pipe::maxDt() const {
  if (implicit_cell_) {  // transport through the one cell: face and centre velocities
    const double rA = solver_->rho(0) * geo_.A_cell[0];
    const double s = std::max({std::fabs(solver_->u(0)), std::fabs(flux_[0].mdot_in) / rA,
                               std::fabs(flux_[1].mdot_in) / rA});
    return s > 0.0 ? cfg_.cfl * geo_.dx / s : std::numeric_limits<double>::infinity();
  }
  const double s = solver_->maxWaveSpeed();
  const double cfl = subcycle_cfl_ > 0.0 ? subcycle_cfl_ : cfg_.cfl;
  return s > 0.0 ? cfl * geo_.dx / s : std::numeric_limits<double>::infinity();
}

void Pipe::step(double dt) {
  if (!(subcycle_cfl_ > 0.0)) return solverStep(dt);
  // own CFL sub-steps, equal within what remains, the end fluxes held
  double remaining = dt;
  while (remaining > 0.0) {
    const double s = solver_->maxWaveSpeed();
    const double own = s > 0.0 ? cfg_.cfl * geo_.dx / s : remaining;
    const double n = std::max(1.0, std::ceil(remaining / own * (1.0 - 1e-12)));
    const double h = n <= 1.0 ? remaining : remaining / n;
    solverStep(h);
    remaining = n <= 1.0 ? 0.0 : remaining - h;
  }
}

void Pipe::solverStep(double dt) {
  const CellFault f = solver_->step(dt, flux_[0], flux_[1]);
  ++steps_;
  if (f.cell >= 0) {
    throw ModelDivergence("pipe " + cfg_.name + " cell " + std::to_string(f.cell), f.quantity,
                          "non-physical value " + std::to_string(f.value) + " after step " +
                              std::to_string(steps_) + " (dt = " + std::to_string(dt) + " s)");
  }
}

}  // namespace hbt::gasdyn
