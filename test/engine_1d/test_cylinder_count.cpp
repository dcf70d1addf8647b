// The cylinder count comes from the configuration (engine_1d/cylinders, firing_order,
// exhaust_bank): a 4-cylinder variant of the engine (firing order 1-3-4-2, cylinders 1-2 on
// turbine entry 1, 3-4 on entry 2, the same cylinder, valves and pipes) fires 720/4 = 180 deg
// apart and, at the same speed and fuel per cylinder-cycle, delivers about 4/6 of the six's
// indicated work per cycle.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "common/units.hpp"
#include "cylinder/kinematics.hpp"
#include "support.hpp"

using namespace hbt::engine_1d;
using namespace hbt::engine_1d::test;

namespace {

Engine1DParams fourCylinders() {
  Engine1DParams p = defaultParams();
  p.engine.cylinders = 4;
  p.engine.firing_order = {1, 3, 4, 2};
  p.engine.exhaust_bank = {1, 1, 2, 2};
  return p;
}

struct CycleMeasure {
  double work_J = 0;       // net indicated work per engine cycle (all cylinders) [J]
  double fuel_kg = 0;      // fuel injected per cylinder-cycle [kg]
  double air_kg = 0;       // compressor air per engine cycle [kg]
  double boost_Pa = 0;     // cycle-mean intake manifold pressure [Pa]
  int runners = 0;         // intake runners built (pipes of the intake network less 2)
};

/// The assembly alone at constant speed [rpm], fuel per cylinder-cycle [kg] and wastegate
/// opening (no controllers): `settle` cycles, then the totals over `cycles` whole cycles.
CycleMeasure runFixedFuel(Engine1D& e, double rpm, double fuel_kg, double wastegate, int settle,
                          int cycles) {
  const double w = rpm * kRpm, cycle_s = 4.0 * M_PI / w, T_amb = 298.15;
  e.reset(w, 500.0, T_amb);
  EngineAssembly& A = e.assembly();
  A.setFuelPerCycle(fuel_kg);
  A.setWastegateOpening(wastegate);
  const int steps_per_cycle = 12;  // macro steps of 60 deg, the twin's 10 ms at 1000 rpm
  auto advance = [&](int n) {
    for (int i = 0; i < n * steps_per_cycle; ++i) {
      A.setAmbient(hbt::units::kStandardAtmosphere_Pa, T_amb);  // filter loss at the cycle-mean flow
      A.advance(cycle_s / steps_per_cycle, w);
    }
  };
  advance(settle);
  const EnergyTotals t0 = A.totals();
  CycleMeans m;
  double air_kg = 0.0;
  for (int c = 0; c < cycles; ++c) {
    advance(1);
    A.cycleMeans(m);
    air_kg += m[kAir] * cycle_s;
  }
  const EnergyTotals& t1 = A.totals();
  CycleMeasure r;
  r.work_J = (t1.indicated_work_J - t0.indicated_work_J) / cycles;
  r.fuel_kg = (t1.fuel_kg - t0.fuel_kg) / (cycles * A.cylinders());
  r.air_kg = air_kg / cycles;
  r.boost_Pa = m[kBoost];
  r.runners = static_cast<int>(A.intakeNetwork().pipes().size()) - 2;
  return r;
}

}  // namespace

TEST(Engine1DCylinderCount, FourCylindersFire180DegApart) {
  Engine1D e4(fourCylinders(), repoRoot());
  Engine1D e6(defaultParams(), repoRoot());
  run(e4, 1400.0, 400.0, 0.3);
  run(e6, 1400.0, 600.0, 0.3);
  for (Engine1D* e : {&e4, &e6}) {
    const EngineAssembly& A = e->assembly();
    const std::vector<double>& order = e->params().engine.firing_order;
    const int n = A.cylinders();
    ASSERT_EQ(static_cast<int>(order.size()), n);
    for (int j = 0; j < n; ++j) {
      // the j-th cylinder of the firing order reaches its firing TDC 720/n deg after the one before
      const int a = static_cast<int>(order[j]) - 1, b = static_cast<int>(order[(j + 1) % n]) - 1;
      EXPECT_EQ(A.firingPhase_deg(a), j * 720.0 / n);
      const double lag = hbt::cylinder::wrapCycleDeg(A.cylinder(a).crankAngle_deg() - A.cylinder(b).crankAngle_deg());
      EXPECT_NEAR(lag, 720.0 / n, 1e-6) << "cylinders " << a + 1 << " -> " << b + 1 << " of " << n;
    }
  }
  EXPECT_EQ(e4.assembly().cylinders(), 4);
  EXPECT_NEAR(e4.assembly().displacement_m3() / e6.assembly().displacement_m3(), 4.0 / 6.0, 1e-15);
}

TEST(Engine1DCylinderCount, FourCylindersDeliverFourSixthsOfTheWork) {
  // 1400 rpm, 70 mg per cylinder-cycle (~55 % of full-load fuel), wastegate 30 % open in both
  const double rpm = 1400.0, fuel = 70e-6, wastegate = 0.3;
  Engine1D e4(fourCylinders(), repoRoot());
  Engine1D e6(defaultParams(), repoRoot());
  const CycleMeasure m4 = runFixedFuel(e4, rpm, fuel, wastegate, 40, 10);
  const CycleMeasure m6 = runFixedFuel(e6, rpm, fuel, wastegate, 40, 10);
  const double ratio = m4.work_J / m6.work_J;
  std::printf("%.0f rpm, %.0f mg/cyl-cycle: W_ind 4 cyl %.1f J, 6 cyl %.1f J per cycle, ratio %.4f "
              "(4/6 = %.4f); fuel/cyl-cycle %.2f / %.2f mg; air per cycle %.3f / %.3f g "
              "(ratio %.3f); boost %.0f / %.0f Pa\n",
              rpm, fuel * 1e6, m4.work_J, m6.work_J, ratio, 4.0 / 6.0, m4.fuel_kg * 1e6, m6.fuel_kg * 1e6,
              m4.air_kg * 1e3, m6.air_kg * 1e3, m4.air_kg / m6.air_kg, m4.boost_Pa, m6.boost_Pa);
  EXPECT_EQ(m4.runners, 4);
  EXPECT_EQ(m6.runners, 6);
  // the same fuel per cylinder-cycle reached every cylinder of both engines
  EXPECT_NEAR(m4.fuel_kg / fuel, 1.0, 1e-3);
  EXPECT_NEAR(m6.fuel_kg / fuel, 1.0, 1e-3);
  // Tolerance +-3 % of 4/6: each cylinder burns the same fuel, but its gas exchange is not the
  // same: the turbocharger, matched to the six, sees 2/3 of the exhaust flow and two pulses per
  // entry and cycle instead of three, so boost, trapped air (lambda) and the pumping loop differ
  // (here boost +7 %, air per cylinder-cycle +7 %); pumping is a few % of the net indicated work.
  // Measured 0.6674 (0.663-0.669 over 1000-1800 rpm, 50-110 mg, wastegate 0-0.6).
  EXPECT_NEAR(ratio, 4.0 / 6.0, 0.03 * 4.0 / 6.0);
}
