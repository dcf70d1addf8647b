// A lumped wall heated by a gas stream and losing heat to ambient: the exact step of its linear
// ODE and the outer film coefficient of a hot cylinder under the bus. Shared by the brick slices
// (brick.hpp) and the exhaust-line walls (exhaust_line.hpp). ROS-free, inline, allocation-free.
//
// Wall (inputs held over the step dt):
//   C dT/dt = G (Tg_in - T) + Q - UA (T - T_amb)                                       [W]
//   G = mdot cp (1 - exp(-NTU)), NTU = hA / (mdot cp): the gas crosses the wall quasi-steadily,
//   Tg_out = T + (Tg_in - T) exp(-NTU) (gas heat capacity << wall heat capacity).
// Exact solution with lambda = (G + UA)/C, T_eq = (G Tg_in + Q + UA T_amb)/(G + UA):
//   T(dt) = T_eq + (T0 - T_eq) exp(-lambda dt),
//   Tbar = T_eq + (T0 - T_eq) (1 - exp(-lambda dt))/(lambda dt)   (time mean over the step),
// so that C (T1 - T0) = dt [G (Tg_in - Tbar) + Q - UA (Tbar - T_amb)] holds to round-off.
//
// Outer film (cylinder of outer diameter D in air at T_amb):
//   h_ext = h_nat + h_rad + h_forced,  h_rad = 4 eps sigma T_m^3, T_m = (T_wall + T_amb)/2
//   (radiation linearised about the film temperature), h_forced from Hilpert's cylinder in cross
//   flow, Nu_D = C Re^m Pr^(1/3) with (C, m) = (0.193, 0.618) for Re < 4e4 and (0.027, 0.805)
//   above (Incropera & DeWitt, "Fundamentals of Heat and Mass Transfer", table 7.2), air
//   properties at T_m and standard pressure, Pr = 0.70.
#pragma once
#include <cmath>

#include "aftertreatment/gas.hpp"

namespace hbt::aftertreatment {

constexpr double kStefanBoltzmann_W_m2K4 = 5.670374e-8;
constexpr double kAirPrandtl = 0.70;  // air film, 300-700 K

struct WallStep {
  double T1 = 0.0;    ///< wall temperature at the end of the step [K]
  double Tbar = 0.0;  ///< time-mean wall temperature over the step [K]
};

/// Exact step of C dT/dt = G (Tg - T) + Q - UA (T - T_amb) over dt (header).
inline WallStep exactWallStep(double T0, double C, double G, double UA, double Q, double Tg,
                              double T_amb, double dt) {
  WallStep w;
  const double a = G + UA;
  if (a > 0.0) {
    const double Teq = (G * Tg + Q + UA * T_amb) / a;
    const double x = a * dt / C;
    const double decay = std::exp(-x);
    w.T1 = Teq + (T0 - Teq) * decay;
    // mean over the step: Teq + (T0 - Teq) (1 - exp(-x)) / x
    const double frac = x > 1e-8 ? -std::expm1(-x) / x : 1.0 - 0.5 * x;
    w.Tbar = Teq + (T0 - Teq) * frac;
  } else {
    w.T1 = T0 + Q * dt / C;
    w.Tbar = 0.5 * (T0 + w.T1);
  }
  return w;
}

/// Outer film coefficient (natural + linearised radiation + forced cross flow) [W/(m^2 K)].
inline double outerFilmH(double T_wall_K, double T_amb_K, double air_speed_m_s, double D_outer_m,
                         double h_natural_W_m2K, double emissivity) {
  const double Tm = 0.5 * (T_wall_K + T_amb_K);
  const double h_rad = 4.0 * emissivity * kStefanBoltzmann_W_m2K4 * Tm * Tm * Tm;
  double h_forced = 0.0;
  if (air_speed_m_s > 0.0) {
    // Air film at the mean of wall and ambient temperature (ambient pressure).
    const double rho = kAtm_Pa / (species::kDryAirGas_J_kgK * Tm);
    const double Re = rho * air_speed_m_s * D_outer_m / viscosity(Tm);
    const double Pr13 = std::cbrt(kAirPrandtl);
    const double Nu = Re < 4e4 ? 0.193 * std::pow(Re, 0.618) * Pr13 : 0.027 * std::pow(Re, 0.805) * Pr13;
    h_forced = Nu * conductivity(Tm) / D_outer_m;
  }
  return h_natural_W_m2K + h_rad + h_forced;
}

}  // namespace hbt::aftertreatment
