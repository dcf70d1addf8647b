// End-face states of a pipe end from the method of characteristics (quasi-steady boundaries).
//
// Along the characteristic leaving the pipe through the end (speed c - u_in outwards), the
// Riemann variable of the end cell is carried to the face:
//   2 c_b/(gamma-1) - u_b = 2 c/(gamma-1) - u_in               (u positive into the pipe)
// and the face gas that came from the pipe keeps the end-cell entropy (p/rho^gamma). So a face
// reached by a simple wave from the end cell has, for face velocity u_b [m/s],
//   p_b = p (1 + (gamma-1)/2 (u_b - u_in)/c)^(2 gamma/(gamma-1))   [Pa].
// Inflow faces (u_b > 0) carry gas from the boundary side, whose stagnation temperature T0 is
// given: T_b = T0 - u_b^2/(2 cp). Faces never exceed sonic speed (choking); mass flows asked
// beyond the sonic limit are capped there, so callers must use the returned state's flow.
#pragma once
#include "gasdyn/gas.hpp"
#include "gasdyn/pipe_end.hpp"

namespace hbt::gasdyn {

struct FaceState {
  double rho;   // [kg/m^3]
  double u_in;  // [m/s], positive into the pipe
  double p;     // [Pa]
  double mdot_in(double A) const { return rho * u_in * A; }
};

/// Pressure of the face brought to rest (u_b = 0): the reflected wall pressure [Pa].
double closedFacePressure(const PerfectGas& g, const EndState& s);
/// Closed end (u_b = 0).
FaceState closedFace(const PerfectGas& g, const EndState& s);
/// Open end to gas at rest (p0 [Pa], T0 [K]): isentropic inflow from the total state, outflow at
/// static p0; both directions may choke.
FaceState reservoirFace(const PerfectGas& g, const EndState& s, double p0, double T0);
/// Face carrying mdot_in [kg/s] (>0 into the pipe, supply stagnation temperature T0_in [K];
/// <0 out of the pipe), capped at the sonic face.
FaceState massFlowFace(const PerfectGas& g, const EndState& s, double mdot_in, double T0_in);
/// Orifice of effective area A_in (flow into the pipe) / A_out (out of the pipe) [m^2] between gas
/// at rest (pv [Pa], Tv [K]) and the pipe end; the isentropic nozzle equation (choked or not)
/// and the pipe characteristic are solved together for the face state.
FaceState orificeFace(const PerfectGas& g, const EndState& s, double A_in, double A_out,
                      double pv, double Tv);
/// Stagnation pressure [Pa] and temperature [K] of a face state.
void stagnation(const PerfectGas& g, const FaceState& f, double& p0, double& T0);

}  // namespace hbt::gasdyn
