// Pipe: one 1D duct (geometry + state) advanced by the solver chosen in its config (strategy at
// pipe level: FsmSolver or TvdSolver; one virtual call per pipe per step, none per cell).
//
// Governing equations (quasi-1D, perfect gas; per unit length, SI units):
//   d(rho A)/dt   + d(rho u A)/dx           = 0                                  [kg/(m s)]
//   d(rho u A)/dt + d((rho u^2 + p) A)/dx   = p dA/dx - f_D/(2D) rho u|u| A      [N/m]
//   d(rho E A)/dt + d(rho u H A)/dx         = h pi D (T_wall - T)                 [W/m]
// E = cv T + u^2/2, H = cp T + u^2/2. Each end is driven by exactly one Boundary object, which
// reads endState() and gives the end-face flux with setEndFlux() before every step.
// step() checks the new state (density > 0, pressure > 0, finite) and throws
// hbt::ModelDivergence("pipe <name> cell <i>", quantity, ...) otherwise.
#pragma once
#include <memory>
#include <string>

#include "gasdyn/pipe_config.hpp"
#include "gasdyn/pipe_solver.hpp"

namespace hbt::gasdyn {

class Pipe {
 public:
  Pipe(const PerfectGas& gas, PipeConfig cfg);
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;

  const std::string& name() const { return cfg_.name; }
  const PipeConfig& config() const { return cfg_; }
  const PipeGeometry& geometry() const { return geo_; }
  const PerfectGas& gas() const { return gas_; }
  int cells() const { return geo_.n; }
  double dx() const { return geo_.dx; }
  double xCentre(int i) const { return (i + 0.5) * geo_.dx; }  // [m]

  // --- state (cell centres) ---
  void setState(int i, double rho, double u, double p) { solver_->setState(i, rho, u, p); }
  /// Uniform initial state from pressure [Pa], temperature [K], velocity [m/s].
  void setUniform(double p, double T, double u = 0.0);
  double rho(int i) const { return solver_->rho(i); }
  double u(int i) const { return solver_->u(i); }
  double p(int i) const { return solver_->p(i); }
  double T(int i) const { return solver_->p(i) / (solver_->rho(i) * gas_.R); }
  double mach(int i) const;
  /// Mass flow rho u A at cell i [kg/s] (positive along +x).
  double massFlow(int i) const { return rho(i) * u(i) * geo_.A_cell[i]; }
  double mass() const { return solver_->mass(); }      // [kg]
  double energy() const { return solver_->energy(); }  // [J]

  // --- boundary exchange ---
  EndState endState(End e) const { return solver_->endState(e); }
  void setEndFlux(End e, const EndFlux& f) { flux_[static_cast<int>(e)] = f; }
  const EndFlux& endFlux(End e) const { return flux_[static_cast<int>(e)]; }
  /// Registers the boundary driving end e; throws InputError if the end is already taken.
  void attach(End e, const std::string& boundary);
  bool attached(End e) const { return !owner_[static_cast<int>(e)].empty(); }

  // --- time stepping ---
  /// CFL dx / max(|u| + c) [s]; a pipe with an implicit cell (setImplicitCell): CFL dx / |u|max
  /// over its cell and end faces (donor-cell transport; its acoustics are implicit, volume.hpp).
  double maxDt() const;
  /// One-cell FSM pipe whose pressure is solved implicitly with the volume at one of its ends
  /// (Network::setImplicitOneCellPipes, volume.hpp "Implicit one-cell pipes").
  void setImplicitCell(bool on) { implicit_cell_ = on; }
  bool implicitCell() const { return implicit_cell_; }
  /// Sub-cycled pipe (coupling_cfl > 0; Network::setSubcycledPipes): step(dt) takes its own CFL
  /// sub-steps with the end fluxes of the network step held, and maxDt() is the end cells'
  /// explicit coupling limit coupling_cfl dx/max(|u| + c) instead of its CFL step. 0: off.
  void setSubcycled(double coupling_cfl) { subcycle_cfl_ = coupling_cfl; }
  double subcycleCfl() const { return subcycle_cfl_; }
  void step(double dt);
  long steps() const { return steps_; }  // solver steps (sub-steps of a sub-cycled pipe)

 private:
  void solverStep(double dt);
  PerfectGas gas_;
  PipeConfig cfg_;
  PipeGeometry geo_;
  std::unique_ptr<PipeSolver> solver_;
  EndFlux flux_[2];
  std::string owner_[2];
  long steps_ = 0;
  bool implicit_cell_ = false;
  double subcycle_cfl_ = 0.0;
};

}  // namespace hbt::gasdyn
