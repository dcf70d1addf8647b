// E-machine thermal network and derating: the 1-node analytic limit, the hand-solved steady
// state and an RK4 transient of the 4-node network, and derating from the winding/magnet
// temperature thresholds (by hand, over a sustained peak, VECTO's continuous point and overload
// time). Shared helpers: support.hpp.
#include "support.hpp"

using namespace hbt;
using namespace hbt::emachine;
using namespace hbt::emachine::test;

TEST(EMachineThermal, OneNodeLimitIsTheAnalyticExponential) {
  // W, S, R tiny and tied by huge conductances to H: one node of C = sum C, G = G_HC.
  ThermalNetwork::Vec C, g;
  C << 1.0, 1.0, 1.0, 5000.0;
  g << 0.0, 0.0, 0.0, 80.0;
  ThermalNetwork::Mat G = ThermalNetwork::Mat::Zero();
  for (int i = 0; i < 3; ++i) G(i, 3) = G(3, i) = 1e6;
  const ThermalNetwork net(C, G, g, ThermalNetwork::Vec::Zero());
  ThermalNetwork::Vec q;
  q << 300.0, 200.0, 100.0, 0.0;  // 600 W held
  const double Tc = 330.0, T0 = 290.0, Ctot = 5003.0;
  ThermalNetwork::Vec x = ThermalNetwork::Vec::Constant(T0), xi;
  double t = 0.0, Q = 0.0;
  for (int k = 0; k < 2000; ++k) {
    const double h = (k % 3 == 0) ? 0.37 : 1.3;  // uneven steps: exact for any h
    const ThermalNetwork::Vec xs = x;
    net.step(h, q, Tc, 0.0, x, xi);  // no engine link: its temperature plays no part
    t += h;
    Q += 80.0 * (xi(3) - Tc * h);
    const double ref = Tc + 600.0 / 80.0 + (T0 - Tc - 600.0 / 80.0) * std::exp(-80.0 * t / Ctot);
    ASSERT_NEAR(x(3), ref, 1e-3) << t;           // internal ΔT <= 600 W / 1e6 W/K
    EXPECT_NEAR(x(0), x(3), 1e-3);
    (void)xs;
  }
  // Energy: 600 W t = Q + sum C ΔT to rounding.
  EXPECT_NEAR(600.0 * t - Q - C.dot(x - ThermalNetwork::Vec::Constant(T0)), 0.0, 1e-6 * 600.0 * t);
}

TEST(EMachineThermal, SteadyStateIsTheHandSolvedNetworkAndTransientMatchesRk4) {
  const EMachineParams p = yamlParams();
  const EMachineModel m(p, "config/emachine.yaml");
  const ThermalNetwork& net = m.network();
  const double q[4] = {1017.0, 107.0, 21.0, 7.0};  // continuous corner, hot (README)
  const double Tc = celsiusToK(65.0), Te = celsiusToK(90.0);  // LT coolant, warm engine
  const auto hand = handSteadyState(p.thermal, q, Tc, Te);
  ThermalNetwork::Vec qv;
  qv << q[0], q[1], q[2], q[3];
  const ThermalNetwork::Vec ss = net.steadyState(qv, Tc, Te);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(ss(i), hand[i], 1e-9) << i;
  std::printf("steady state at 65 degC coolant, 90 degC engine, 1017/107/21/7 W: W %.1f S %.1f R %.1f H %.1f degC\n",
              hand[0] - 273.15, hand[1] - 273.15, hand[2] - 273.15, hand[3] - 273.15);
  // Long exact step lands on it; energy balance in steady state: losses + heat from the engine
  // (housing flange and rotor hub) = G_HC (T_H - Tc).
  ThermalNetwork::Vec x = ThermalNetwork::Vec::Constant(Tc), xi;
  net.step(1e6, qv, Tc, Te, x, xi);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(x(i), hand[i], 1e-8);
  const double from_engine =
      p.thermal.G_housing_engine_W_K * (Te - hand[3]) + p.thermal.G_rotor_crank_W_K * (Te - hand[2]);
  EXPECT_GT(from_engine, 0.0);  // the engine is hotter than housing and rotor here
  EXPECT_NEAR(p.thermal.G_housing_coolant_W_K * (hand[3] - Tc), q[0] + q[1] + q[2] + q[3] + from_engine, 1e-9);
  // Transient: 0.01 s exact steps vs RK4 with 1 ms steps from a cold start at 25 degC, 65 degC coolant.
  double y[4];
  for (double& v : y) v = celsiusToK(25.0);
  x = ThermalNetwork::Vec::Constant(celsiusToK(25.0));
  for (int block = 0; block < 6; ++block) {  // 6 x 100 s
    rk4Network(p.thermal, q, Tc, Te, 1e-3, 100000, y);
    for (int k = 0; k < 10000; ++k) net.step(0.01, qv, Tc, Te, x, xi);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(x(i), y[i], 1e-7) << "t=" << (block + 1) * 100 << " node " << i;
  }
}

