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

namespace hbt::aftertreatment {
namespace {

/// A producer integrating its 10 ms outputs into the totals as engine_model.hpp does.
struct Producer {
  InputTotals tot;
  void run(double mdot_kg_s, double T_K, double yO2, double nox_kg_s, double T_published_K, int steps) {
    for (int i = 0; i < steps; ++i) {
      tot.exhaust_mass_kg += mdot_kg_s * 0.01;
      tot.exhaust_mass_T_kg_K += mdot_kg_s * T_K * 0.01;
      tot.exhaust_T_time_K_s += T_published_K * 0.01;
      tot.o2_kg += mdot_kg_s * yO2 * 0.01;
      tot.co2_kg += mdot_kg_s * 0.06 * 0.01;
      tot.nox_kg += nox_kg_s * 0.01;
    }
  }
};

AtsInputs pointAt(double mdot, double T, double yO2) {
  AtsInputs p;
  p.exhaust_mass_flow_kg_s = mdot;
  p.exhaust_T_K = T;
  p.comp.y_O2 = yO2;
  p.comp.y_CO2 = yO2 > 0.2 ? 0.0 : 0.06;
  p.ambient_T_K = 313.15;
  return p;
}

// A warm engine running (0.08 kg/s at 650 K, 12 % O2), then stopped: no flow, the published
// temperature the map engine's no-flow value (ambient, 313.15 K) and air.
constexpr double kRun = 0.08, kTrun = 650.0, kO2run = 0.12, kNOx = 3e-5, kTamb = 313.15, kO2air = 0.232;

StepInputs primed(Producer& pr) {  // a first step after 10 s of running, so that totals are large
  StepInputs si;
  pr.run(kRun, kTrun, kO2run, kNOx, kTrun, 1000);
  si.next(pr.tot, pointAt(kRun, kTrun, kO2run), 0.1);
  return si;
}

}  // namespace

TEST(StepInputs, AWindowThatStartsAnEngineStopCarriesTheRunningGas) {
  Producer pr;
  StepInputs si = primed(pr);
  pr.run(kRun, kTrun, kO2run, kNOx, kTrun, 4);  // 40 ms running, then fuel cut and stop
  pr.run(0.0, kTamb, kO2air, 0.0, kTamb, 6);
  const AtsInputs in = si.next(pr.tot, pointAt(0.0, kTamb, kO2air), 0.1);
  EXPECT_NEAR(in.exhaust_mass_flow_kg_s, kRun * 0.4, 1e-12);  // mass: 4 of 10 steps
  EXPECT_NEAR(in.exhaust_T_K, kTrun, 1e-6);  // all the mass was the running engine's gas
  EXPECT_NEAR(in.comp.y_O2, kO2run, 1e-9);
  EXPECT_NEAR(in.nox_mass_flow_kg_s, kNOx * 0.4, 1e-15);
}

TEST(StepInputs, AWindowThatEndsAnEngineStopCarriesTheRestartedGas) {
  Producer pr;
  StepInputs si = primed(pr);
  pr.run(0.0, kTamb, kO2air, 0.0, kTamb, 300);  // 3 s stopped
  si.next(pr.tot, pointAt(0.0, kTamb, kO2air), 0.1);
  pr.run(0.0, kTamb, kO2air, 0.0, kTamb, 7);  // restart after 70 ms: idle flow of cool gas
  pr.run(0.03, 420.0, 0.17, 5e-6, 420.0, 3);
  const AtsInputs in = si.next(pr.tot, pointAt(0.03, 420.0, 0.17), 0.1);
  EXPECT_NEAR(in.exhaust_mass_flow_kg_s, 0.03 * 0.3, 1e-12);
  EXPECT_NEAR(in.exhaust_T_K, 420.0, 1e-6);
  EXPECT_NEAR(in.comp.y_O2, 0.17, 1e-9);
  EXPECT_NEAR(in.nox_mass_flow_kg_s, 5e-6 * 0.3, 1e-15);
}

TEST(StepInputs, AWholeWindowWithTheEngineOffIsNoFlowAtTheNoFlowTemperature) {
  Producer pr;
  StepInputs si = primed(pr);
  pr.run(0.0, kTamb, kO2air, 0.0, kTamb, 10);
  si.next(pr.tot, pointAt(0.0, kTamb, kO2air), 0.1);
  pr.run(0.0, kTamb, kO2air, 0.0, kTamb, 10);
  const AtsInputs in = si.next(pr.tot, pointAt(0.0, kTamb, kO2air), 0.1);
  EXPECT_EQ(in.exhaust_mass_flow_kg_s, 0.0);
  EXPECT_EQ(in.nox_mass_flow_kg_s, 0.0);
  EXPECT_NEAR(in.exhaust_T_K, kTamb, 1e-9);  // what the engine publishes for no flow
  EXPECT_EQ(in.comp.y_O2, kO2air);           // the sample's composition: air
  const AtsInputs air = pointAt(0.0, kTamb, kO2air);
  EXPECT_NEAR(in.comp.y_N2, 1.0 - air.comp.y_O2 - air.comp.y_CO2 - air.comp.y_H2O, 1e-15);
}

TEST(StepInputs, ASpinDownFlowTooSmallToWeightIsNoFlowNotZeroKelvin) {
  // the crank coasting down: the pumped flow decays through 1e-11 kg/s, so the mass total still
  // moves by an ulp or two while the mass x temperature total no longer does
  Producer pr;
  StepInputs si = primed(pr);
  for (int k = 0; k < 60; ++k) {  // 6 s of decay, one ATS step every 0.1 s
    for (int i = 0; i < 10; ++i) {
      const double mdot = 1e-4 * std::exp(-0.5 * (10 * k + i));
      pr.run(mdot, kTamb, kO2air, 0.0, kTamb, 1);
    }
    const AtsInputs in = si.next(pr.tot, pointAt(0.0, kTamb, kO2air), 0.1);
    ASSERT_TRUE(std::isfinite(in.exhaust_T_K)) << k;
    EXPECT_GT(in.exhaust_T_K, 300.0) << k;  // the gas temperature, or the no-flow one: both 313 K
    EXPECT_LT(in.exhaust_T_K, 330.0) << k;
    EXPECT_GE(in.exhaust_mass_flow_kg_s, 0.0) << k;
    EXPECT_LE(in.exhaust_mass_flow_kg_s, 1e-4) << k;
    EXPECT_GE(in.comp.y_N2, 0.0) << k;
  }
}

}  // namespace hbt::aftertreatment
