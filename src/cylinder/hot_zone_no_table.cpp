#include "cylinder/hot_zone_no_table.hpp"

#include <cmath>
#include <limits>

namespace hbt::cylinder {

HotZoneNOTable::HotZoneNOTable(const GasThermo& thermo, double tau_s, double step_u,
                               double step_lnp)
    : hz_(thermo), tau_(tau_s), du_(step_u), dlp_(step_lnp) {
  u0_ = 1e3 / kMaxT_K;
  lp0_ = std::log(kMinP_Pa);
  nu_ = static_cast<int>(std::ceil((1e3 / kMinT_K - u0_) / du_)) + 1;
  np_ = static_cast<int>(std::ceil((std::log(kMaxP_Pa) - lp0_) / dlp_)) + 1;
  ln_g_.assign(static_cast<std::size_t>(nu_) * np_, std::numeric_limits<double>::quiet_NaN());
}

double HotZoneNOTable::exactSpecificNO_mol_kg(double T_f, double p) {
  hz_.coldStart();
  return hz_.specificNO_mol_kg(T_f, p, tau_, nullptr, kNodeToleranceK);
}

double HotZoneNOTable::node(int i, int j) {
  double& v = ln_g_[static_cast<std::size_t>(i) * np_ + j];
  if (std::isnan(v)) {
    const double g = exactSpecificNO_mol_kg(1e3 / (u0_ + i * du_), std::exp(lp0_ + j * dlp_));
    v = g > 0.0 ? std::log(g) : -std::numeric_limits<double>::infinity();
    ++computed_;
  }
  return v;
}

double HotZoneNOTable::specificNO_mol_kg(double T_f, double p) {
  const double x = (1e3 / T_f - u0_) / du_, y = (std::log(p) - lp0_) / dlp_;
  if (!(x >= 0.0 && x < nu_ - 1 && y >= 0.0 && y < np_ - 1)) return exactSpecificNO_mol_kg(T_f, p);
  const int i = static_cast<int>(x), j = static_cast<int>(y);
  const double fx = x - i, fy = y - j;
  const double h00 = node(i, j), h01 = node(i, j + 1), h10 = node(i + 1, j),
               h11 = node(i + 1, j + 1);
  if (!std::isfinite(h00 + h01 + h10 + h11)) return exactSpecificNO_mol_kg(T_f, p);
  return std::exp((1.0 - fx) * ((1.0 - fy) * h00 + fy * h01) + fx * ((1.0 - fy) * h10 + fy * h11));
}

double HotZoneNOTable::noMoles(double dm_fuel, double T_u, double y_air, double p, double T_min) {
  const double T_f = hz_.frozenFlameTemperature_K(T_u, y_air);
  if (!std::isfinite(T_f)) return -1.0;
  if (T_f < T_min) return 0.0;
  const double g = specificNO_mol_kg(T_f, p);
  if (g < 0.0) return -1.0;
  return g * hz_.productsPerFuel(y_air) * dm_fuel;
}

}  // namespace hbt::cylinder
