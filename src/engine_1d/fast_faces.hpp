// Warm-started pipe-end face solvers for boundaries evaluated every time step.
//
// The solvers now live in gasdyn (characteristics.hpp: warmDemandOutflowFace /
// warmDemandInflowFace, also used by gasdyn's TurbineEntry and CompressorOutlet); these names are
// kept for the engine assembly's boundaries (valves, charge-air cooler link).
#pragma once
#include "gasdyn/characteristics.hpp"

namespace hbt::engine_1d {

/// Outflow face with demand(p0_face, T0_face) [kg/s]; ws = the last call's root and slope.
template <class Demand>
gasdyn::FaceState warmOutflowFace(const PerfectGas& gas, const gasdyn::EndState& s,
                                  Demand demand, gasdyn::WarmStart& ws) {
  return gasdyn::warmDemandOutflowFace(gas, s, demand, ws);
}

/// Inflow face with demand(p_b) -> Supply{mdot, T0}; ws = the last call's root and slope.
template <class Demand>
gasdyn::FaceState warmInflowFace(const PerfectGas& gas, const gasdyn::EndState& s,
                                 Demand demand, gasdyn::WarmStart& ws) {
  return gasdyn::warmDemandInflowFace(gas, s, demand, ws);
}

}  // namespace hbt::engine_1d
