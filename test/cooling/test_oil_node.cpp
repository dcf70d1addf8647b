// The engine oil node of the thermal network (src/cooling/coolant_network.hpp) against
// independent references: the steady state by hand with friction heat into the oil, the limit of
// an infinite oil-cooler conductance (oil = engine loop), the oil relaxing to the coolant with
// the exchanger's time constant m c_p/UA when no friction heat enters it (exact backward-Euler
// decay and the continuous exponential), and the model's oil temperature feeding nothing but
// its own balance (the energy bookkeeping with the oil's heat in).
#include <gtest/gtest.h>

#include <cmath>

#include "common/units.hpp"
#include "cooling/coolant_network.hpp"
#include "cooling/cooling_model.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::cooling;
using units::celsiusToK;

namespace {

NetworkCapacities shippedCapacities() { return CoolingModel(test::yamlParams()).capacities(); }

// The shipped conductances of the engine side, radiator closed, no heater, no losses.
NetworkCoefficients engineSide(const CoolingParams& p) {
  NetworkCoefficients k;
  k.G_mc = p.ht.metal_to_coolant_UA_W_K;
  k.G_om = p.ht.oil_to_metal_UA_W_K;
  k.G_oc = p.ht.oil_cooler_UA_W_K;
  return k;
}

}  // namespace

// Steady state by hand: Q_m into the metal and Q_o into the oil leave through the radiator
// (W_r, G_HT); the engine loop sits at θ_c = (Q_m + Q_o)/G_HT, and metal and oil above it solve
//   Q_m = G_mc a + G_om (a - b),   Q_o + G_om (a - b) = G_oc b   (a = θ_m - θ_c, b = θ_o - θ_c).
TEST(OilNode, SteadyStateMatchesTheHandSolution) {
  const CoolingParams p = test::yamlParams();
  const CoolantNetwork net(shippedCapacities());
  const double Ta = celsiusToK(25.0), Q_m = 50e3, Q_o = 8e3;
  NetworkCoefficients k = engineSide(p);
  k.W_rad = 12e3;
  k.G_ht = 2e3;
  k.Q_engine = Q_m;
  k.Q_oil = Q_o;
  NetworkState T{Ta, Ta, Ta, Ta, Ta, Ta};
  for (int n = 0; n < 3000; ++n) net.step(10.0, Ta, k, T);
  const double G_mc = k.G_mc, G_om = k.G_om, G_oc = k.G_oc;
  const double det = (G_mc + G_om) * (G_om + G_oc) - G_om * G_om;  // [G_mc+G_om, -G_om; -G_om, G_om+G_oc]
  const double a = (Q_m * (G_om + G_oc) + G_om * Q_o) / det, b = ((G_mc + G_om) * Q_o + G_om * Q_m) / det;
  const double th_c = (Q_m + Q_o) / k.G_ht;
  EXPECT_NEAR(T.engine_loop - Ta, th_c, 1e-9 * th_c);
  EXPECT_NEAR(T.metal - T.engine_loop, a, 1e-9 * th_c);
  EXPECT_NEAR(T.oil - T.engine_loop, b, 1e-9 * th_c);
  // what the oil cooler carries = the oil's heat in + what the oil takes from the metal
  const NetworkFluxes f = net.step(10.0, Ta, k, T);
  EXPECT_NEAR(f.oil_cooler, Q_o - f.oil_to_metal, 1e-9 * Q_o);
  std::printf("steady 50 kW metal + 8 kW oil: oil %.2f K, metal %.2f K above the engine loop\n", b, a);
}

// UA -> infinity: the oil cooler ties the oil to the engine loop; on a warm-up ramp with
// friction heat into the oil, θ_o - θ_c is the hand ramp offset b (support.hpp), which falls as
// 1/G_oc to 0: oil = coolant.
TEST(OilNode, InfiniteOilCoolerGivesOilAtTheCoolant) {
  const CoolingParams p = test::yamlParams();
  const NetworkCapacities C = shippedCapacities();
  const CoolantNetwork net(C);
  const double Ta = celsiusToK(0.0), Q_m = 40e3, Q_o = 6e3, h = 0.1;
  double previous = 0.0;
  for (double G_oc : {1e3, 1e5, 1e7}) {
    NetworkCoefficients k = engineSide(p);
    k.G_oc = G_oc;
    k.Q_engine = Q_m;
    k.Q_oil = Q_o;
    NetworkState T{Ta, Ta, Ta, Ta, Ta, Ta};
    for (int i = 0; i < 12000; ++i) net.step(h, Ta, k, T);  // 1200 s: the transients (< 80 s) are over
    const double r = (Q_m + Q_o) / (C.metal + C.oil + C.engine_loop);
    const test::RampOffsets lead = test::rampOffsets(k.G_mc, k.G_om, G_oc, C.oil, Q_o, r, C.engine_loop * r);
    EXPECT_NEAR(T.oil - T.engine_loop, lead.oil_K, 1e-7);
    EXPECT_NEAR(T.metal - T.engine_loop, lead.metal_K, 1e-7);
    if (G_oc > 1e6) {
      EXPECT_NEAR(previous / lead.oil_K, 100.0, 1.0);  // -> 0 as 1/G_oc
    }
    previous = lead.oil_K;
    std::printf("oil cooler %.0e W/K: oil %.5f K above the engine loop\n", G_oc, T.oil - T.engine_loop);
  }
  EXPECT_LT(std::abs(previous), 1e-3);
}

// No friction heat, no metal coupling: the oil relaxes to the coolant. Two nodes exchanging
// through G_oc: their difference decays with λ = G_oc (1/C_o + 1/C_c); backward Euler gives
// exactly (1 + h λ)^-n. With the coolant's capacity -> infinity λ = UA/(m c_p): at t = τ the
// difference is e^-1 of its start.
TEST(OilNode, OilRelaxesToTheCoolantWithTheExchangerTimeConstant) {
  const CoolingParams p = test::yamlParams();
  NetworkCapacities C = shippedCapacities();
  NetworkCoefficients k;
  k.G_oc = p.ht.oil_cooler_UA_W_K;
  const double Ta = celsiusToK(20.0), h = 0.01, d0 = 60.0;
  {  // shipped capacities: exact discrete decay
    const CoolantNetwork net(C);
    NetworkState T{Ta, Ta, Ta, Ta, Ta, Ta + d0};
    const double lambda = k.G_oc * (1.0 / C.oil + 1.0 / C.engine_loop);
    for (int n = 1; n <= 5000; ++n) {
      net.step(h, Ta, k, T);
      ASSERT_NEAR(T.oil - T.engine_loop, d0 * std::pow(1.0 + h * lambda, -n), 1e-9) << n;
    }
  }
  C.engine_loop = 1e15;  // a coolant that does not move: τ = m c_p / UA
  const CoolantNetwork net(C);
  const double tau = p.ht.oil_mass_kg * p.ht.oil_cp_J_kgK / p.ht.oil_cooler_UA_W_K;
  NetworkState T{Ta, Ta, Ta, Ta, Ta, Ta + d0};
  const int n = static_cast<int>(std::lround(tau / h));
  for (int i = 0; i < n; ++i) net.step(h, Ta, k, T);
  EXPECT_NEAR(T.engine_loop, Ta, 1e-6);  // ~ C_o d0 / 1e15 J/K
  EXPECT_NEAR((T.oil - T.engine_loop) / d0, std::exp(-n * h / tau), 1e-4);  // backward Euler O(h/τ)
  std::printf("oil cooler time constant m c_p/UA = %.1f s\n", tau);
}
