// StepInputs: the aftertreatment's step means from its producers' cumulative totals equal the
// means of the 10 ms values they integrate (exact up to rounding), the mass-weighted temperature
// and composition included; the no-flow and first-step cases take what step_inputs.hpp says.
#include <gtest/gtest.h>

#include <cmath>

#include "aftertreatment/step_inputs.hpp"

namespace hbt::aftertreatment {
namespace {

struct Sample {
  double m, T, yO2, yCO2, yH2O, nox, v;
};
Sample sampleAt(int i) {  // a 10 ms engine/vehicle trace with a tip-in and a fuel cut
  const double load = i < 30 ? 0.2 : (i < 60 ? 0.9 : 0.0);
  return {0.05 + 0.2 * load + 0.01 * std::sin(0.7 * i), 450.0 + 300.0 * load + 5.0 * std::cos(i),
          0.20 - 0.12 * load, 0.01 + 0.08 * load, 0.01 + 0.05 * load, 2e-5 * load, 8.0 + 0.1 * i};
}

}  // namespace

TEST(StepInputs, MeansOfTheTotalsAreTheMeansOfTheSamples) {
  constexpr double dt = 0.01, P = 0.1;
  InputTotals tot;
  StepInputs si;
  AtsInputs point;
  point.ambient_T_K = 280.0;
  int checked = 0;
  for (int i = 0; i <= 90; ++i) {
    if (i > 0) {  // the producer integrates its step outputs (engine_model.hpp, vehicle distance)
      const Sample s = sampleAt(i);
      tot.exhaust_mass_kg += s.m * dt;
      tot.exhaust_mass_T_kg_K += s.m * s.T * dt;
      tot.exhaust_T_time_K_s += s.T * dt;
      tot.o2_kg += s.m * s.yO2 * dt;
      tot.co2_kg += s.m * s.yCO2 * dt;
      tot.h2o_kg += s.m * s.yH2O * dt;
      tot.nox_kg += s.nox * dt;
      tot.distance_m += s.v * dt;
    }
    if (i % 10 != 0) continue;
    const Sample now = sampleAt(i);
    point.exhaust_mass_flow_kg_s = now.m;
    point.exhaust_T_K = now.T;
    point.vehicle_speed_m_s = now.v;
    const AtsInputs in = si.next(tot, point, P);
    if (i == 0) {  // first step: the point values
      EXPECT_EQ(in.exhaust_mass_flow_kg_s, now.m);
      EXPECT_EQ(in.exhaust_T_K, now.T);
      continue;
    }
    double m = 0, mT = 0, mO2 = 0, mCO2 = 0, mH2O = 0, nox = 0, v = 0;
    for (int j = i - 9; j <= i; ++j) {  // the ten 10 ms values of the last step
      const Sample s = sampleAt(j);
      m += s.m;
      mT += s.m * s.T;
      mO2 += s.m * s.yO2;
      mCO2 += s.m * s.yCO2;
      mH2O += s.m * s.yH2O;
      nox += s.nox;
      v += s.v;
    }
    EXPECT_NEAR(in.exhaust_mass_flow_kg_s, m / 10.0, 1e-14);
    EXPECT_NEAR(in.exhaust_T_K, mT / m, 1e-9);
    EXPECT_NEAR(in.comp.y_O2, mO2 / m, 1e-12);
    EXPECT_NEAR(in.comp.y_CO2, mCO2 / m, 1e-12);
    EXPECT_NEAR(in.comp.y_H2O, mH2O / m, 1e-12);
    EXPECT_NEAR(in.comp.y_N2, 1.0 - (mO2 + mCO2 + mH2O) / m, 1e-12);
    EXPECT_NEAR(in.nox_mass_flow_kg_s, nox / 10.0, 1e-18);
    EXPECT_NEAR(in.vehicle_speed_m_s, v / 10.0, 1e-11);
    EXPECT_EQ(in.ambient_T_K, 280.0);
    ++checked;
  }
  EXPECT_EQ(checked, 9);
}

TEST(StepInputs, NoFlowTakesTheTimeMeanTemperatureAndThePointComposition) {
  StepInputs si;
  InputTotals a, b;
  AtsInputs point;
  point.comp.y_O2 = 0.23;
  si.next(a, point, 0.1);
  b.exhaust_T_time_K_s = 0.1 * 400.0;  // 400 K held, no flow (engine off)
  const AtsInputs in = si.next(b, point, 0.1);
  EXPECT_EQ(in.exhaust_mass_flow_kg_s, 0.0);
  EXPECT_NEAR(in.exhaust_T_K, 400.0, 1e-12);
  EXPECT_EQ(in.comp.y_O2, 0.23);
}

}  // namespace hbt::aftertreatment
