// Engine-out NOx of the calibrated 1D engine and of the map engine's NOx map derived from it
// (config/data/engine/nox_map_1d.csv, src/engine_1d/tools/make_nox_map.py): at steady points the
// map engine (EI(ω, load) x its own fuel) reproduces the 1D engine within 5 % on the map's grid
// (steady-state history and the 1D-vs-map fuel difference) and within 15 % between grid points
// (bilinear interpolation of a convex NOx surface).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "engine_1d/steady_point.hpp"
#include "support.hpp"

using namespace hbt::engine_1d;
using namespace hbt::engine_1d::test;

TEST(Engine1DNox, MapEngineNoxMapReproducesThe1DEngineAtSteadyPoints) {
  Engine1DParams p = defaultParams();
  p.turbo.shaft.inertia_kg_m2 *= 0.25;  // as the steady tool
  const hbt::engine_map::MapEngine map(p.reference, repoRoot());  // loads nox_map_file
  const struct { double rpm, load, tol; } pts[] = {
      {1550.0, 0.55, 0.05}, {2000.0, 0.82, 0.05}, {1325.0, 0.28, 0.05},  // grid points
      {1400.0, 0.60, 0.15}, {1900.0, 0.40, 0.15}};                        // between grid points
  for (const auto& q : pts) {
    Engine1D e(p, repoRoot());
    const double w = q.rpm * kRpm, treq = q.load * e.fullLoadTorque(w);
    e.reset(w, treq);
    const SteadyPointResult r = runSteadyPoint(e, q.rpm, treq);
    ASSERT_TRUE(r.converged) << q.rpm << " rpm " << q.load;
    const double Tb = r.mean.brake_torque_Nm;
    const double nox_map = map.noxEmissionIndex(w, Tb) * map.steadyFuel(w, Tb);
    const double nox_1d = r.mean.nox_mass_flow_kg_s;
    std::printf("%6.0f rpm load %.2f: NOx 1D %.3f g/s (%.2f g/kWh), map engine %.3f g/s (%+.1f %%)\n",
                q.rpm, q.load, 1e3 * nox_1d, r.nox_g_kWh, 1e3 * nox_map, 100.0 * (nox_map / nox_1d - 1.0));
    EXPECT_NEAR(nox_map / nox_1d, 1.0, q.tol) << q.rpm << " rpm load " << q.load;
  }
}
