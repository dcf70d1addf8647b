// Magnet temperature in the loss model: the NdFeB remanence law β(T_m) = 1 + α_Br (T_m − T_ref)
// applied to the torque constant, the field-weakening current scale and the peak flux density,
// checked against the formulas written out here (hand calculation with the YAML values) and its
// limits: β = 1 at the reference, copper loss ∝ 1/β² at the same torque below the voltage limit,
// and the flux in field weakening set by the voltage alone (independent of the magnets).
#include "support.hpp"

using namespace hbt;
using namespace hbt::emachine;
using namespace hbt::emachine::test;

TEST(EMachineMagnets, FluxFactorFollowsTheRemanenceLawByHand) {
  const EMachineParams p = yamlParams();
  const LossModel lm(p.electrical, p.iron, p.mechanical, p.inverter);
  const double a = p.electrical.magnet_remanence_tempco_per_K;
  EXPECT_EQ(lm.magnetFluxFactor(kMagnetRef_K), 1.0);
  for (double Tc : {-20.0, 0.0, 60.0, 100.0, 150.0}) {
    const double T = celsiusToK(Tc);
    EXPECT_NEAR(lm.magnetFluxFactor(T), 1.0 + a * (T - 293.15), 1e-15) << Tc;
    EXPECT_NEAR(lm.torqueConstant(T), 0.73 * (1.0 + a * (T - 293.15)), 1e-15) << Tc;
  }
  // Sintered NdFeB loses 8-10 % of its remanence between 20 and 100 degC (alpha -0.09..-0.12 %/K).
  const double drop = 1.0 - lm.magnetFluxFactor(celsiusToK(100.0));
  EXPECT_GT(drop, 0.072);
  EXPECT_LT(drop, 0.096);
}

TEST(EMachineMagnets, HotMagnetsNeedMoreCurrentForTheSameTorque) {
  const EMachineParams p = yamlParams();
  const LossModel lm(p.electrical, p.iron, p.mechanical, p.inverter);
  const double Tw = celsiusToK(80.0), hot = celsiusToK(120.0);
  const double beta = lm.magnetFluxFactor(hot);
  // Standstill (cranking torque): I = T/(β k_t) exactly, copper ∝ I².
  const LossBreakdown c = lm.evaluate(150.0, 0.0, 48.0, Tw, kMagnetRef_K);
  const LossBreakdown h = lm.evaluate(150.0, 0.0, 48.0, Tw, hot);
  EXPECT_NEAR(h.i_A, 150.0 / (0.73 * beta), 1e-12);
  EXPECT_NEAR(h.copper_W / c.copper_W, 1.0 / (beta * beta), 1e-12);
  EXPECT_EQ(h.magnet_flux_factor, beta);
  // Below the voltage limit at speed (full flux): iron loss ∝ B² = β².
  const double w = 0.5 * lm.voltageLimitSpeed(48.0, kMagnetRef_K);
  const LossBreakdown cw = lm.evaluate(50.0, w, 48.0, Tw, kMagnetRef_K);
  const LossBreakdown hw = lm.evaluate(50.0, w, 48.0, Tw, hot);
  EXPECT_EQ(hw.flux_ratio, 1.0);
  EXPECT_NEAR(hw.iron_W / cw.iron_W, beta * beta, 1e-12);
  EXPECT_NEAR(hw.i_q_A / cw.i_q_A, 1.0 / beta, 1e-12);
}

TEST(EMachineMagnets, FieldWeakeningFluxIsSetByTheVoltageAlone) {
  const EMachineParams p = yamlParams();
  const LossModel lm(p.electrical, p.iron, p.mechanical, p.inverter);
  const double hot = celsiusToK(120.0), beta = lm.magnetFluxFactor(hot);
  // The voltage-limit speed rises as the magnet EMF falls: ω_v = V k_v/(β k_t/3).
  const double wv_ref = lm.voltageLimitSpeed(48.0, kMagnetRef_K);
  EXPECT_NEAR(lm.voltageLimitSpeed(48.0, hot), wv_ref / beta, 1e-9);
  // Deep in field weakening the stator flux (∝ B) is V/ω whatever the magnets: same iron loss;
  // the d-current I_d = -β I_ch (1 - ω_v/ω) by hand.
  const double w = 3.0 * wv_ref / beta;
  const LossBreakdown c = lm.evaluate(0.0, w, 48.0, celsiusToK(60.0), kMagnetRef_K);
  const LossBreakdown h = lm.evaluate(0.0, w, 48.0, celsiusToK(60.0), hot);
  EXPECT_NEAR(h.iron_W, c.iron_W, 1e-9 * c.iron_W);
  EXPECT_NEAR(h.i_d_A, -beta * 150.0 * (1.0 - (wv_ref / beta) / w), 1e-9);
  EXPECT_NEAR(c.i_d_A, -150.0 * (1.0 - wv_ref / w), 1e-9);
}

TEST(EMachineMagnets, EngineHeatPathWarmsTheMachineTowardTheEngine) {
  // Machine idle (no torque, at rest: no losses), coolant at 40 degC, engine at 90 degC: the
  // steady state sits between them, with the heat from the engine equal to the heat to the
  // coolant (no losses), and the model's cumulative engine heat equals the coolant's.
  const EMachineParams p = yamlParams();
  EMachineModel m(p, "config/emachine.yaml");
  const double Tc = celsiusToK(40.0), Te = celsiusToK(90.0);
  m.reset(Tc);
  EMachineInputs in;
  in.coolant_T_K = Tc;
  in.engine_T_K = Te;
  for (int k = 0; k < 20000; ++k) m.step(1.0, in);  // 20000 s, exact steps
  const auto& o = m.outputs();
  const double q0[4] = {0.0, 0.0, 0.0, 0.0};
  const auto hand = handSteadyState(p.thermal, q0, Tc, Te);
  EXPECT_NEAR(o.housing_T_K, hand[3], 1e-6);
  EXPECT_NEAR(o.magnet_T_K, hand[2], 1e-6);
  EXPECT_GT(o.housing_T_K, Tc);
  EXPECT_LT(o.magnet_T_K, Te);
  const double q_e = p.thermal.G_housing_engine_W_K * (Te - hand[3]) + p.thermal.G_rotor_crank_W_K * (Te - hand[2]);
  EXPECT_NEAR(o.engine_heat_W, q_e, 1e-6 * q_e);
  EXPECT_NEAR(o.lt_heat_W, q_e, 1e-6 * q_e);
  std::printf("idle machine, coolant 40 degC, engine 90 degC: housing %.1f degC, magnets %.1f degC, "
              "heat from the engine %.0f W\n", o.housing_T_K - 273.15, o.magnet_T_K - 273.15, q_e);
}