TEST(EMachineDerating, LimitsFollowTheTemperatureThresholdsByHand) {
  const EMachineModel m(yamlParams(), "config/emachine.yaml");
  const double w = rpmToRadps(700.0);  // 1400 rpm EM: gen peak 30 kW, continuous 15 kW
  const CrankLimits cold = m.limits(w, kNom, celsiusToK(25.0), celsiusToK(25.0));
  EXPECT_NEAR(cold.min_cont / cold.min_peak, 0.5, 3e-5);  // 15 of 30 kW (data rounding)
  auto check = [&](double Tw_c, double Tm_c, double lam, double kap) {
    const CrankLimits c = m.limits(w, kNom, celsiusToK(Tw_c), celsiusToK(Tm_c));
    EXPECT_NEAR(c.min_live, kap * (cold.min_cont + lam * (cold.min_peak - cold.min_cont)), 1e-9)
        << Tw_c << " " << Tm_c;
    EXPECT_NEAR(c.max_live, kap * cold.max_peak, 1e-9);  // motoring: peak = continuous here
    const double f = std::min(c.max_live / c.max_peak, c.min_live / c.min_peak);
    EXPECT_NEAR(c.derating_factor, f, 1e-12);
  };
  check(139.0, 25.0, 1.0, 1.0);
  check(150.0, 25.0, 0.5, 1.0);
  check(160.0, 25.0, 0.0, 1.0);
  check(170.0, 25.0, 0.0, 0.5);
  check(180.0, 25.0, 0.0, 0.0);
  check(25.0, 127.5, 0.5, 1.0);   // magnets 120 -> 135
  check(25.0, 142.5, 0.0, 0.5);   // magnets 135 -> 150
  check(150.0, 123.0, 0.5, 1.0);  // the worse of the two
  check(25.0, 200.0, 0.0, 0.0);
}

