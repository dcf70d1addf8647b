// Cabin heat balance (src/hvac/cabin.hpp) against its exact solutions: the steady state is the
// analytic balance temperature, a step of heat gives the first-order exponential of the lumped
// mass, the door exchange is the large-opening formula, and the booked flows close the balance.
#include <gtest/gtest.h>

#include <cmath>

#include "hvac/cabin.hpp"
#include "support.hpp"

using namespace hbt;
using namespace hbt::hvac;

namespace {

// The conductance and capacity computed here from the YAML values, independently of cabin.cpp.
struct Hand {
  double UA, G_fresh, C;
};
Hand hand(const HvacParams& p, double T_a, double p_a) {
  const auto& c = p.cabin;
  Hand h;
  h.UA = c.u_value_W_m2K * 2.0 * (c.length_m * c.width_m + c.length_m * c.height_m + c.width_m * c.height_m);
  h.G_fresh = p_a / (p.air.R_J_kgK * T_a) * c.air_volume_m3 * c.fresh_air_changes_per_h / 3600.0 * p.air.cp_J_kgK;
  h.C = 101325.0 / (p.air.R_J_kgK * 293.15) * c.air_volume_m3 * p.air.cp_J_kgK + c.interior_heat_capacity_J_K;
  return h;
}

}  // namespace

TEST(Cabin, SteadyStateIsTheAnalyticBalanceTemperature) {
  const HvacParams p = test::yamlParams();
  Cabin cab(p.cabin, p.doors, p.air);
  CabinInputs in;
  in.ambient_T_K = 273.15;
  in.heat_W = 12000.0;
  in.gain_W = 1300.0;
  const Hand h = hand(p, in.ambient_T_K, in.ambient_p_Pa);
  EXPECT_NEAR(cab.bodyUA_W_K(), 445.5, 1e-9);  // 3 W/(m^2 K) x 148.5 m^2
  cab.reset(in.ambient_T_K);
  for (int i = 0; i < 200000; ++i) cab.step(0.1, in);  // 20000 s = 15 time constants
  const double T_bal = in.ambient_T_K + (in.heat_W + in.gain_W) / (h.UA + h.G_fresh);
  EXPECT_NEAR(cab.temperature_K(), T_bal, 1e-6);
  EXPECT_NEAR(units::kToCelsius(T_bal), 21.49, 0.01);  // 13.3 kW over 619 W/K (445.5 body + 173.5 fresh air)
}

TEST(Cabin, HeatStepGivesTheFirstOrderExponential) {
  const HvacParams p = test::yamlParams();
  Cabin cab(p.cabin, p.doors, p.air);
  CabinInputs in;
  in.ambient_T_K = 273.15;
  in.heat_W = 20000.0;
  const Hand h = hand(p, in.ambient_T_K, in.ambient_p_Pa);
  EXPECT_NEAR(cab.heatCapacity_J_K(), h.C, 1e-6);
  const double G = h.UA + h.G_fresh, tau = h.C / G, dT_inf = in.heat_W / G;
  cab.reset(in.ambient_T_K);
  double t = 0.0;
  for (double t_check : {60.0, 600.0, tau, 3000.0, 6000.0}) {
    while (t < t_check - 1e-9) {
      const double dt = std::min(0.1, t_check - t);
      cab.step(dt, in);
      t += dt;
    }
    const double exact = in.ambient_T_K + dT_inf * (1.0 - std::exp(-t / tau));
    EXPECT_NEAR(cab.temperature_K(), exact, 1e-8 * dT_inf) << "t = " << t;
  }
  // The exact update does not depend on the step: one step of 6000 s lands on the same value.
  Cabin one(p.cabin, p.doors, p.air);
  one.reset(in.ambient_T_K);
  one.step(6000.0, in);
  EXPECT_NEAR(one.temperature_K(), cab.temperature_K(), 1e-9);
  EXPECT_NEAR(tau, 1087.0, 1.0);  // 672.8 kJ/K over 619 W/K
}

TEST(Cabin, OpenDoorsExchangeAirByTheLargeOpeningFormula) {
  const HvacParams p = test::yamlParams();
  Cabin cab(p.cabin, p.doors, p.air);
  CabinInputs in;
  in.ambient_T_K = 273.15;
  in.doors_open = true;
  const double T = 293.15;
  const double rho = in.ambient_p_Pa / (p.air.R_J_kgK * in.ambient_T_K);
  const double Q_door = 0.6 / 3.0 * 1.2 * 2.0 * std::sqrt(9.81 * 2.0 * 20.0 / 283.15);  // one door [m^3/s]
  EXPECT_NEAR(cab.conductance(in, T).doors_W_K, rho * 3.0 * Q_door * p.air.cp_J_kgK, 1e-9);
  EXPECT_NEAR(3.0 * Q_door, 1.695, 0.001);  // 1.7 m^3/s through three doors at 20 K
  EXPECT_EQ(cab.conductance(in, in.ambient_T_K).doors_W_K, 0.0);  // no buoyancy without a difference
  in.doors_open = false;
  EXPECT_EQ(cab.conductance(in, T).doors_W_K, 0.0);
}

TEST(Cabin, BookedFlowsCloseTheBalance) {
  const HvacParams p = test::yamlParams();
  Cabin cab(p.cabin, p.doors, p.air);
  cab.reset(280.0);
  CabinInputs in;
  in.ambient_T_K = 268.15;
  double in_J = 0.0, out_J = 0.0;
  for (int i = 0; i < 30000; ++i) {
    in.doors_open = (i / 300) % 4 == 0;  // doors open 30 s of every 120 s
    in.heat_W = (i / 1000) % 2 ? 15000.0 : 5000.0;
    in.cool_W = (i / 7000) % 3 == 2 ? 2000.0 : 0.0;
    in.gain_W = 1200.0;
    const CabinFlows f = cab.step(0.1, in);
    in_J += (in.heat_W - in.cool_W + in.gain_W) * 0.1;
    out_J += (f.body_W + f.fresh_air_W + f.doors_W) * 0.1;
  }
  const double stored_J = cab.heatCapacity_J_K() * (cab.temperature_K() - 280.0);
  EXPECT_NEAR(in_J - out_J - stored_J, 0.0, 1e-9 * in_J);
}
