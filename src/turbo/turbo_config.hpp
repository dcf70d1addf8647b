// Turbocharger configuration (parameters from config/engine_1d_turbo.yaml), scaling of the
// measured maps to this engine, and construction of the models.
//
// Scaling rule (geometric similarity of the whole turbocharger, see README):
//   rated fuel flow   ṁ_f = P_rated · BSFC                               [kg/s]
//   rated air flow    ṁ_a = ṁ_f · λ · AFR_st                             [kg/s]
//   corrected         ṁ_a,c = ṁ_a √(T_1/T_ref)/(p_1/p_ref)               [kg/s]
//   flow factor       f = ṁ_a,c / ṁ_ridge(Π_rated)   (ṁ_ridge: corrected flow on the map's
//                     maximum-efficiency ridge at the design pressure ratio Π_rated)
//   compressor:       ṁ_c × f,  N_c × 1/√f,  Π and η unchanged     (flow ∝ D², N ∝ 1/D)
//   turbine:          Φ × f_t (default f_t = f),  N_r × 1/√f        (same rotor, same D ratio)
//   rotor inertia:    J ∝ D⁵ = f^(5/2) (only reported; the YAML value is used as given)
// Paths: map files are `<base_dir>/<data_dir>/<map_file>` (data_dir relative to the repo root
// by default: ../shared/data/turbo), unless given as absolute paths.
#pragma once
#include <string>

#include "common/params.hpp"
#include "turbo/compressor.hpp"
#include "turbo/intercooler.hpp"
#include "turbo/shaft.hpp"
#include "turbo/turbine.hpp"

namespace hbt::turbo {

struct ScalingParams {
  double rated_power_W = 210000.0;
  double bsfc_g_kWh = 210.0;
  double lambda = 1.6;
  double afr_stoich = 14.5;
  double rated_pressure_ratio = 2.45;     // design Π on the compressor efficiency ridge
  double inlet_pressure_Pa = 98000.0;     // compressor inlet total p at rated (after air filter)
  double inlet_temperature_K = 298.0;     // compressor inlet total T at rated
  double flow_scale_override = 0.0;       // > 0: use instead of the computed factor
  double turbine_flow_scale_override = 0.0;  // > 0: turbine Φ factor (default = compressor's)
};

struct ScalingResult {
  double fuel_kg_s = 0.0, air_kg_s = 0.0, exhaust_kg_s = 0.0;
  double corrected_air_kg_s = 0.0;   // at the rated compressor inlet state
  double ridge_flow_kg_s = 0.0;      // unscaled map, at rated_pressure_ratio
  double flow_factor = 1.0;          // f
  double speed_factor = 1.0;         // 1/√f
  double diameter_factor = 1.0;      // √f
  double inertia_factor = 1.0;       // f^(5/2)
  double turbine_flow_factor = 1.0;  // f_t
};

struct TurboConfig {
  std::string source = "(turbo parameters)";  // file the parameters came from (errors)
  std::string key_prefix;                     // prefix used in declare()
  std::string data_dir = "../shared/data/turbo";
  std::string compressor_map_file =
      "scania_di09_enginetoolbox/compressor_map_SAE_lowflow_extrapolated.csv";
  CompressorMapFormat compressor_format;
  CompressorMapOptions compressor_options;
  double compressor_ref_pressure_Pa = 100000.0;
  double compressor_ref_temperature_K = 298.0;
  double air_gas_constant = 287.0;
  std::string turbine_map_file = "scania_di09_enginetoolbox/turbine_map_SAE.csv";
  TurbineMapFormat turbine_format;
  double exhaust_gamma = 1.33;
  double exhaust_gas_constant = 287.0;
  double wastegate_cd = 0.8;
  double wastegate_max_area_m2 = 3.0e-4;
  ScalingParams scaling;
  ShaftParams shaft;
  IntercoolerParams intercooler;

  /// Declares every parameter (keys under `prefix`, e.g. "turbo/").
  void declare(ParamSet& ps, const std::string& prefix = "");
  std::string resolve(const std::string& base_dir, const std::string& file) const;
};

/// Rated flows and the similarity factors for `unscaled` (throws InputError naming cfg.source).
ScalingResult computeScaling(const CompressorMap& unscaled, const TurboConfig& cfg);

struct Turbocharger {
  Compressor compressor;
  TwinEntryTurbine turbine;
  TurboShaft shaft;
  Intercooler intercooler;
  ScalingResult scaling;
};

/// Reads and scales both maps and builds all models. base_dir: repository root.
Turbocharger buildTurbocharger(const TurboConfig& cfg, const std::string& base_dir);

}  // namespace hbt::turbo