// Sustained peak generation at 65 degC coolant from a warm start: the generating limit stays at
// the peak until the winding crosses 140 degC -- at the time an independent RK4 integration of the
// network with the same losses predicts -- then falls toward the continuous envelope; with zero
// torque it cools and the peak limit comes back.
TEST(EMachineDerating, SustainedPeakGenerationDeratesWhenTheWindingReachesTheThresholdAndRecovers) {
  const EMachineParams p = yamlParams();
  EMachineModel m(p, "config/emachine.yaml");
  const double Tc = celsiusToK(65.0);
  m.reset(Tc);
  EMachineInputs in;
  in.crank_speed_rad_s = rpmToRadps(700.0);
  in.coolant_T_K = Tc;
  in.engine_T_K = Tc;
  in.torque_request_Nm = -1e4;
  const CrankLimits cold = m.limits(in.crank_speed_rad_s, kNom, Tc, Tc);
  // Reference: RK4 (1 ms) of the hand-written network, losses of the peak torque at the current
  // winding temperature (the loss model is the only shared piece), crossing time of 140 degC.
  const double w_em = 2.0 * in.crank_speed_rad_s;
  const double T_em = cold.min_peak * 0.98 / 2.0;
  double y[4] = {Tc, Tc, Tc, Tc}, t_ref = -1.0;
  for (int k = 0; k < 600000 && t_ref < 0; ++k) {
    const LossBreakdown b = m.lossModel().evaluate(T_em, w_em, kNom, y[0], y[2]);
    const double q[4] = {b.copper_W, b.iron_W, b.rotor_W + b.windage_W, b.bearing_W};
    const double before = y[0];
    rk4Network(p.thermal, q, Tc, in.engine_T_K, 1e-3, 1, y);
    if (before < p.derating.winding_start_K && y[0] >= p.derating.winding_start_K)
      t_ref = (k + (p.derating.winding_start_K - before) / (y[0] - before)) * 1e-3;
  }
  ASSERT_GT(t_ref, 0.0);
  double t_model = -1.0, t = 0.0, Tmag_max = 0.0, prev_min_live = 0.0;
  for (int k = 0; k < 100000; ++k) {
    m.step(0.01, in);
    t += 0.01;
    const auto& o = m.outputs();
    Tmag_max = std::max(Tmag_max, o.magnet_T_K);
    if (t_model < 0.0) {
      if (o.limits.min_live > o.limits.min_peak) {
        t_model = t;  // first published limit above (less negative than) the peak
        EXPECT_GE(o.winding_T_K, p.derating.winding_start_K);
      } else {
        EXPECT_EQ(o.torque_Nm, cold.min_peak) << t;  // full peak delivered until then
      }
    }
    if (k > 0) {
      EXPECT_EQ(o.torque_Nm, prev_min_live) << "delivered = limit published at the step start";
    }
    prev_min_live = o.limits.min_live;
    if (t > t_model + 120.0 && t_model > 0) break;
  }
  std::printf("peak generation 30 kW at 1400 rpm EM, 65 degC coolant: derating starts at t = %.2f s "
              "(RK4 reference crossing of 140 degC: %.3f s); magnet max %.1f degC\n",
              t_model, t_ref, Tmag_max - 273.15);
  EXPECT_NEAR(t_model, t_ref, 0.011);
  EXPECT_LT(Tmag_max, p.derating.magnet_start_K);  // the winding, not the magnets, limits here
  // Two minutes later: settled between peak and continuous, winding between 140 and 160 degC.
  const auto& o = m.outputs();
  EXPECT_GT(o.winding_T_K, p.derating.winding_start_K);
  EXPECT_LT(o.winding_T_K, p.derating.winding_continuous_K);
  EXPECT_LT(o.limits.derating_factor, 1.0);
  EXPECT_LE(o.limits.min_live, o.limits.min_cont);
  // Cool down at zero torque: the peak comes back once the winding is below 140 degC.
  in.torque_request_Nm = 0.0;
  double t_back = -1.0;
  for (int k = 0; k < 60000 && t_back < 0; ++k) {
    m.step(0.01, in);
    if (m.outputs().limits.derating_factor == 1.0) t_back = 0.01 * (k + 1);
  }
  EXPECT_GT(t_back, 0.0);
  EXPECT_LT(m.outputs().winding_T_K, p.derating.winding_start_K);
  EXPECT_EQ(m.outputs().limits.min_live, cold.min_peak);
  std::printf("  recovered to the peak limit %.1f s after the request went to 0\n", t_back);
}

