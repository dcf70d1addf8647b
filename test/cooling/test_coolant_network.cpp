// The HT coolant volumes of the thermal network (src/cooling/coolant_network.hpp) against
// independent references: the energy conservation of every implicit update, the hand steady
// state, the exact lag of a well-mixed volume behind a ramp, the single well-mixed node as the
// flows grow, and the shut-off volumes through the full model.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "common/units.hpp"
#include "cooling/coolant_network.hpp"
#include "cooling/cooling_model.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::cooling;
using units::celsiusToK;
using units::rpmToRadps;

namespace {

// The shipped capacities (config/cooling.yaml) [J/K].
NetworkCapacities shippedCapacities() { return CoolingModel(test::yamlParams()).capacities(); }

// Deterministic uniform numbers in [lo, hi) (64-bit LCG, Knuth's MMIX constants).
struct Lcg {
  std::uint64_t x = 12345;
  double operator()(double lo, double hi) {
    x = x * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(x >> 11) / 9007199254740992.0;
  }
};

// The network with no losses, no radiator or heater heat and constant heat into the metal.
NetworkCoefficients closedRamp(double Q_W, double W_rad, double W_heater) {
  NetworkCoefficients k;
  k.G_mc = 5000.0;
  k.W_rad = W_rad;
  k.W_heater = W_heater;
  k.Q_engine = Q_W;
  return k;
}

}  // namespace

// Every update conserves energy: h (heat in - heat out) = Σ C ΔT to round-off, whatever the
// (frozen) coefficients, including shut and open valves and a heater on a stagnant loop.
TEST(CoolantNetwork, EveryImplicitUpdateConservesEnergyToRoundOff) {
  const CoolantNetwork net(shippedCapacities());
  Lcg u;
  const double Ta = celsiusToK(0.0);
  NetworkState T{Ta, Ta, Ta, Ta, Ta, Ta};
  double worst = 0.0;
  for (int n = 0; n < 20000; ++n) {
    NetworkCoefficients k;
    k.G_mc = u(1e3, 1e4);
    k.G_s = u(0.0, 50.0);
    k.G_om = u(0.0, 1.0) < 0.2 ? 0.0 : u(0.0, 1e3);
    k.G_oc = u(10.0, 3e3);
    k.Q_oil = u(0.0, 20e3);
    k.W_rad = u(0.0, 1.0) < 0.3 ? 0.0 : u(0.0, 2e4);
    k.W_heater = u(0.0, 1.0) < 0.3 ? 0.0 : u(0.0, 5e3);
    k.G_ht = std::min(k.W_rad, u(0.0, 4e3));  // ε C_min <= the coolant's capacity rate
    k.preheat = u(0.0, 0.2);
    k.G_lt = u(0.0, 800.0);
    k.q_heater = u(0.0, 1.0) < 0.5 ? u(0.0, 12e3) : 0.0;
    k.g_heater = k.q_heater > 0.0 ? 0.0 : u(0.0, 400.0);
    k.Q_engine = u(-5e3, 120e3);
    k.Q_aux = u(0.0, 1.0) < 0.2 ? 3e3 : 0.0;
    k.Q_loop = u(0.0, 1.0) < 0.2 ? 30e3 : 0.0;
    k.Q_lt = u(0.0, 8e3);
    const double h = u(0.01, 0.1);
    const NetworkState T0 = T;
    const NetworkFluxes f = net.step(h, Ta, k, T);
    const double in = k.Q_engine + k.Q_oil + k.Q_aux + k.Q_loop + k.Q_lt;
    const double out = f.radiator_ht + f.radiator_lt + f.heater + f.surface;
    const double r = h * (in - out) - net.storedSince_J(T, T0);
    worst = std::max(worst, std::abs(r) / (h * 120e3));
    // The exchanges between the volumes are what each volume gained or lost.
    EXPECT_NEAR(net.capacities().radiator * (T.radiator - T0.radiator), h * (f.to_radiator - f.radiator_ht),
                1e-9 * h * 120e3);
    EXPECT_NEAR(net.capacities().convector * (T.convector - T0.convector), h * (f.to_convector - f.heater + k.Q_loop),
                1e-9 * h * 120e3);
    EXPECT_NEAR(net.capacities().oil * (T.oil - T0.oil), h * (k.Q_oil - f.oil_cooler - f.oil_to_metal),
                1e-9 * h * 120e3);
  }
  std::printf("worst per-step residual: %.3g of the step's 120 kW x h\n", worst);
  EXPECT_LT(worst, 1e-11);
}

