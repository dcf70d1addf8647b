// Tabulated hot-zone NO (hot_zone_no.hpp) for the cylinder's batches.
//
// The NO a packet forms per kg of its gas, g = [NO](τ) v_p [mol/kg], depends on the frozen flame
// temperature T_f [K] and the pressure p [Pa] only (at the cylinder's fixed residence time τ
// [s]): the hot zone is always the stoichiometric products (the BURNED group of thermo.hpp), so
// its dissociated temperature, equilibrium and Zeldovich rates are functions of (T_f, p). Each
// exact evaluation costs two to four 12-species equilibrium solves (flame_temperature.hpp); the
// table replaces them by a look-up:
//   nodes uniform in u = 1000 K / T_f (step du) and in ln p (step dlp), node values ln g;
//   ln g(T_f, p) bilinear in (u, ln p), g = exp(ln g).
// ln g is nearly linear in 1/T (the Zeldovich rate ∝ exp(−38 370 K / T), the equilibrium NO
// ∝ exp(−10 800 K / T)) and smooth in ln p, so the bilinear error is second order in (du, dlp)
// with a small constant (test_hot_zone_no_table: ≤ 3e-4 relative over 1700–3300 K, 5–250 bar at
// the shipped steps, ≈ 4× smaller at half the steps; the u step dominates).
// Nodes are computed on first use, each from a cold equilibrium start, so a node's value does not
// depend on which packets came before (deterministic). Storage is allocated at construction
// (nothing is allocated in a step). Outside the grid, or next to a node where g is not positive
// (τ = 0, a failed equilibrium), the exact HotZoneNO value is returned.
#pragma once
#include <vector>

#include "cylinder/hot_zone_no.hpp"

namespace hbt::cylinder {

class HotZoneNOTable {
 public:
  /// Grid steps: du [1/kK] in u = 1000 K / T_f, dlp [-] in ln(p/Pa).
  static constexpr double kStepU = 0.001;   // 6.3 K at 2500 K, 9 K at 3000 K
  static constexpr double kStepLnP = 0.05;  // 5 % in pressure
  /// Grid range: T_f in [kMinT_K, kMaxT_K], p in [kMinP_Pa, kMaxP_Pa].
  static constexpr double kMinT_K = 1500.0, kMaxT_K = 3500.0;
  static constexpr double kMinP_Pa = 1e5, kMaxP_Pa = 5e7;

  /// thermo: the cylinder's gas (referenced); tau_s: the hot-zone residence time [s].
  HotZoneNOTable(const GasThermo& thermo, double tau_s, double step_u = kStepU,
                 double step_lnp = kStepLnP);
  HotZoneNOTable(const HotZoneNOTable&) = delete;
  HotZoneNOTable& operator=(const HotZoneNOTable&) = delete;

  /// g(T_f, p) [mol NO per kg of hot-zone gas], interpolated; negative if the exact value is
  /// needed and fails.
  double specificNO_mol_kg(double T_frozen_K, double p_Pa);
  /// The exact value (cold start), as the nodes are computed: dissociated temperature to
  /// kNodeToleranceK (the per-packet model's 0.05 K moves g by up to ~3e-4: d ln g/dT ≈
  /// 38 370 K/T² = 6e-3 /K at 2500 K).
  static constexpr double kNodeToleranceK = 1e-4;
  double exactSpecificNO_mol_kg(double T_frozen_K, double p_Pa);
  /// NO [mol] of dm_fuel_kg burning at T_u_K, p_Pa with unburned gas of air mass fraction
  /// y_air (HotZoneNO::noMoles with the interpolated g); packets with T_f < T_min_K form none.
  /// Negative if the flame temperature or the equilibrium fails.
  double noMoles(double dm_fuel_kg, double T_u_K, double y_air, double p_Pa, double T_min_K);
  const HotZoneNO& exact() const { return hz_; }
  double residenceTime_s() const { return tau_; }
  int nodesComputed() const { return computed_; }

 private:
  double node(int i, int j);  // ln g at u_i, ln p_j (computed on first use; -inf: g <= 0)

  HotZoneNO hz_;
  double tau_, du_, dlp_, u0_, lp0_;
  int nu_, np_, computed_ = 0;
  std::vector<double> ln_g_;  // nu_ x np_, NaN until computed
};

}  // namespace hbt::cylinder
