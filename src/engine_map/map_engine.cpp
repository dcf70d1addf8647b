#include "engine_map/map_engine.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/oil_viscosity.hpp"
#include "common/units.hpp"

namespace hbt::engine_map {
namespace {

std::string resolve(const std::string& base, const std::string& path) {
  if (base.empty() || path.empty() || path[0] == '/') return path;
  return base + (base.back() == '/' ? "" : "/") + path;
}

}  // namespace

void MapEngineParams::declare(ParamSet& ps) {
  ps.add("full_load_file", full_load_file, "VECTO .vfld full-load + motoring curve of the reference engine");
  ps.add("fuel_map_file", fuel_map_file, "VECTO .vmap fuel map of the reference engine");
  ps.add("pt1_file", pt1_file, "VECTO PT1 table (time constant vs engine speed)");
  ps.add("nox_map_file", nox_map_file,
         "engine-out NOx map (EI over speed x load, nox_map.hpp); empty: constant emission index");
  ps.add("target_peak_torque_Nm", target_peak_torque_Nm, "Nm", 100.0, 5000.0, "peak torque after scaling");
  ps.add("target_peak_power_W", target_peak_power_W, "W", 1e4, 1e6, "peak power after scaling");
  ps.add("idle_speed_rad_s", idle_speed_rad_s, "rad/s", 30.0, 150.0,
         "engine idle speed: the start speed of the twin's engine (map and 1D)");
  ps.add("scale_speed_axis", scale_speed_axis, "scale the speed axis so that peak power = target");
  ps.add("pt1_time_constant_factor", pt1_time_constant_factor, "-", 0.0, 10.0, "multiplier on PT1 tau");
  ps.add("torque_decrease_time_constant_s", torque_decrease_time_constant_s, "s", 0.0, 10.0,
         "lag of torque decreases (0 = instantaneous)");
  GasPathParams& g = gas;
  ps.add("displacement_m3", g.displacement_m3, "m^3", 1e-3, 3e-2, "swept volume");
  ps.add("volumetric_efficiency", g.volumetric_efficiency, "-", 0.5, 1.2, "referred to intake-manifold density");
  ps.add("boost_pressure_ratio_max", g.boost_pressure_ratio_max, "-", 1.0, 5.0, "boost PR at rated fuel flow");
  ps.add("boost_fuel_exponent", g.boost_fuel_exponent, "-", 0.1, 3.0, "PR-1 ∝ (fuel/fuel_rated)^exponent");
  ps.add("compressor_efficiency", g.compressor_efficiency, "-", 0.3, 0.9, "isentropic");
  ps.add("intercooler_effectiveness", g.intercooler_effectiveness, "-", 0.0, 1.0, "air-to-air");
  ps.add("coolant_fraction_light_load", g.coolant_fraction_light_load, "-", 0.0, 0.6, "of fuel power at zero load");
  ps.add("coolant_fraction_full_load", g.coolant_fraction_full_load, "-", 0.0, 0.6, "of fuel power at full load");
  ps.add("friction_heat_to_oil_fraction", g.friction_heat_to_oil_fraction, "-", 0.0, 1.0,
         "share of the friction work carried by the oil (bearings, valve train); the rest heats the metal");
  ps.add("misc_heat_fraction", g.misc_heat_fraction, "-", 0.0, 0.3, "oil/radiation, of fuel power");
  ps.add("exhaust_cp_J_kgK", g.exhaust_cp_J_kgK, "J/(kg K)", 900.0, 1400.0, "mean exhaust cp");
  ps.add("air_cp_J_kgK", g.air_cp_J_kgK, "J/(kg K)", 900.0, 1100.0, "air cp");
  ps.add("air_gamma", g.air_gamma, "-", 1.2, 1.45, "air ratio of specific heats");
  ps.add("air_R_J_kgK", g.air_R_J_kgK, "J/(kg K)", 280.0, 295.0, "air gas constant");
  ps.add("fuel_h_to_c_molar", g.fuel_h_to_c_molar, "-", 1.5, 2.2, "H/C molar ratio of the diesel");
  ps.add("friction_share_of_motoring", friction_share_of_motoring, "-", 0.0, 1.0,
         "share of the motoring torque that is mechanical friction (cold-oil correction)");
  ps.add("oil_ref_K", oil_ref_K, "K", 300.0, 420.0, "oil temperature of the warm map");
  ps.add("oil_vogel_b_K", oil_vogel_b_K, "K", 100.0, 5000.0, "Vogel b of the oil viscosity");
  ps.add("oil_vogel_c_K", oil_vogel_c_K, "K", 0.0, 250.0, "Vogel c of the oil viscosity");
  ps.add("oil_viscosity_exponent", oil_viscosity_exponent, "-", 0.0, 1.0, "friction ∝ viscosity^n");
  ps.add("back_pressure_ref_rated_Pa", back_pressure_ref_rated_Pa, "Pa", 0.0, 1e5,
         "over-pressure at the turbine outlet the map was measured with, at rated exhaust flow");
  ps.add("back_pressure_ref_exponent", back_pressure_ref_exponent, "-", 0.5, 3.0,
         "reference back-pressure ∝ exhaust flow^n");
  ps.add("nox_emission_index_kg_per_kg", g.nox_emission_index_kg_per_kg, "kg/kg", 0.0, 0.1,
         "engine-out NOx (as NO2) per kg fuel");
}

MapEngine::MapEngine(const MapEngineParams& p, const std::string& base_dir) : p_(p) {
  const FullLoadCurve ref = readFullLoadCurve(resolve(base_dir, p.full_load_file));
  const FuelMapPoints refmap = readFuelMap(resolve(base_dir, p.fuel_map_file));
  const Table1D refpt1 = readPt1Table(resolve(base_dir, p.pt1_file));
  if (!p.nox_map_file.empty()) nox_map_ = readNoxMap(resolve(base_dir, p.nox_map_file), "nox_map_file");
  scaling_ = computeScaling(ref, p.target_peak_torque_Nm, p.target_peak_power_W, p.scale_speed_axis);
  fld_ = applyScaling(ref, scaling_);
  map_pts_ = applyScaling(refmap, scaling_);
  pt1_ = applySpeedScaling(refpt1, scaling_);
  t_fl_ = Table1D(fld_.speed_rad_s, fld_.full_load_Nm, fld_.source, "full load torque");
  t_mot_ = Table1D(fld_.speed_rad_s, fld_.motoring_Nm, fld_.source, "motoring torque");
  fuel_ = ScatteredLinearMap(map_pts_.speed_rad_s, map_pts_.torque_Nm, map_pts_.fuel_kg_s,
                             map_pts_.source);
  w_min_ = *std::min_element(map_pts_.speed_rad_s.begin(), map_pts_.speed_rad_s.end());
  w_max_ = *std::max_element(map_pts_.speed_rad_s.begin(), map_pts_.speed_rad_s.end());
  // The map must cover the full-load curve's speed range (else the engine would extrapolate
  // over whole regions rather than edge slivers).
  if (fld_.speed_rad_s.front() < w_min_ - 1e-9 || fld_.speed_rad_s.back() > w_max_ + 1e-9)
    throw InputError(map_pts_.source, "engine speed",
                     "fuel map speed range does not cover the full-load curve of " + fld_.source);
  double w_rated = 0.0;
  engine_map::peakPower(fld_, &w_rated);
  fuel_ref_kg_s_ = steadyFuel(w_rated, fullLoadTorque(w_rated));
  exhaust_ref_kg_s_ = computeGasPath(p_.gas, w_rated, fullLoadTorque(w_rated), 1.0, fuel_ref_kg_s_,
                                     fuel_ref_kg_s_, 298.15, units::kStandardAtmosphere_Pa,
                                     warmFriction_W(w_rated), 0.0).exhaust_mass_flow_kg_s;
  if (!(fuel_ref_kg_s_ > 0.0))
    throw InputError(map_pts_.source, "fuel consumption", "no positive fuel flow at rated power");
  const auto checkPositive = [](double v, const char* key) {
    if (!(v > 0.0)) throw InputError("(engine parameters)", key, "must be > 0");
  };
  checkPositive(p.gas.displacement_m3, "displacement_m3");
  reset(w_min_);
}

double MapEngine::fullLoadTorque(double w) const {
  const double wl = fld_.speed_rad_s.front();
  if (w < wl) return w <= 0.0 ? 0.0 : t_fl_(wl) * w / wl;
  return t_fl_(w);
}

double MapEngine::motoringTorque(double w) const {
  const double wl = fld_.speed_rad_s.front();
  if (w < wl) return w <= 0.0 ? 0.0 : t_mot_(wl) * w / wl;
  return t_mot_(w);
}

double MapEngine::warmFriction_W(double w) const {
  return p_.friction_share_of_motoring * std::fabs(motoringTorque(w)) * std::max(w, 0.0);
}

double MapEngine::timeConstant(double w) const {
  return p_.pt1_time_constant_factor * pt1_(std::max(w, 0.0));
}

double MapEngine::noxEmissionIndex(double w, double T) const {
  if (nox_map_.empty()) return p_.gas.nox_emission_index_kg_per_kg;
  const double tfl = fullLoadTorque(w);
  return nox_map_(w, tfl > 0.0 ? T / tfl : 0.0);
}

double MapEngine::steadyFuel(double w, double T) const {
  if (w <= 0.0) return 0.0;
  const double tmot = motoringTorque(w);
  if (T <= tmot) return 0.0;
  const double wc = std::clamp(w, w_min_, w_max_);
  const double s = std::min(1.0, w / w_min_);
  // Torque referred to the clamped speed keeps the same load fraction in the stall region.
  const double Tc = (s < 1.0 && s > 0.0) ? T / s : T;
  return std::max(0.0, fuel_(wc, Tc)) * s;
}

void MapEngine::reset(double w, double T, double ambient_T_K, double ambient_p_Pa) {
  out_ = MapEngineOutputs{};
  torque_ = std::clamp(T, motoringTorque(w), fullLoadTorque(w));
  out_.brake_torque_Nm = torque_;
  out_.max_torque_Nm = fullLoadTorque(w);
  out_.min_torque_Nm = motoringTorque(w);
  out_.dynamic_max_torque_Nm = out_.max_torque_Nm;
  out_.time_constant_s = timeConstant(w);
  out_.fuel_mass_flow_kg_s = steadyFuel(w, torque_);
  out_.fuel_cut = out_.fuel_mass_flow_kg_s <= 0.0;
  const double tfl = out_.max_torque_Nm;
  out_.gas = computeGasPath(p_.gas, w, torque_, tfl > 0.0 ? torque_ / tfl : 0.0,
                            out_.fuel_mass_flow_kg_s, fuel_ref_kg_s_, ambient_T_K, ambient_p_Pa,
                            warmFriction_W(w), 0.0);
  out_.gas.nox_mass_flow_kg_s = noxEmissionIndex(w, torque_) * out_.fuel_mass_flow_kg_s;
}

const MapEngineOutputs& MapEngine::step(double dt, const MapEngineInputs& in) {
  if (!std::isfinite(in.speed_rad_s) || !std::isfinite(in.torque_request_Nm) ||
      !std::isfinite(in.ambient_T_K) || !std::isfinite(in.ambient_p_Pa) || !(dt > 0.0))
    throw ModelDivergence("map engine", "inputs", "non-finite input or dt <= 0");
  const double w = std::max(in.speed_rad_s, 0.0);
  const double phi = in.oil_T_K > 0.0 ? oilViscosityFactor(in.oil_T_K, p_.oil_ref_K, p_.oil_vogel_b_K,
                                                           p_.oil_vogel_c_K, p_.oil_viscosity_exponent)
                                       : 1.0;
  const double T_fric_warm = p_.friction_share_of_motoring * std::fabs(motoringTorque(w));
  const double dT_fric = T_fric_warm * (phi - 1.0);
  double dT_pump = 0.0;
  if (in.back_pressure_Pa > 0.0 && exhaust_ref_kg_s_ > 0.0) {
    const double x = std::max(out_.gas.exhaust_mass_flow_kg_s, 0.0) / exhaust_ref_kg_s_;
    const double p_ref = in.ambient_p_Pa + p_.back_pressure_ref_rated_Pa * std::pow(x, p_.back_pressure_ref_exponent);
    const double pi_T = std::max(1.0, out_.gas.pressure_ratio);
    dT_pump = (in.back_pressure_Pa - p_ref) * pi_T * p_.gas.displacement_m3 / (4.0 * units::kPi);
  }
  const double dT = dT_fric + dT_pump;
  const double tfl = fullLoadTorque(w) - dT, tmot = motoringTorque(w) - dT;
  const double tau = timeConstant(w);
  const double prev = torque_;
  double upper = tfl;
  if (tau > 0.0 && prev < tfl) upper = prev + (tfl - prev) * (1.0 - std::exp(-dt / tau));
  upper = std::clamp(upper, tmot, tfl);
  double lower = tmot;
  const double tdec = p_.torque_decrease_time_constant_s;
  if (tdec > 0.0 && prev > tmot) lower = prev - (prev - tmot) * (1.0 - std::exp(-dt / tdec));
  lower = std::clamp(lower, tmot, upper);

  const bool cut = !in.fuel_enabled || in.torque_request_Nm <= tmot;
  const double req = cut ? tmot : in.torque_request_Nm;
  torque_ = std::clamp(req, lower, upper);
  const double mf = (cut || torque_ <= tmot) ? 0.0 : steadyFuel(w, torque_ + dT);

  out_.brake_torque_Nm = torque_;
  out_.fuel_mass_flow_kg_s = mf;
  out_.max_torque_Nm = tfl;
  out_.min_torque_Nm = tmot;
  out_.dynamic_max_torque_Nm = upper;
  out_.time_constant_s = tau;
  out_.friction_correction_Nm = dT_fric;
  out_.pumping_correction_Nm = dT_pump;
  out_.fuel_cut = mf <= 0.0;
  out_.gas = computeGasPath(p_.gas, w, torque_, tfl > 0.0 ? torque_ / tfl : 0.0, mf, fuel_ref_kg_s_,
                            in.ambient_T_K, in.ambient_p_Pa, (T_fric_warm + dT_fric) * w, dT_fric * w);
  out_.gas.nox_mass_flow_kg_s = noxEmissionIndex(w, torque_) * mf;
  const double pb = torque_ * w;
  out_.fuel_mass_kg += mf * dt;
  out_.fuel_energy_J += out_.gas.fuel_power_W * dt;
  out_.brake_work_J += pb * dt;
  out_.positive_work_J += std::max(pb, 0.0) * dt;
  out_.motoring_work_J += std::min(pb, 0.0) * dt;
  out_.coolant_heat_J += out_.gas.coolant_heat_W * dt;
  out_.metal_heat_J += out_.gas.metal_heat_W * dt;
  out_.oil_heat_J += out_.gas.oil_heat_W * dt;
  out_.friction_work_J += out_.gas.friction_W * dt;
  out_.nox_mass_kg += out_.gas.nox_mass_flow_kg_s * dt;
  return out_;
}

}  // namespace hbt::engine_map
