// Map-based diesel engine (SPEC §3): VECTO full-load/motoring curve and scattered fuel map of a
// reference engine, scaled to 210 kW / 1,100 Nm (see engine_scaling.hpp), with torque build-up
// dynamics, overrun fuel cut and a quasi-steady gas path for the aftertreatment port.
//
// Speed ω [rad/s] is imposed (by the vehicle/driveline). Per step of length Δt [s], with the
// brake torque T_{k-1} of the previous step, static limits T_fl(ω) (full load) and T_mot(ω)
// (motoring, < 0) and the VECTO PT1 time constant τ(ω) [s] (declaration_2015/PT1.csv, speed
// axis scaled by f_n, times pt1_time_constant_factor):
//
//   T_dyn,max = T_{k-1} + (T_fl - T_{k-1}) (1 - e^{-Δt/τ})        (VECTO "dynamic full load":
//               a first-order lag of the available torque towards full load; τ = 0 -> T_fl)
//   T_dyn,min = T_mot  (torque decrease instantaneous, or lagged with τ_dec if > 0)
//   T_k       = clamp(T_req, T_dyn,min, T_dyn,max)
//
// so a full-load step from T_0 at constant speed gives exactly T(t) = T_fl - (T_fl - T_0) e^{-t/τ},
// while small increases (idle governor) are served within the available headroom.
//   ṁ_f = 0                             if T_req <= T_mot or fuel is disabled (overrun fuel cut,
//                                        engine off): T_k = T_mot (drag)
//   ṁ_f = max(0, F(ω_c, T_k)) · s(ω)    otherwise; F = Delaunay/barycentric map [kg/s],
//                                        ω_c = ω clamped to the map speed range,
//                                        s = min(1, ω/ω_min) (cranking/stall region below the
//                                        lowest map speed, where T_fl and T_mot fade linearly to 0)
// Gas path, coolant heat and NOx: gas_path.hpp. Fuel energy ṁ_f·LHV.
//
// Cold engine and exhaust back-pressure (the map was measured warm, at the bench's back-pressure):
// the engine needs an extra indicated torque ΔT [Nm] for the same brake torque,
//   ΔT_fric = s_f |T_mot(ω)| (φ(T_oil) − 1)            φ = oil viscosity factor (oil_viscosity.hpp),
//                                                        T_oil from the cooling node's oil
//   ΔT_pump = (p_b − p_b,ref(ṁ_x)) π_T V_d / (4π)       p_b,ref − p_amb = Δp_r (ṁ_x/ṁ_x,r)^n_b
//   ΔT = ΔT_fric + ΔT_pump;  T_fl → T_fl − ΔT,  T_mot → T_mot − ΔT,  ṁ_f = F(ω, T_k + ΔT)
// s_f = share of the motoring torque that is mechanical friction; a turbine-outlet pressure rise
// Δp raises the turbine-inlet (exhaust-manifold) pressure by about π_T Δp at an unchanged
// expansion ratio (π_T ≈ the boost pressure ratio of the last step), and PMEP rises by that
// (Heywood 1988 §13.2: PMEP ≈ p_exhaust − p_intake). p_b,ref is the back-pressure the map was
// measured with (bench set to the installed ATS at rated flow ṁ_x,r). Inputs oil_T_K <= 0
// or back_pressure_Pa <= 0 switch the respective correction off (no cooling / ATS node).
// Friction heat: the mechanical friction work rate P_f = s_f |T_mot(ω)| φ ω (warm + cold extra,
// φ = 1 without the cooling node) ends in the oil and the metal (gas_path.hpp, Q_oil, Q_metal).
// Outputs are valid for the step just taken; no allocation in step().
#pragma once
#include <string>

#include "common/params.hpp"
#include "common/table1d.hpp"
#include "common/units.hpp"
#include "engine_map/engine_scaling.hpp"
#include "engine_map/gas_path.hpp"
#include "engine_map/nox_map.hpp"
#include "engine_map/scattered_map.hpp"

