#include "cylinder/hot_zone_no.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hbt::cylinder {

HotZoneNO::HotZoneNO(const GasThermo& thermo) : th_(thermo) {}

double HotZoneNO::frozenFlameTemperature_K(double T_u, double y_air) const {
  if (!(T_u > 0.0 && y_air > 0.0 && y_air <= 1.0)) return std::numeric_limits<double>::quiet_NaN();
  const FuelSpec& f = th_.fuel();
  const double a_A = th_.afrStoich(), a_R = a_A * (1.0 / y_air - 1.0), m_p = 1.0 + a_A + a_R;
  const Poly& B = th_.group(kBurned);
  const double H = th_.group(kFuelVap).h(T_u) + f.lhv_J_kg + f.hfg_J_kg +
                   a_A * th_.group(kAir).h(T_u) + a_R * B.h(T_u);  // [J/kg fuel]
  // Newton on m_p h_B(T) = H from a flame-like start; h_B is monotonic (cp > 0).
  double T = 2500.0;
  for (int it = 0; it < 50; ++it) {
    const double dT = (m_p * B.h(T) - H) / (m_p * B.cp(T));
    T -= dT;
    if (!(T > 0.0) || !std::isfinite(T)) break;
    if (std::fabs(dT) < 1e-9 * T) return T;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// Stages: frozen flame temperature; the packet's NO per kg of hot-zone gas; its moles.
double HotZoneNO::noMoles(double dm_fuel, double T_u, double y_air, double p, double tau,
                          double T_min, Packet* out) {
  Packet k;
  k.T_frozen_K = frozenFlameTemperature_K(T_u, y_air);
  if (!std::isfinite(k.T_frozen_K)) return -1.0;
  if (k.T_frozen_K < T_min) {
    k.T_K = k.T_frozen_K;
    if (out) *out = k;
    return 0.0;
  }
  const double g = specificNO_mol_kg(k.T_frozen_K, p, tau, &k);
  if (g < 0.0) return -1.0;
  k.products_kg_kg = productsPerFuel(y_air);
  if (out) *out = k;
  return g * k.products_kg_kg * dm_fuel;
}

// Stages: dissociated hot-zone state (stoichiometric products = the BURNED group); Zeldovich
// from [NO] = 0 over τ; NO per kg of the packet's gas.
double HotZoneNO::specificNO_mol_kg(double T_frozen, double p, double tau, Packet* out,
                                    double tol) {
  double Y[kNumSpecies];
  for (int s = 0; s < kNumSpecies; ++s) Y[s] = th_.massFraction(kBurned, Species(s));
  DissociatedFlame::Result r;
  if (!flame_.solve(th_.elements(kBurned), Y, T_frozen, p, r, tol)) {
    flame_.reset();
    if (!flame_.solve(th_.elements(kBurned), Y, T_frozen, p, r, tol)) return -1.0;
  }
  Packet k;
  if (out) k = *out;
  k.T_K = r.T_K;
  k.volume_m3_kg = r.n_mol_kg * kRu * r.T_K / p;
  zeldovich_.setConditions(r.T_K, p, r.x);
  k.no_eq_mol_m3 = zeldovich_.equilibriumNO();
  k.no_mol_m3 = tau > 0.0 ? k.no_eq_mol_m3 * alphaAt(tau) : 0.0;
  if (out) *out = k;
  return k.no_mol_m3 * k.volume_m3_kg;
}

// α = [NO]/[NO]_e after t at the current conditions: one-way equilibrium rates
// R1 = k1f [O][N2], R2 = k2f [N][O2], R3 = k3f [N][OH]; τ_NO = [NO]_e/(2 R1), K = R1/(R2 + R3);
// F(α) = ½ ln((1+α)/(1−α)) − ½ K ln(1−α²) − t/τ_NO = 0, F' = (1 + Kα)/(1 − α²) > 0 on [0, 1):
// Newton from the linear-growth start, kept inside a shrinking bracket (bisection fallback).
double HotZoneNO::alphaAt(double t) const {
  const ZeldovichNO& z = zeldovich_;
  const double R1 = z.k1f() * z.conc(kO) * z.conc(kN2);
  const double R23 = z.k2f() * z.conc(kN) * z.conc(kO2) + z.k3f() * z.conc(kN) * z.conc(kOH);
  const double ceq = z.equilibriumNO();
  if (!(R1 > 0.0 && ceq > 0.0 && R23 > 0.0)) return 0.0;
  const double x = 2.0 * R1 * t / ceq, K = R1 / R23;  // x = t/τ_NO
  if (x > 40.0) return 1.0;                          // 1 − α < 1e-17: equilibrium reached
  double lo = 0.0, hi = 1.0, a = std::min(x, 0.5);
  for (int it = 0; it < 100; ++it) {
    const double F = 0.5 * std::log((1.0 + a) / (1.0 - a)) - 0.5 * K * std::log(1.0 - a * a) - x;
    (F < 0.0 ? lo : hi) = a;
    double an = a - F * (1.0 - a * a) / (1.0 + K * a);
    if (!(an > lo && an < hi)) an = 0.5 * (lo + hi);
    if (std::fabs(an - a) < 1e-14) return an;
    a = an;
  }
  return a;
}

}  // namespace hbt::cylinder
