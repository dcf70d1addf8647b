// Centrifugal compressor on physical states (wraps a scaled CompressorMap).
//
// Inputs: inlet total pressure p_1 [Pa], inlet total temperature T_1 [K], outlet pressure p_2 [Pa]
// (total, or static at the boundary — the map is total-to-total), shaft speed ω [rad/s].
//   N_c = (60 ω/2π) √(T_ref/T_1)               corrected speed [rpm]
//   Π   = p_2/p_1                             [-]
//   (ṁ_c, η, w) = map(N_c, Π)                  see compressor_map.hpp
//   ṁ   = ṁ_c (p_1/p_ref) / √(T_1/T_ref)       [kg/s]   (≥ 0; no reverse flow)
//   T_2 = T_1 (1 + w) = T_1 (1 + (Π^k − 1)/η)  inside the map [K]
//   P   = ṁ c_p (T_2 − T_1)                    absorbed power [W]
//   τ   = P/ω                                  absorbed torque [N·m] (0 for ω < 1 rad/s)
// Cheap: one map look-up, no allocation; safe to call every gas-dynamic time step.
#pragma once
#include "common/perfect_gas.hpp"
#include "turbo/compressor_map.hpp"

namespace hbt::turbo {

struct CompressorState {
  double mass_flow_kg_s = 0.0;
  double corrected_flow_kg_s = 0.0;
  double corrected_speed_rpm = 0.0;
  double pressure_ratio = 1.0;
  double eta = 0.0;
  double outlet_total_temperature_K = 0.0;
  double power_W = 0.0;
  double torque_Nm = 0.0;
  int region = 0;  // CompressorMap::Region bits
};

class Compressor {
 public:
  Compressor() = default;
  /// `map` must already be scaled; p_ref [Pa], T_ref [K]: map reference state; gas: air.
  Compressor(CompressorMap map, double p_ref_Pa, double T_ref_K, PerfectGas gas = {});

  CompressorState evaluate(double p_in_Pa, double T_in_K, double p_out_Pa,
                           double speed_rad_s) const;
  /// Gas-dynamic boundary callbacks.
  double massFlow(double p_in_Pa, double T_in_K, double p_out_Pa, double speed_rad_s) const {
    return evaluate(p_in_Pa, T_in_K, p_out_Pa, speed_rad_s).mass_flow_kg_s;
  }
  double outletTotalTemperature(double p_in_Pa, double T_in_K, double p_out_Pa,
                                double speed_rad_s) const {
    return evaluate(p_in_Pa, T_in_K, p_out_Pa, speed_rad_s).outlet_total_temperature_K;
  }
  /// Isentropic efficiency [-]. Outside the map (Π ≤ 1 on the choke side) the isentropic form
  /// T_1(1 + (Π^k − 1)/η) is not the energy balance: use outletTotalTemperature() there.
  double efficiency(double p_in_Pa, double T_in_K, double p_out_Pa, double speed_rad_s) const {
    return evaluate(p_in_Pa, T_in_K, p_out_Pa, speed_rad_s).eta;
  }

  const CompressorMap& map() const { return map_; }
  const PerfectGas& gas() const { return gas_; }
  double pRef() const { return p_ref_; }
  double tRef() const { return t_ref_; }

 private:
  CompressorMap map_;
  double p_ref_ = 100000.0, t_ref_ = 298.0;
  PerfectGas gas_;
};

}  // namespace hbt::turbo