namespace hbt::engine_map {

struct MapEngineParams {
  // Data files (relative paths are resolved against the base directory given to MapEngine).
  std::string full_load_file = "config/data/engine/generic_primary_bus_7.7l_200kW/FullLoad.vfld";
  std::string fuel_map_file = "config/data/engine/generic_primary_bus_7.7l_200kW/FCMap.vmap";
  std::string pt1_file = "config/data/vehicle/declaration_2015/PT1.csv";
  // Engine-out NOx map (nox_map.hpp: EI over speed x load from the calibrated 1D engine); empty:
  // the constant emission index gas.nox_emission_index_kg_per_kg.
  std::string nox_map_file = "config/data/engine/nox_map_1d.csv";
  double target_peak_torque_Nm = 1100.0;   // SPEC §3
  double target_peak_power_W = 210000.0;   // SPEC §3
  // Idle speed [rad/s] of the engine (not scaled with the speed axis): where the twin's engine
  // starts, whichever model runs it (engine_interface/engine_model.hpp; the 1D engine reads this file as
  // its reference). 700 rpm: VECTO 'Generic primary bus 41 Engine' (config/data/engine/README.txt).
  double idle_speed_rad_s = 73.3038;
  bool scale_speed_axis = true;            // false: torque-only scaling (power = f_T P_ref)
  double pt1_time_constant_factor = 1.0;   // multiplier on the VECTO PT1 τ [-]
  double torque_decrease_time_constant_s = 0.0;  // τ_dec [s]; 0 = instantaneous decrease
  GasPathParams gas;
  // Cold-engine friction (same oil law and constants as the 1D engine's Chen-Flynn friction).
  double friction_share_of_motoring = 0.75;   // s_f [-]
  double oil_ref_K = 363.15;                  // oil temperature of the (warm) map [K]
  double oil_vogel_b_K = 1170.0, oil_vogel_c_K = 150.0;
  double oil_viscosity_exponent = 0.25;       // n [-]
  // Back-pressure the map was measured with: Δp_r at rated exhaust flow, exponent n_b.
  double back_pressure_ref_rated_Pa = 15000.0;
  double back_pressure_ref_exponent = 1.5;
  /// Registers every parameter (key names = config/engine_map.yaml).
  void declare(ParamSet& ps);
};

struct MapEngineInputs {
  double speed_rad_s = 0.0;          // imposed crank speed ω [rad/s]
  double torque_request_Nm = 0.0;    // requested brake torque [Nm]
  double ambient_T_K = 298.15;       // ambient = air-filter inlet temperature [K]
  double ambient_p_Pa = units::kStandardAtmosphere_Pa;  // ambient pressure [Pa]
  bool fuel_enabled = true;          // false = engine off / fuel cut (torque = motoring)
  double oil_T_K = 0.0;              // engine oil temperature [K]; <= 0: warm map, no correction
  double back_pressure_Pa = 0.0;     // turbine-outlet (ATS inlet) pressure [Pa]; <= 0: map's own
};

struct MapEngineOutputs {
  double brake_torque_Nm = 0.0;        // actual brake torque T_k [Nm]
  double fuel_mass_flow_kg_s = 0.0;    // [kg/s]
  double max_torque_Nm = 0.0;          // static full-load torque at ω [Nm]
  double min_torque_Nm = 0.0;          // motoring torque at ω [Nm] (< 0)
  double dynamic_max_torque_Nm = 0.0;  // PT1-limited available torque this step [Nm]
  double time_constant_s = 0.0;        // τ(ω) used [s]
  double friction_correction_Nm = 0.0; // ΔT_fric (cold oil) [Nm]
  double pumping_correction_Nm = 0.0;  // ΔT_pump (back-pressure vs the map's) [Nm]
  bool fuel_cut = false;               // overrun / engine-off fuel cut active
  GasPathState gas;                    // air path, exhaust flow/T/composition, heat split, NOx
  // Cumulative since reset():
  double fuel_mass_kg = 0.0;           // [kg]
  double fuel_energy_J = 0.0;          // ∫ṁ_f LHV dt [J]
  double brake_work_J = 0.0;           // ∫T ω dt [J] (positive and motoring)
  double positive_work_J = 0.0;        // ∫max(Tω, 0) dt [J]
  double motoring_work_J = 0.0;        // ∫min(Tω, 0) dt [J] (<= 0)
  double coolant_heat_J = 0.0;         // ∫Q_cool dt [J] (metal + oil)
  double metal_heat_J = 0.0;           // ∫Q_metal dt [J]
  double oil_heat_J = 0.0;             // ∫Q_oil dt [J]
  double friction_work_J = 0.0;        // ∫P_f dt [J]
  double nox_mass_kg = 0.0;            // ∫ṁ_NOx dt [kg]
};

class MapEngine {
 public:
  /// Loads and scales the data. Throws InputError (file + key) on bad data or parameters.
  explicit MapEngine(const MapEngineParams& p, const std::string& base_dir = "");

