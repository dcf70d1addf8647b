// Twin-entry fixed-geometry radial turbine with a wastegate on entry 1 only.
//
// One entry (inputs: inlet total p_3 [Pa], T_3 [K], outlet static p_4 [Pa], shaft speed ω [rad/s]):
//   N_r = (60 ω/2π)/√T_3 [rpm/√K],  ER = p_3/p_4,  (Φ, η) = map(N_r, ER)  (turbine_map.hpp)
//   ṁ   = s · Φ · (p_3/1000) / √T_3                [kg/s],   s = admission share (0.5)
//   P   = ṁ c_p T_3 (1 − ER^(−k)) η                [W]
//   T_4 = T_3 (1 − η (1 − ER^(−k)))                [K]   (total, leaving the wheel)
// Twin entry (equal-admission assumption): each entry is half of the full turbine (s = 0.5),
// sees its own inlet state and the common outlet pressure, and uses the full map at its own
// ER and N_r; the rotor power is the sum of the entries' powers. Partial-admission losses and
// cross-flow between entries are neglected (see README).
// Wastegate (entry 1, bypasses the wheel): isentropic orifice
//   ṁ_wg = C_d · a · A_max · p_3/√(R T_3) · ψ(p_4/p_3),  a = opening ∈ [0,1] from the controller.
// All calls: no allocation, no NaN, flows ≥ 0.
#pragma once
#include "common/perfect_gas.hpp"
#include "turbo/turbine_map.hpp"

namespace hbt::turbo {

struct TurbineState {
  double mass_flow_kg_s = 0.0;
  double reduced_speed = 0.0;       // [rpm/√K]
  double expansion_ratio = 1.0;     // [-]
  double mfp = 0.0;                 // per full turbine [kg·√K/(s·kPa)]
  double eta = 0.0;                 // [-]
  double outlet_total_temperature_K = 0.0;
  double power_W = 0.0;
  double torque_Nm = 0.0;
  int region = 0;                   // TurbineMap::Region bits
};

class TurbineEntry {
 public:
  TurbineEntry() = default;
  /// `map` already scaled to the whole turbine; share = fraction of its flow capacity.
  TurbineEntry(TurbineMap map, double share) : map_(std::move(map)), share_(share) {}
  TurbineState evaluate(double p_in_Pa, double T_in_K, double p_out_Pa, double speed_rad_s) const;
  double massFlow(double p_in_Pa, double T_in_K, double p_out_Pa, double speed_rad_s) const {
    return evaluate(p_in_Pa, T_in_K, p_out_Pa, speed_rad_s).mass_flow_kg_s;
  }
  /// Total-to-static efficiency [-]; T_4 = T_3 (1 − η (1 − ER^(−k))) everywhere.
  double efficiency(double p_in_Pa, double T_in_K, double p_out_Pa, double speed_rad_s) const {
    return evaluate(p_in_Pa, T_in_K, p_out_Pa, speed_rad_s).eta;
  }
  const TurbineMap& map() const { return map_; }
  double share() const { return share_; }

 private:
  TurbineMap map_;
  double share_ = 1.0;
};

class Wastegate {
 public:
  Wastegate() = default;
  /// cd [-], max_area [m²], gas: exhaust.
  Wastegate(double cd, double max_area_m2, PerfectGas gas)
      : cd_(cd), a_max_(max_area_m2), gas_(gas) {}
  /// opening ∈ [0,1] (clamped); area = opening × A_max [m²].
  double massFlow(double p_in_Pa, double T_in_K, double p_out_Pa, double opening) const;
  double area(double opening) const;
  double maxArea() const { return a_max_; }

 private:
  double cd_ = 0.8, a_max_ = 0.0;
  PerfectGas gas_;
};

struct TwinEntryState {
  TurbineState entry[2];
  double wastegate_flow_kg_s = 0.0;  // bypass of entry 1 (ṁ_wg)
  double power_W = 0.0;              // wheel power, both entries
  double torque_Nm = 0.0;
  double total_flow_kg_s = 0.0;      // entries + wastegate
  double outlet_mixed_temperature_K = 0.0;  // adiabatic mix of both entries and the bypass
};

class TwinEntryTurbine {
 public:
  TwinEntryTurbine() = default;
  /// Builds both entries (share 0.5 each) from the full-turbine map.
  TwinEntryTurbine(const TurbineMap& full_map, Wastegate wastegate)
      : e_{TurbineEntry(full_map, 0.5), TurbineEntry(full_map, 0.5)}, wg_(wastegate) {}
  /// Entry 0 (with wastegate) and entry 1: the exhaust banks of config/engine_1d.yaml exhaust_bank (1 and 2; the shipped six: cylinders 1–3 and 4–6).
  const TurbineEntry& entry(int i) const { return e_[i == 0 ? 0 : 1]; }
  const Wastegate& wastegate() const { return wg_; }
  TwinEntryState evaluate(double p_in1_Pa, double T_in1_K, double p_in2_Pa, double T_in2_K,
                          double p_out_Pa, double speed_rad_s, double wg_opening) const;

 private:
  TurbineEntry e_[2];
  Wastegate wg_;
};

}  // namespace hbt::turbo
