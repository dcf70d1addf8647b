// Strategy interface between a Pipe and its numerical scheme (FsmSolver, TvdSolver).
// One virtual call per pipe per time step; the cell loops inside each solver are plain loops
// over contiguous std::vector<double> (structure of arrays) sized at construction.
#pragma once
#include "gasdyn/gas.hpp"
#include "gasdyn/pipe_config.hpp"
#include "gasdyn/pipe_end.hpp"

namespace hbt::gasdyn {

/// First non-physical value found after a step (cell < 0: none).
struct CellFault {
  int cell = -1;
  const char* quantity = "";
  double value = 0.0;
};

class PipeSolver {
 public:
  virtual ~PipeSolver() = default;
  /// Initial condition of cell i: density [kg/m^3], velocity [m/s], pressure [Pa].
  virtual void setState(int i, double rho, double u, double p) = 0;
  virtual double rho(int i) const = 0;  // [kg/m^3]
  virtual double u(int i) const = 0;    // cell-centre velocity [m/s]
  virtual double p(int i) const = 0;    // [Pa]
  virtual EndState endState(End e) const = 0;
  /// Advances by dt [s] with the end-face fluxes given by the boundaries (into the pipe).
  /// Returns the first non-physical value found (fault.cell < 0 if none).
  virtual CellFault step(double dt, const EndFlux& left, const EndFlux& right) = 0;
  virtual double maxWaveSpeed() const = 0;  // max(|u| + c) over the cells [m/s]
  virtual double mass() const = 0;          // [kg]
  virtual double energy() const = 0;        // total (internal + kinetic) energy [J]
};

}  // namespace hbt::gasdyn