// Steady state by hand: heat Q into the metal leaves through the radiator alone (no surface,
// no heater, no LT): θ_c = Q/G_HT, θ_m = θ_c + Q/G_mc, radiator return θ_r = θ_c - Q/W_r,
// convector volume (open, no heat drawn) θ_v = θ_c.
TEST(CoolantNetwork, SteadyStateMatchesTheHandSolution) {
  const CoolantNetwork net(shippedCapacities());
  const double Ta = celsiusToK(25.0), Q = 60e3;
  NetworkCoefficients k = closedRamp(Q, 12e3, 2e3);
  k.G_ht = 2e3;
  NetworkState T{Ta, Ta, Ta, Ta, Ta, Ta};
  for (int n = 0; n < 2000; ++n) net.step(10.0, Ta, k, T);  // 20000 s >> every time constant
  const double th_c = Q / k.G_ht;
  EXPECT_NEAR(T.engine_loop - Ta, th_c, 1e-9 * th_c);
  EXPECT_NEAR(T.metal - T.engine_loop, Q / k.G_mc, 1e-9 * th_c);
  EXPECT_NEAR(T.engine_loop - T.radiator, Q / k.W_rad, 1e-9 * th_c);
  EXPECT_NEAR(T.convector, T.engine_loop, 1e-9 * th_c);
  EXPECT_EQ(T.lt, Ta);
}

// No losses, constant heat Q: every node ends on the ramp r = Q/ΣC. A well-mixed volume fed
// at capacity rate W lags its feed by its residence time C/W: θ_c - θ_r = C_r r/W_r,
// θ_c - θ_v = C_v r/W_v; the metal leads the coolant it feeds by (C_c + C_r + C_v) r/G_mc.
// As W grows the engine loop tends to the single well-mixed node of all 50 L:
// θ_c,single = (Q t - C_m C_cool r/G_mc)/ΣC; the difference is (C_r²/W_r + C_v²/W_v) r/ΣC.
TEST(CoolantNetwork, VolumesLagARampByTheirResidenceTimeAndTendToOneNode) {
  const NetworkCapacities C = shippedCapacities();
  const CoolantNetwork net(C);
  const double Ta = celsiusToK(25.0), Q = 50e3, h = 0.1;
  const double C_cool = C.coolantHt(), sumC = C.metal + C_cool + C.lt;
  double previous_gap = 0.0;
  for (double W : {1e3, 1e4, 1e5, 1e6}) {
    NetworkCoefficients k = closedRamp(Q, W, 0.5 * W);
    NetworkState T{Ta, Ta, Ta, Ta, Ta, Ta};
    const int n = 80000;  // 8000 s: the slowest transient (~190 s at W = 1 kW/K) has died out
    for (int i = 0; i < n; ++i) net.step(h, Ta, k, T);
    const double t = n * h, r = Q / (sumC - C.lt);
    EXPECT_NEAR(T.engine_loop - T.radiator, C.radiator * r / k.W_rad, 1e-9);
    EXPECT_NEAR(T.engine_loop - T.convector, C.convector * r / k.W_heater, 1e-9);
    EXPECT_NEAR(T.metal - T.engine_loop, C_cool * r / k.G_mc, 1e-9);
    EXPECT_EQ(T.lt, Ta);  // no heat into LT
    const double single = (Q * t - C.metal * C_cool * r / k.G_mc) / (C.metal + C_cool);
    const double gap = (T.engine_loop - Ta) - single;
    EXPECT_NEAR(gap, (C.radiator * C.radiator / k.W_rad + C.convector * C.convector / k.W_heater) * r /
                         (C.metal + C_cool), 1e-7);
    if (previous_gap > 0.0) {
      EXPECT_NEAR(previous_gap / gap, 10.0, 1e-4);  // -> 0 as 1/W
    }
    previous_gap = gap;
    std::printf("W_r %.0e W/K: engine loop %.4f K above the single 50 L node after %.0f s\n", W, gap, t);
  }
}

