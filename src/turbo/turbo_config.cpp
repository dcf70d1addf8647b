#include "turbo/turbo_config.hpp"

#include <cmath>
#include <sstream>

#include "common/errors.hpp"
#include "common/table1d.hpp"

namespace hbt::turbo {

void TurboConfig::declare(ParamSet& ps, const std::string& prefix) {
  key_prefix = prefix;
  ps.setPrefix(prefix);
  ps.add("data_dir", data_dir, "directory of the map files, relative to the repository root");
  ps.add("compressor/map_file", compressor_map_file, "compressor map CSV (relative to data_dir)");
  ps.add("compressor/col_speed", compressor_format.col_speed, "column: corrected speed [rpm]");
  ps.add("compressor/col_flow", compressor_format.col_flow, "column: corrected flow [kg/s]");
  ps.add("compressor/col_pressure_ratio", compressor_format.col_pr, "column: Π total-total");
  ps.add("compressor/col_efficiency", compressor_format.col_eff, "column: isentropic η");
  ps.add("compressor/ref_pressure_Pa", compressor_ref_pressure_Pa, "Pa", 5e4, 1.2e5,
         "map reference pressure");
  ps.add("compressor/ref_temperature_K", compressor_ref_temperature_K, "K", 250, 330,
         "map reference temperature");
  ps.add("compressor/gamma", compressor_options.gamma, "-", 1.3, 1.42, "air γ");
  ps.add("compressor/gas_constant_J_kgK", air_gas_constant, "J/(kg K)", 280, 295, "air R");
  ps.add("compressor/eta_floor", compressor_options.eta_floor, "-", 0.05, 0.6,
         "lower bound of the compressor efficiency");
  ps.add("compressor/shutoff_head_ratio", compressor_options.shutoff_head_ratio, "-", 1.0001,
         2.0, "isentropic head at zero flow / head at the surge point");
  ps.add("compressor/throttle_flow_fraction", compressor_options.throttle_flow_fraction, "-",
         0.01, 2.0, "stationary wheel: corrected flow at critical pressure drop / max map flow");
  ps.add("turbine/map_file", turbine_map_file, "turbine map CSV (relative to data_dir)");
  ps.add("turbine/col_speed", turbine_format.col_speed, "column: reduced speed [rpm/sqrt(K)]");
  ps.add("turbine/col_flow_parameter", turbine_format.col_mfp,
         "column: reduced flow parameter [kg sqrt(K)/(s kPa)]");
  ps.add("turbine/col_expansion_ratio", turbine_format.col_er, "column: ER total-static");
  ps.add("turbine/col_efficiency", turbine_format.col_eff, "column: η total-static");
  ps.add("turbine/gamma", exhaust_gamma, "-", 1.25, 1.4, "exhaust gas γ");
  ps.add("turbine/gas_constant_J_kgK", exhaust_gas_constant, "J/(kg K)", 280, 295, "exhaust R");
  ps.add("wastegate/discharge_coefficient", wastegate_cd, "-", 0.1, 1.0, "orifice C_d");
  ps.add("wastegate/max_area_m2", wastegate_max_area_m2, "m^2", 0.0, 2e-3,
         "flow area when fully open (entry 1 only)");
  ps.add("scaling/rated_power_W", scaling.rated_power_W, "W", 5e4, 5e5, "engine rated power");
  ps.add("scaling/bsfc_g_kWh", scaling.bsfc_g_kWh, "g/kWh", 150, 300, "BSFC at rated power");
  ps.add("scaling/lambda", scaling.lambda, "-", 1.1, 3.0, "air-fuel equivalence at rated power");
  ps.add("scaling/afr_stoich", scaling.afr_stoich, "-", 14.0, 15.0, "stoichiometric AFR");
  ps.add("scaling/rated_pressure_ratio", scaling.rated_pressure_ratio, "-", 1.5, 4.5,
         "design Π placed on the compressor efficiency ridge");
  ps.add("scaling/inlet_pressure_Pa", scaling.inlet_pressure_Pa, "Pa", 7e4, 1.1e5,
         "compressor inlet total pressure at rated power");
  ps.add("scaling/inlet_temperature_K", scaling.inlet_temperature_K, "K", 230, 330,
         "compressor inlet total temperature at rated power");
  ps.add("scaling/flow_scale_override", scaling.flow_scale_override, "-", 0.0, 10.0,
         "> 0: flow factor used instead of the computed one");
  ps.add("scaling/turbine_flow_scale_override", scaling.turbine_flow_scale_override, "-", 0.0,
         10.0, "> 0: turbine flow factor (default: the compressor's)");
  ps.add("shaft/inertia_kg_m2", shaft.inertia_kg_m2, "kg m^2", 1e-6, 1e-2, "rotor inertia J");
  ps.add("shaft/eta_mech", shaft.eta_mech, "-", 0.5, 1.0, "mechanical efficiency on P_t");
  ps.add("shaft/friction_ref_power_W", shaft.friction_ref_power_W, "W", 0.0, 1e4,
         "bearing drag at friction_ref_speed");
  ps.add("shaft/friction_ref_speed_rad_s", shaft.friction_ref_speed_rad_s, "rad/s", 100, 3e4,
         "speed of friction_ref_power");
  ps.add("shaft/omega_min_rad_s", shaft.omega_min_rad_s, "rad/s", 1.0, 2000.0,
         "floor of ω in the 1/ω term of dω/dt");
  ps.add("intercooler/effectiveness_flow_kg_s", intercooler.effectiveness_flow_kg_s, "kg/s", 0.0,
         5.0, "charge flow breakpoints of the effectiveness table");
  ps.add("intercooler/effectiveness", intercooler.effectiveness, "-", 0.0, 1.0,
         "effectiveness ε at the breakpoints (one value = constant)");
  ps.add("intercooler/cooling_air_offset_K", intercooler.cooling_air_offset_K, "K", -20.0, 50.0,
         "cooling-air temperature above ambient");
  ps.add("intercooler/dp_ref_Pa", intercooler.dp_ref_Pa, "Pa", 0.0, 1e5, "reference drop");
  ps.add("intercooler/dp_ref_flow_kg_s", intercooler.dp_ref_flow_kg_s, "kg/s", 1e-3, 5.0,
         "flow at the reference drop");
  ps.add("intercooler/dp_ref_temperature_K", intercooler.dp_ref_temperature_K, "K", 200, 700,
         "inlet T at the reference drop");
  ps.add("intercooler/dp_ref_pressure_Pa", intercooler.dp_ref_pressure_Pa, "Pa", 5e4, 6e5,
         "inlet p at the reference drop");
  ps.setPrefix("");
}

std::string TurboConfig::resolve(const std::string& base_dir, const std::string& file) const {
  if (!file.empty() && file[0] == '/') return file;
  std::string dir = data_dir;
  if (dir.empty() || dir[0] != '/') dir = (base_dir.empty() ? "." : base_dir) + "/" + dir;
  return dir + "/" + file;
}

ScalingResult computeScaling(const CompressorMap& unscaled, const TurboConfig& cfg) {
  const ScalingParams& s = cfg.scaling;
  ScalingResult r;
  r.fuel_kg_s = s.rated_power_W * s.bsfc_g_kWh * 1e-3 / 3.6e6;
  r.air_kg_s = r.fuel_kg_s * s.lambda * s.afr_stoich;
  r.exhaust_kg_s = r.air_kg_s + r.fuel_kg_s;
  r.corrected_air_kg_s = r.air_kg_s * std::sqrt(s.inlet_temperature_K /
                                                cfg.compressor_ref_temperature_K) /
                         (s.inlet_pressure_Pa / cfg.compressor_ref_pressure_Pa);
  std::vector<double> pr, flow;
  unscaled.ridge(pr, flow);
  for (std::size_t i = 1; i < pr.size(); ++i)
    if (!(pr[i] > pr[i - 1]))
      throw InputError(unscaled.source(), cfg.compressor_format.col_eff,
                       "maximum-efficiency ridge: pressure ratio must rise with speed");
  if (s.rated_pressure_ratio < pr.front() || s.rated_pressure_ratio > pr.back()) {
    std::ostringstream os;
    os << "outside the map's efficiency ridge [" << pr.front() << ", " << pr.back() << "]";
    throw InputError(cfg.source, cfg.key_prefix + "scaling/rated_pressure_ratio", os.str());
  }
  r.ridge_flow_kg_s = Table1D(pr, flow, unscaled.source(), "ridge")(s.rated_pressure_ratio);
  r.flow_factor = s.flow_scale_override > 0.0 ? s.flow_scale_override
                                              : r.corrected_air_kg_s / r.ridge_flow_kg_s;
  r.diameter_factor = std::sqrt(r.flow_factor);
  r.speed_factor = 1.0 / r.diameter_factor;
  r.inertia_factor = std::pow(r.flow_factor, 2.5);
  r.turbine_flow_factor =
      s.turbine_flow_scale_override > 0.0 ? s.turbine_flow_scale_override : r.flow_factor;
  return r;
}

Turbocharger buildTurbocharger(const TurboConfig& cfg, const std::string& base_dir) {
  Turbocharger t;
  CompressorMap cm = CompressorMap::read(cfg.resolve(base_dir, cfg.compressor_map_file),
                                         cfg.compressor_format, cfg.compressor_options);
  t.scaling = computeScaling(cm, cfg);
  cm.scale(t.scaling.flow_factor);
  PerfectGas air{cfg.compressor_options.gamma, cfg.air_gas_constant};
  t.compressor = Compressor(std::move(cm), cfg.compressor_ref_pressure_Pa,
                            cfg.compressor_ref_temperature_K, air);
  const PerfectGas exh{cfg.exhaust_gamma, cfg.exhaust_gas_constant};
  TurbineMap tm = TurbineMap::read(cfg.resolve(base_dir, cfg.turbine_map_file),
                                   cfg.turbine_format, exh);
  tm.scale(t.scaling.turbine_flow_factor, t.scaling.speed_factor);
  t.turbine = TwinEntryTurbine(tm, Wastegate(cfg.wastegate_cd, cfg.wastegate_max_area_m2, exh));
  t.shaft = TurboShaft(cfg.shaft);
  t.intercooler = Intercooler(cfg.intercooler, cfg.source, cfg.key_prefix + "intercooler/");
  return t;
}

}  // namespace hbt::turbo
