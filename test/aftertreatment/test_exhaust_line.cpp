// ExhaustLine (lumped walls of manifold, turbine housing, pipes, box chambers) against the energy
// balance, the analytic steady pipe solution and the analytic lumped time constant.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "aftertreatment/exhaust_line.hpp"
#include "support.hpp"

namespace hbt::aftertreatment {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Gas properties written out here, independent of gas.hpp: Sutherland (air) and the k(T) power law.
double mu(double T) { return 1.716e-5 * std::pow(T / 273.15, 1.5) * (273.15 + 110.4) / (T + 110.4); }
double kgas(double T) { return 0.0241 * std::pow(T / 273.15, 0.81); }

ExhaustLine upstreamLine(const AtsParams& p) {
  const LineParams& l = p.line;
  return ExhaustLine({"manifold", "turbine_housing", "downpipe", "rear_pipe", "box_inlet"},
                     {l.manifold, l.turbine_housing, l.downpipe, l.rear_pipe, l.box_inlet}, l,
                     p.h_natural_W_m2K);
}

// Over a city-like transient (flow, gas temperature, vehicle speed swinging, engine stops) the
// line's energy closes to round-off: enthalpy given up by the gas = stored + outer loss.
TEST(ExhaustLine, EnergyBalanceClosesToRoundOff) {
  const AtsParams p = test::loadParams();
  ExhaustLine line = upstreamLine(p);
  const double T0 = 273.15, cp = 1080.0;
  line.setUniformTemperature(T0);
  const double E0 = line.energyStored();
  BrickEnergy e;
  double given_J = 0.0, max_Tout = 0.0;
  for (int k = 0; k < 36000; ++k) {  // 1 h at 0.1 s
    const double t = 0.1 * k;
    const double load = 0.5 + 0.5 * std::sin(2.0 * kPi * t / 60.0);
    const bool stop = std::fmod(t, 300.0) > 270.0;  // 30 s engine off every 5 min
    const double mdot = stop ? 0.0 : 0.03 + 0.2 * load;
    const double Tin = 420.0 + 300.0 * load;
    const double Tout = line.step(0.1, mdot, cp, Tin, T0, 8.0 * load, e);
    given_J += mdot * cp * (Tin - Tout) * 0.1;
    max_Tout = std::max(max_Tout, Tout);
  }
  const double stored = line.energyStored() - E0;
  EXPECT_NEAR(e.stored_J, stored, 1e-9 * stored);
  const double residual = given_J - e.stored_J - e.can_loss_J;
  EXPECT_GT(e.can_loss_J, 0.05 * given_J);  // the losses are material
  EXPECT_LT(std::abs(residual), 1e-10 * given_J);
  EXPECT_NEAR(e.gas_to_wall_J, given_J, 1e-10 * given_J);
  EXPECT_LT(max_Tout, 720.0);  // the walls damp the 720 K peaks
  std::printf("[ats] line 1 h: gas gave %.4g J = stored %.4g + outer loss %.4g, residual %.2g J\n",
              given_J, e.stored_J, e.can_loss_J, residual);
}

// One down-pipe segment at constant flow with a constant outer conductance (natural convection
// only, no radiation, no wrap): the wall settles at T_w = (G Tin + UA Tamb)/(G + UA), the gas
// leaves at T_w + (Tin - T_w) exp(-hA/(mdot cp)), and a step from T0 follows
// T(t) = T_w + (T0 - T_w) exp(-t/tau), tau = C/(G + UA) -- every quantity computed here from
// the Dittus-Boelter law and the geometry.
TEST(ExhaustLine, SteadyStateAndStepResponseMatchTheAnalyticPipe) {
  const AtsParams p = test::loadParams();
  PipeSegmentParams s = p.line.downpipe;
  s.emissivity = 0.0;
  s.insulation_thickness_m = 0.0;
  s.air_speed_factor = 0.0;
  const double h_nat = 5.0;
  ExhaustLine line({"downpipe"}, {s}, p.line, h_nat);
  const double mdot = 0.15, cp = 1100.0, Tin = 700.0, Tamb = 290.0, T0 = 290.0;
  const double Re = 4.0 * mdot / (kPi * s.diameter_m * mu(Tin));
  const double Nu = 0.023 * std::pow(Re, 0.8) * std::pow(0.70, 0.3);
  const double hA = Nu * kgas(Tin) / s.diameter_m * s.inner_area_m2;
  EXPECT_NEAR(s.inner_area_m2, kPi * s.diameter_m * s.length_m, 0.01 * s.inner_area_m2);  // a pipe
  const double G = mdot * cp * (1.0 - std::exp(-hA / (mdot * cp)));
  const double UA = h_nat * s.outer_area_m2;
  const double Tw = (G * Tin + UA * Tamb) / (G + UA);
  const double tau = s.wall_mass_kg * s.wall_cp_J_kgK / (G + UA);
  EXPECT_GT(Re, 1e4);  // turbulent: the Dittus-Boelter branch
  EXPECT_NEAR(line.gasSideHA(0, mdot, Tin), hA, 1e-12 * hA);
  line.setUniformTemperature(T0);
  BrickEnergy e;
  double t = 0.0, max_err = 0.0, Tout = 0.0;
  for (int k = 0; k < 10000; ++k) {  // 5000 s = 45 tau: settled
    Tout = line.step(0.5, mdot, cp, Tin, Tamb, 0.0, e);
    t += 0.5;
    max_err = std::max(max_err, std::abs(line.T(0) - (Tw + (T0 - Tw) * std::exp(-t / tau))));
  }
  EXPECT_GT(tau, 30.0);  // a real transient (60 steps per tau)
  EXPECT_LT(max_err, 1e-9 * (Tin - T0));
  EXPECT_NEAR(line.T(0), Tw, 1e-6);
  const double Tout_exact = Tw + (Tin - Tw) * std::exp(-hA / (mdot * cp));
  EXPECT_NEAR(Tout, Tout_exact, 1e-6);
  std::printf("[ats] down-pipe 0.15 kg/s, 700 K: Re %.0f, hA %.2f W/K, UA %.2f W/K, tau %.1f s, "
              "max step-response error %.2g K; steady wall %.3f K, gas out %.3f K (exact %.3f K)\n",
              Re, hA, UA, tau, max_err, line.T(0), Tout, Tout_exact);
}

// The pulsating-flow law upstream of the turbine, the steady pipe law downstream, the laminar
// bound at idle-like flows (Re from the geometry here).
TEST(ExhaustLine, NusseltLawsPerSegment) {
  const AtsParams p = test::loadParams();
  ExhaustLine line = upstreamLine(p);
  const double mdot = 0.2, T = 750.0;
  const double Re_m = 4.0 * mdot / (kPi * p.line.manifold.diameter_m * mu(T));
  EXPECT_NEAR(line.nusselt(0, mdot, T), 0.07 * std::pow(Re_m, 0.75), 1e-9 * Re_m);
  const double Re_d = 4.0 * mdot / (kPi * p.line.downpipe.diameter_m * mu(T));
  EXPECT_NEAR(line.nusselt(2, mdot, T), 0.023 * std::pow(Re_d, 0.8) * std::pow(0.7, 0.3), 1e-9 * Re_d);
  // at Re ~ 1e5 the pulsating law gives about twice the steady pipe law of the same passage
  EXPECT_GT(0.07 * std::pow(Re_m, 0.75), 1.8 * 0.023 * std::pow(Re_m, 0.8) * std::pow(0.7, 0.3));
  EXPECT_DOUBLE_EQ(line.nusselt(2, 1e-5, T), 3.66);  // laminar bound
}

// No flow: the walls cool through their outer surfaces alone and the gas temperature given has
// no effect.
TEST(ExhaustLine, WithoutFlowTheWallsCoolThroughTheirOuterSurfaceOnly) {
  const AtsParams p = test::loadParams();
  ExhaustLine a = upstreamLine(p), b = upstreamLine(p);
  a.setUniformTemperature(600.0);
  b.setUniformTemperature(600.0);
  BrickEnergy ea, eb;
  for (int k = 0; k < 600; ++k) {
    a.step(0.1, 0.0, 1080.0, 300.0, 290.0, 0.0, ea);
    b.step(0.1, 0.0, 1080.0, 900.0, 290.0, 0.0, eb);
  }
  for (int i = 0; i < a.segments(); ++i) {
    EXPECT_EQ(a.T(i), b.T(i));
    EXPECT_LT(a.T(i), 600.0);
    EXPECT_GT(a.T(i), 290.0);
  }
  EXPECT_EQ(ea.gas_to_wall_J, 0.0);
  EXPECT_NEAR(ea.stored_J, -ea.can_loss_J, 1e-9 * ea.can_loss_J);
}

}  // namespace
}  // namespace hbt::aftertreatment
