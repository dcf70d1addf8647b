// Air-to-air charge-air cooler (intercooler), effectiveness model.
//
//   T_out = T_in − ε(ṁ) (T_in − T_cool),   T_cool = T_ambient + ΔT_cool   [K]
//     ε(ṁ): piecewise-linear table over charge mass flow [kg/s] (clamped at the ends), or a
//     constant (one-point table); 0 ≤ ε ≤ 1. ΔT_cool: heating of the cooling air ahead of the
//     core (e.g. by an upstream radiator or recirculation), 0 by default.
//   Δp = K ṁ² T_in/p_in,  K = Δp_ref p_ref/(ṁ_ref² T_ref)   [Pa]
//     (Δp = ζ ṁ²/(2 ρ A²) with ρ = p/(R T): ∝ ṁ² T/p at constant loss coefficient ζ).
// Ambient temperature enters here and through the compressor inlet: hotter ambient → hotter
// charge → lower density → less trapped air.
#pragma once
#include <string>
#include <vector>

#include "common/table1d.hpp"

namespace hbt::turbo {

struct IntercoolerParams {
  std::vector<double> effectiveness_flow_kg_s{0.05, 0.15, 0.30, 0.40};
  std::vector<double> effectiveness{0.93, 0.90, 0.86, 0.83};
  double cooling_air_offset_K = 0.0;
  double dp_ref_Pa = 10000.0;       // pressure drop at the reference point
  double dp_ref_flow_kg_s = 0.30;
  double dp_ref_temperature_K = 440.0;
  double dp_ref_pressure_Pa = 260000.0;
};

class Intercooler {
 public:
  Intercooler() = default;
  /// `source` (file) and key_prefix + key name errors (keys as in the YAML).
  Intercooler(const IntercoolerParams& p, const std::string& source = "(intercooler)",
              const std::string& key_prefix = "intercooler/");

  double effectiveness(double m_dot_kg_s) const;
  double outletTemperature(double T_in_K, double T_ambient_K, double m_dot_kg_s) const;
  double pressureDrop(double m_dot_kg_s, double T_in_K, double p_in_Pa) const;
  /// Inverse of pressureDrop: ṁ ≥ 0 for a drop Δp [Pa] (0 if Δp ≤ 0).
  double massFlowForDrop(double dp_Pa, double T_in_K, double p_in_Pa) const;
  double dropCoefficient() const { return K_; }  // K [Pa·Pa·s²/(kg²·K)]

 private:
  IntercoolerParams p_;
  Table1D eps_;
  double K_ = 0.0;
};

}  // namespace hbt::turbo