// Through the model: thermostat fully open and the heater loop in the circuit at a large pump
// flow, no air flow (fan at rest, bus standing) -> no heat leaves: the engine outlet follows the
// single well-mixed node of all 50 L warmed by Q - the cabin's 1 W demand.
TEST(CoolingModelVolumes, OpenValvesAtLargeFlowBehaveAsOneWellMixedNode) {
  CoolingParams p = test::yamlParams();
  p.ht.surface_loss_UA_W_K = 0.0;
  p.ht.pump_rated_flow_m3_s = 0.05;  // 3000 L/min at the rated speed
  p.heater.loop_flow_fraction = 1.0;
  p.thermostat.opening_start_K = 300.0;  // open from 27 degC, fully at 28 degC
  p.thermostat.full_open_K = 301.0;
  p.thermostat.wax_time_constant_s = 0.0;
  p.fan.min_speed_ratio = p.fan.max_speed_ratio = 0.0;  // no air through the radiator
  CoolingModel m(p);
  const double Ta = celsiusToK(25.0);
  const double T_start = celsiusToK(45.0);  // everything warm: both valves open from the start
  m.reset(Ta, T_start, T_start, Ta);
  CoolingInputs in;
  in.ambient_T_K = Ta;
  in.engine_heat_W = 20e3;
  in.pump_speed_rad_s = p.ht.pump_rated_speed_rad_s;
  in.cabin_from_hvac = true;  // heating wanted: 1 W at a cabin far below the coolant
  in.cabin_heat_demand_W = 1.0;
  in.cabin_T_K = Ta;
  for (int i = 0; i < 10000; ++i) m.step(0.1, in);  // 1000 s >> the ~45 s metal transient
  const CoolingOutputs& o = m.outputs();
  ASSERT_TRUE(o.heater_valve_open);
  EXPECT_NEAR(o.thermostat_opening, 1.0, 1e-12);
  EXPECT_EQ(o.radiator_ht_heat_W, 0.0);
  EXPECT_NEAR(o.heater_loop_flow_m3_s, 0.05, 1e-12);
  EXPECT_NEAR(o.heater_J, 1.0 * o.time_s, 1e-6);
  const NetworkCapacities& C = m.capacities();
  const double C_cool = C.coolantHt(), sumC = C.metal + C.oil + C_cool, t = o.time_s;
  const double Q_h = 1.0, r = (in.engine_heat_W - Q_h) / sumC;
  const double W = p.ht.coolant_density_kg_m3 * p.ht.coolant_cp_J_kgK * 0.05;  // both loops [W/K]
  // The metal and the oil lead by what flows through the jacket and the oil cooler, C_cool r + Q_h
  // (test::rampOffsets); the volumes lag by
  // their residence times C/W (0.3 and 0.5 s) and the convectors also by Q_h/W. The engine
  // outlet is then lag = (C_r C_r r + C_v (C_v r + Q_h))/(W ΣC) = 8 mK above the single 50 L
  // node: the split model is the single node up to the mixing time of its volumes.
  const test::RampOffsets lead = test::rampOffsets(p.ht.metal_to_coolant_UA_W_K, p.ht.oil_to_metal_UA_W_K,
                                                   p.ht.oil_cooler_UA_W_K, C.oil, 0.0, r, C_cool * r + Q_h);
  const double single = T_start + r * t - (C.metal * lead.metal_K + C.oil * lead.oil_K) / sumC;
  const double lag = (C.radiator * C.radiator * r + C.convector * (C.convector * r + Q_h)) / (W * sumC);
  EXPECT_NEAR(o.coolant_ht_T_K - single, lag, 1e-7);
  EXPECT_NEAR(o.coolant_ht_T_K - o.radiator_coolant_T_K, C.radiator * r / W, 1e-7);
  EXPECT_NEAR(o.coolant_ht_T_K - o.convector_coolant_T_K, (C.convector * r + Q_h) / W, 1e-7);
  EXPECT_LT(lag, 0.02);
  std::printf("open valves, 3000 L/min: engine outlet %.4f K from the single 50 L node (lag %.4f K)\n",
              o.coolant_ht_T_K - single, lag);
}
