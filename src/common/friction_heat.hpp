// Where an engine's heat enters the cooling model (src/cooling: the engine metal and the engine
// oil are nodes of their own), the same rule for the map and the 1D engine:
//
//   Q̇_oil   = f_o P_f                       [W]
//   Q̇_metal = Q̇_wall + (1 − f_o) P_f        [W]
//
// P_f = mechanical friction work rate of the engine [W] (crankshaft bearings and seals, piston
// rings and skirts, valve train; pumping work is gas work, not in it), Q̇_wall = combustion heat
// through the cylinder walls [W], f_o = share of the friction dissipated in the oil films of the
// bearings and the valve train, carried off by the oil; the rest, the piston rings' and skirts'
// friction on the liners, heats the liners (metal -> water jacket). Every watt of friction ends
// in the oil or the metal: Q̇_oil + Q̇_metal = Q̇_wall + P_f. Mechanical friction breakdown of
// engines: the power cylinder (rings + skirt) about equals bearings + valve train (Wong & Tung,
// "Overview of automotive engine friction and reduction trends", Friction 4(1) (2016) 1–28,
// Fig. 2), hence f_o = 0.5 in config/engine_map.yaml and config/engine_1d.yaml.
#pragma once

namespace hbt {

struct EngineHeatSplit {
  double metal_W = 0.0;  // into the engine metal (on to the coolant through the water jacket) [W]
  double oil_W = 0.0;    // into the engine oil [W]
};

/// The split above; wall_W and friction_W in W, oil_fraction f_o in [0, 1].
inline EngineHeatSplit splitEngineHeat(double wall_W, double friction_W, double oil_fraction) {
  EngineHeatSplit s;
  s.oil_W = oil_fraction * friction_W;
  s.metal_W = wall_W + (friction_W - s.oil_W);
  return s;
}

}  // namespace hbt
