// What a pipe end exchanges with the boundary object attached to it.
//
// The pipe end exposes its end-cell state (EndState) and accepts the flux through its end face
// (EndFlux). Directions are counted INTO the pipe, whichever end it is:
//   u_in > 0         gas moving from the boundary into the pipe [m/s]
//   mdot_in          mass flow into the pipe [kg/s]
//   energy_in        total-enthalpy flow into the pipe, mdot_in (cp T + u^2/2) [W]
//   momentum         momentum flux through the face (p + rho u^2) A [N] (direction-independent)
#pragma once
#include "gasdyn/gas.hpp"

namespace hbt::gasdyn {

enum class End { Left = 0, Right = 1 };

struct EndState {
  double rho;   // end-cell density [kg/m^3]
  double u_in;  // end-cell velocity, positive into the pipe [m/s]
  double p;     // end-cell static pressure [Pa]
  double A;     // end-face area [m^2]
};

struct EndFlux {
  double mdot_in = 0.0;    // [kg/s]
  double momentum = 0.0;   // [N]
  double energy_in = 0.0;  // [W]
};

/// Flux through a face carrying the state (rho [kg/m^3], u_in [m/s], p [Pa]) over area A [m^2].
inline EndFlux faceFlux(const PerfectGas& g, double rho, double u_in, double p, double A) {
  const double mdot = rho * u_in * A;
  return {mdot, (p + rho * u_in * u_in) * A,
          mdot * (g.gamma / (g.gamma - 1.0) * p / rho + 0.5 * u_in * u_in)};
}

}  // namespace hbt::gasdyn