  /// Starts at speed ω0 [rad/s] with brake torque T0 [Nm] (clamped to the limits), ambient T [K]
  /// and p [Pa] (the gas path of the start state).
  void reset(double speed_rad_s, double torque_Nm = 0.0, double ambient_T_K = 298.15,
             double ambient_p_Pa = units::kStandardAtmosphere_Pa);
  /// Advances by dt_s [s] (> 0). Throws ModelDivergence on non-finite inputs.
  const MapEngineOutputs& step(double dt_s, const MapEngineInputs& in);
  const MapEngineOutputs& outputs() const { return out_; }

  // Static characteristics of the scaled engine (SI).
  double fullLoadTorque(double speed_rad_s) const;
  double motoringTorque(double speed_rad_s) const;
  double timeConstant(double speed_rad_s) const;
  /// Mechanical friction work rate of the warm engine s_f |T_mot(ω)| ω [W].
  double warmFriction_W(double speed_rad_s) const;
  /// Steady-state fuel flow [kg/s] at brake torque T (0 at or below motoring torque).
  double steadyFuel(double speed_rad_s, double torque_Nm) const;
  double peakTorque() const { return engine_map::peakTorque(fld_); }
  double peakPower(double* speed_rad_s = nullptr) const { return engine_map::peakPower(fld_, speed_rad_s); }
  double minMapSpeed() const { return w_min_; }
  double maxMapSpeed() const { return w_max_; }
  const EngineScaling& scaling() const { return scaling_; }
  const FullLoadCurve& fullLoadCurve() const { return fld_; }
  const FuelMapPoints& fuelMapPoints() const { return map_pts_; }
  const ScatteredLinearMap& fuelMap() const { return fuel_; }
  const MapEngineParams& params() const { return p_; }
  /// Engine-out NOx emission index [kg NO2 / kg fuel] at speed ω and brake torque T: the NOx map
  /// at (ω, T / T_full-load(ω)) (clamped at its edges), or the constant index without a map.
  double noxEmissionIndex(double speed_rad_s, double torque_Nm) const;

 private:
  MapEngineParams p_;
  Table2D nox_map_;                  // empty: constant emission index
  EngineScaling scaling_;
  FullLoadCurve fld_;
  FuelMapPoints map_pts_;
  ScatteredLinearMap fuel_;
  Table1D t_fl_, t_mot_, pt1_;
  double w_min_ = 0.0, w_max_ = 0.0;
  double fuel_ref_kg_s_ = 0.0;  // fuel at the rated (peak-power) full-load point
  double exhaust_ref_kg_s_ = 0.0;  // exhaust flow at the rated point (ambient 25 °C) [kg/s]
  double torque_ = 0.0;
  MapEngineOutputs out_;
};

}  // namespace hbt::engine_map