// Motoring: peak = continuous envelope (VECTO), so the motoring limit falls only from the
// continuous-to-zero threshold (160 degC); between 140 and 160 degC it moves only by the rounding
// of the .vemp data (peak and continuous differ by < 3e-5 there). A weakly cooled variant
// (G_WS = 5 W/K) reaches 160 degC at 15 kW.
TEST(EMachineDerating, MotoringLimitFallsOnlyAtTheContinuousThreshold) {
  EMachineParams p = yamlParams();
  p.thermal.G_winding_stator_W_K = 5.0;
  EMachineModel m(p, "config/emachine.yaml");
  const double Tc = celsiusToK(65.0);
  m.reset(Tc);
  EMachineInputs in;
  in.crank_speed_rad_s = rpmToRadps(600.0);
  in.coolant_T_K = in.engine_T_K = Tc;
  in.torque_request_Nm = 1e4;
  EXPECT_NEAR(m.outputs().limits.max_peak, 2.0 * 0.98 * 220.0, 1e-9);  // reset: standstill
  double t = 0, t_fall = -1, T_at_fall = 0;
  for (int k = 0; k < 400000 && t_fall < 0; ++k) {
    const double Tw_before = m.outputs().winding_T_K;
    m.step(0.01, in);
    t += 0.01;
    const auto& o = m.outputs();
    if (o.winding_T_K < p.derating.winding_continuous_K) {
      EXPECT_GT(o.limits.max_live, (1.0 - 3e-5) * o.limits.max_peak) << t;
    }
    if (o.limits.max_live < 0.999 * o.limits.max_peak) {
      t_fall = t;
      T_at_fall = o.winding_T_K;
      EXPECT_LT(Tw_before, p.derating.winding_continuous_K + 0.05 * 20.0);  // within the first 0.1 %
    }
  }
  ASSERT_GT(t_fall, 0.0);
  EXPECT_GE(T_at_fall, p.derating.winding_continuous_K);
  std::printf("weakly cooled motoring at 15 kW: motoring limit 0.1 %% below peak at t = %.1f s, winding %.2f degC\n",
              t_fall, T_at_fall - 273.15);
}

// The two VECTO thermal numbers of the generic machine: the continuous power (15 kW at 651 rpm)
// is sustainable at the LT design coolant temperature (65 degC) below the derating threshold,
// and from that steady state the peak (440 Nm generating at 651 rpm) lasts about the VECTO
// overload time (15 s) before the limit starts to fall.
TEST(EMachineDerating, VectoContinuousPointIsSustainableAndOverloadTimeIsReproduced) {
  const EMachineParams p = yamlParams();
  EMachineModel m(p, "config/emachine.yaml");
  const double Tc = celsiusToK(65.0);
  m.reset(Tc);
  EMachineInputs in;
  in.crank_speed_rad_s = 15000.0 / 220.0 / 2.0;  // 651.09 rpm EM
  in.coolant_T_K = in.engine_T_K = Tc;           // bench: the mounting flange at the coolant temperature
  in.torque_request_Nm = -2.0 * 220.0 / 0.98;     // continuous generating, 15 kW
  for (int k = 0; k < 1200000; ++k) m.step(0.01, in);  // 12000 s: steady (slowest mode ~1700 s)
  const auto o = m.outputs();
  EXPECT_NEAR(o.torque_Nm, in.torque_request_Nm, 1e-9);
  EXPECT_LT(o.winding_T_K, p.derating.winding_start_K);
  EXPECT_LT(o.magnet_T_K, p.derating.magnet_start_K);
  EXPECT_EQ(o.limits.derating_factor, 1.0);
  in.torque_request_Nm = -1e4;  // peak: 440 Nm EM
  double t = 0.0;
  while (m.outputs().limits.derating_factor == 1.0 && t < 600.0) {
    m.step(0.01, in);
    t += 0.01;
  }
  std::printf("VECTO continuous point 15 kW at 651 rpm, 65 degC coolant: winding %.1f, stator %.1f, magnet %.1f, "
              "housing %.1f degC, copper %.0f W; peak (440 Nm) from there until derating: %.1f s (VECTO: 15 s)\n",
              o.winding_T_K - 273.15, o.stator_T_K - 273.15, o.magnet_T_K - 273.15, o.housing_T_K - 273.15,
              o.loss.copper_W, t);
  EXPECT_GT(t, 8.0);
  EXPECT_LT(t, 30.0);
}

