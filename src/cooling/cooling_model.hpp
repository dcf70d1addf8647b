// Cooling system of the bus: high-temperature (engine) circuit with wax thermostat, radiator,
// viscous-clutch fan and cabin heater, plus the low-temperature (e-machine + power electronics)
// circuit whose radiator sits in front of the HT radiator in the same air stream. ROS-free,
// deterministic, no allocation in step().
//
// States: T_m engine metal, T_o engine oil [K]; HT coolant in three well-mixed volumes: T_c engine loop (jacket,
// pump, thermostat housing, bypass; its temperature is the engine outlet, "the" HT coolant
// temperature of the thermostat, fan, heater valve, warm-up time and EMS), T_r radiator volume,
// T_v convector volume (heater loop); T_l LT coolant [K]; T_w thermostat wax [K], T_p
// play-operator output of the wax temperature [K], e fan-clutch engagement [-], ω_lt LT pump
// speed (clutch output, before the input-speed cap) [rad/s]; the heater valve (open/shut).
//
// Thermal network (equations in coolant_network.hpp; Q̇ in W, C in J/K, G, W in W/K, T_a ambient):
//   C_m dT_m/dt = Q̇_eng - G_mc (T_m - T_c) - G_om (T_m - T_o) - G_s (T_m - T_a) - Q̇_em
//                 (Q̇_eng: the engine's heat into its metal, combustion heat through the walls and
//                 the ring and skirt friction on the liners; Q̇_em: heat conducted into the P1
//                 e-machine's housing and rotor, which its LT heat then carries)
//   C_o dT_o/dt = Q̇_oil + G_om (T_m - T_o) - G_oc (T_o - T_c)   (Q̇_oil: the engine's friction heat
//                 carried by the oil, bearings and valve train; G_oc: the engine's oil cooler)
//   C_c dT_c/dt = G_mc (T_m - T_c) + G_oc (T_o - T_c) - W_r (T_c - T_r) - W_v (T_c - T_v) + Q̇_gb
//                 (Q̇_gb: the automatic gearbox's oil-to-coolant cooler)
//   C_r dT_r/dt = W_r (T_c - T_r) - Q̇_rad,HT
//   C_v dT_v/dt = W_v (T_c - T_v) - Q̇_heater + Q̇_aux   (Q̇_aux: the fuel-fired water heater, in
//                 the heating circuit ahead of the convectors; it switches on the water
//                 reaching it, T_c while the loop flows from the engine, else T_v: the hvac)
//   C_l dT_l/dt = Q̇_LT,in - Q̇_rad,LT
//   C_m = m_metal c_metal,  C_o = m_oil c_oil,  C_c, C_r, C_v = ρ V c of the engine loop, radiator and
//   convector volumes,  C_l = ρ V_lt c + C_components
//   W_r = ṁ_rad c (thermostat),  W_v = ṁ_heater c (heater valve open, heating wanted; else 0)
//   Q̇_rad,LT = G_LT (T_l - T_a),                       G = ε C_min of the radiator (radiator.hpp)
//   T_air,HT,in = T_a + Q̇_rad,LT/(ṁ_air c_p,air)        (LT radiator pre-heats the HT radiator air)
//   Q̇_rad,HT = G_HT (T_c - T_air,HT,in)                 (radiator inlet = engine outlet)
//   Heating wanted: T_a < T_bal (balance point) or, with the hvac participant (in.cabin_from_hvac),
//   its demand Q̇_d > 0. Heater valve (heater loop <-> engine loop): opens when T_c >= T_heat,min
//   and shuts when T_c < T_heat,min - hysteresis; shut while no heating is wanted (the climate
//   control keeps the convector loop out of the circuit). Convectors: draw heat while heating is
//   wanted and their water is warm (the same lockout on T_v: on at T_v >= T_heat,min, off below
//   T_heat,min - hysteresis), valve open or shut (shut: the loop heated by the fuel-fired heater).
//   Q̇_heater = min(UA_cab (T_bal - T_a), G_h (T_v - T_a)), or with the hvac participant
//   min(Q̇_d, G_h (T_v - T_cab)) (0 if T_v <= T_cab); 0 while no heating is wanted or T_v is cold
// Coolant flows: V̇_pump = V̇_r ω_p/ω_r; radiator share y_eff = leak + (1 - leak) y, the rest
// bypasses; ṁ_rad = ρ y_eff V̇_pump; heater loop (parallel branch) ṁ_heater = ρ f_h V̇_pump.
// Engine stopped (the step's mean pump speed 0) with the heater valve open: the 24 V electric
// circulation pump circulates the heater loop through the engine jacket, ṁ_heater = ρ V̇_e, at
// its electric power P_e (0 otherwise; V̇_e = 0, a bus without the pump: the loop stands, the
// convectors cool their own water only and the engine loop gives nothing). While the fuel-fired
// heater burns the same pump runs (its circulating pump): P_e booked, the loop circulating within
// itself when the valve is shut.
// LT: ṁ_lt = ρ V̇_lt,r ω_lt/ω_lt,max.
// Thermostat: wax lag dT_w/dt = (T_c - T_w)/τ_w; play operator of half-width h = hysteresis/2,
//   T_p <- clamp(T_p, T_w - h, T_w + h); y = clamp((T_p + h - T_start)/(T_full - T_start), 0, 1),
//   so the heating curve opens at T_start..T_full and the cooling curve closes 2h lower.
// Fan (viscous clutch): e* = max(clamp((T_c - T_e0)/(T_e1 - T_e0)), fan_demand),
//   de/dt = (e* - e)/τ_f,  n_fan = ω_crank r_drive (s_min + (s_max - s_min) e)   [rad/s]
// Air path (fan laws + linear fan curve in flow coefficient, quadratic system resistance):
//   Δp_fan = Δp_0 (n/n_r)² - (Δp_0/V̇_free,r) (n/n_r) V̇,   Δp_0 = Δp_r/(1 - 1/r_free),
//   Δp_r = P_r η/V̇_r,  V̇_free,r = r_free V̇_r  (i.e. ψ = ψ_0 (1 - φ/φ_free))
//   Δp_sys = K V̇² = K V̇_ram² + Δp_fan,  K = Δp_r/V̇_r²,  V̇_ram = r_ram v A_grille
//   -> K V̇² + b V̇ - (a + K V̇_ram²) = 0, positive root. At v = 0: V̇ ∝ n, Δp ∝ n², P ∝ n³.
//   All pressures (fan, system, ram) scale with ρ/ρ_r: V̇ does not depend on ρ, Δp and P ∝ ρ.
//   P_fan = Δp_fan V̇/η (Δp_fan >= 0),  P_fan = η Δp_fan V̇ (Δp_fan < 0: the ram air drives the
//   fan, windmilling, power < 0 = returned to the shaft). ṁ_air = ρ V̇, ρ = p/(R T_a).
//   Crank-side (drive) power through the viscous clutch, same torque on both sides:
//   P_drive = P_fan ω_in/n_fan for P_fan > 0 (includes the slip loss), P_drive = P_fan when
//   windmilling (no slip loss booked).
// Pumps (affinity laws): P_hyd = Δp_r V̇_r (ω/ω_r)³, P_shaft = P_hyd/η; LT pump input power
//   through its viscous clutch P_in = P_shaft ω_in/ω_lt (same torque on both sides, slip loss).
// LT pump rule: ω*_lt = ω_idle + (ω_max - ω_idle) clamp((T_l - T_lo)/(T_hi - T_lo)),
//   dω_lt/dt = (ω*_lt - ω_lt)/τ_lt, actual speed min(ω_lt, ω_crank r_lt).
//
// Integration: per substep (<= max_substep_s) the flows, ε and the heater valve are frozen at
// the start of the substep (the heater's min() on the branch the new convector temperature
// picks) and the linear 6-node network is advanced by backward Euler (implicit,
// unconditionally stable). The cumulative energies book exactly the fluxes of that update, so
// heat in - heat out - Δstored = 0 to round-off. Lags (wax, clutch, LT pump) use the exact
// exponential update with the new coolant temperature.
#pragma once
#include "common/units.hpp"
#include <Eigen/Dense>

#include "cooling/coolant_network.hpp"
#include "cooling/cooling_params.hpp"
#include "cooling/radiator.hpp"

namespace hbt::cooling {

struct CoolingInputs {
  double engine_heat_W = 0.0;          // heat the engine rejects into its metal [W]
  double engine_oil_heat_W = 0.0;      // heat the engine's friction puts into its oil [W]
  double pump_speed_rad_s = 0.0;       // HT pump shaft speed = crank speed (1:1) [rad/s]
  double vehicle_speed_m_s = 0.0;      // for ram air [m/s]
  double ambient_T_K = 298.15;         // [K]
  double ambient_p_Pa = units::kStandardAtmosphere_Pa;      // [Pa]
  double lt_heat_W = 0.0;              // e-machine + power electronics losses [W] (0 baseline)
  double em_engine_heat_W = 0.0;       // heat the P1 e-machine draws from the engine metal through
                                       // its flange and rotor hub [W] (> 0 out of the metal; 0 baseline)
  double fan_demand = 0.0;             // [-] extra fan request 0..1 (HVAC)
  // Cabin heating by the hvac participant (hvac:=on): its demand and cabin temperature replace
  // the balance-point demand of heater/ (cabin_from_hvac), and its fuel-fired heater's heat
  // enters the HT coolant.
  bool cabin_from_hvac = false;
  double cabin_heat_demand_W = 0.0;    // heat the cabin asks of the convectors [W]
  double cabin_T_K = 293.15;           // cabin temperature [K] (convector driving difference)
  double aux_heater_heat_W = 0.0;      // fuel-fired heater's heat into the heater loop (convector volume) [W]
  double gearbox_cooler_heat_W = 0.0;  // the AT's oil-to-coolant cooler into the HT engine loop [W]
};

struct CoolingOutputs {
  double coolant_ht_T_K = 0.0;         // engine loop = engine outlet [K]
  double metal_T_K = 0.0, coolant_lt_T_K = 0.0;
  double oil_T_K = 0.0;                // engine oil (sump) [K]
  double oil_cooler_heat_W = 0.0;      // oil -> engine-loop coolant through the oil cooler [W]
  double radiator_coolant_T_K = 0.0;   // radiator volume (= its return to the engine) [K]
  double convector_coolant_T_K = 0.0;  // convector volume (heater loop) [K]
  bool heater_valve_open = false;      // heater loop in the circuit (heating wanted, coolant warm)
  double heater_loop_flow_m3_s = 0.0;  // coolant flow through the heater loop [m^3/s]
  double electric_pump_power_W = 0.0;  // 24 V heater circulation pump, electric [W]
  double thermostat_opening = 0.0;     // [-]
  double fan_speed_rad_s = 0.0, fan_engagement = 0.0;
  double fan_power_W = 0.0;            // fan shaft power, signed (< 0 windmilling)
  double fan_drive_power_W = 0.0;      // crank-side fan drive power incl. clutch slip, signed
  double fan_pressure_rise_Pa = 0.0;
  double pump_power_W = 0.0;           // HT pump shaft power [W]
  double lt_pump_speed_rad_s = 0.0;
  double lt_pump_power_W = 0.0;        // LT pump clutch input power (shaft + slip) [W]
  double lt_pump_hydraulic_power_W = 0.0;
  double radiator_ht_heat_W = 0.0, radiator_lt_heat_W = 0.0, heater_heat_W = 0.0;
  double aux_heater_heat_W = 0.0;      // fuel-fired heater's heat into the heater loop (convector volume) [W]
  double surface_loss_W = 0.0;
  double air_volume_flow_m3_s = 0.0, air_mass_flow_kg_s = 0.0;
  double coolant_flow_m3_s = 0.0, radiator_coolant_flow_m3_s = 0.0;
  double ht_air_in_T_K = 0.0;          // HT radiator air inlet (after the LT radiator) [K]
  // Cumulative since reset [J].
  double fan_energy_J = 0.0, fan_drive_energy_J = 0.0, pump_energy_J = 0.0, lt_pump_energy_J = 0.0;
  double electric_pump_energy_J = 0.0; // 24 V heater circulation pump, electric
  double engine_heat_J = 0.0, lt_heat_J = 0.0, aux_heater_J = 0.0;
  double engine_oil_heat_J = 0.0;      // the engine's friction heat into its oil
  double oil_cooler_J = 0.0;           // oil -> engine-loop coolant through the oil cooler
  double em_engine_heat_W = 0.0, em_engine_heat_J = 0.0;  // engine metal -> e-machine [W], [J]
  double gearbox_cooler_J = 0.0;       // the AT's oil cooler into the HT engine loop [J]
  double radiator_ht_J = 0.0, radiator_lt_J = 0.0, heater_J = 0.0, surface_loss_J = 0.0;
  double stored_change_J = 0.0;        // Σ C (T - T_0) over metal, oil, the three HT volumes and LT
  double energy_residual_J = 0.0;      // in - out - stored change (ideally 0)
  double warmup_time_s = -1.0;         // first time T_c >= opening start (-1 before)
  double time_s = 0.0;
};

class CoolingModel {
 public:
  /// Validates p (throws InputError naming `file` and the key) and sizes the radiators.
  explicit CoolingModel(const CoolingParams& p, const std::string& file = "(cooling parameters)");
  /// Cold start: every temperature = ambient_T_K, clutches at rest (e = 0, LT pump idle),
  /// thermostat closed, cumulatives 0.
  void reset(double ambient_T_K);
  /// Restarts warm: metal, oil, HT (all three volumes) and LT coolant at the given temperatures [K] (the wax and its
  /// play on the heating branch at the coolant, the heater valve as the coolant sets it), fan
  /// clutch released; the stored energy and warm-up time count from this state (warm-up time 0
  /// when the coolant is already at the thermostat's opening).
  void reset(double ambient_T_K, double metal_T_K, double coolant_ht_T_K, double coolant_lt_T_K, double oil_T_K);
  /// The same with the oil at the metal's temperature.
  void reset(double ambient_T_K, double metal_T_K, double coolant_ht_T_K, double coolant_lt_T_K) {
    reset(ambient_T_K, metal_T_K, coolant_ht_T_K, coolant_lt_T_K, metal_T_K);
  }
  /// Advances by dt_s with inputs held constant. Throws ModelDivergence naming the quantity.
  void step(double dt_s, const CoolingInputs& in);
  const CoolingOutputs& outputs() const { return out_; }
  const CoolingParams& params() const { return p_; }
  const Radiator& htRadiator() const { return rad_ht_; }
  const Radiator& ltRadiator() const { return rad_lt_; }
  /// Heat capacities of the network's nodes [J/K] (metal, engine loop, radiator, convector, LT, oil).
  const NetworkCapacities& capacities() const { return network_.capacities(); }

  /// Air path alone: volume flow [m^3/s], fan pressure rise [Pa] and signed fan power [W] at fan
  /// speed n [rad/s], vehicle speed v [m/s], air density rho (<= 0: the rated density).
  struct AirPoint { double flow_m3_s, dp_Pa, power_W; };
  AirPoint airPath(double fan_speed_rad_s, double vehicle_speed_m_s, double rho_kg_m3 = 0.0) const;
  /// Thermostat opening from the play-operator state (heating curve when T_p = T_w - h).
  double openingFromPlay(double T_p) const;
  /// LT pump rule target speed at LT coolant temperature T [rad/s].
  double ltPumpTarget(double T_l) const;

 private:
  // One substep: the coefficients frozen at its start, then the implicit update's results.
  struct SubstepState {
    double h = 0, Ta = 0, w_p = 0;            // substep [s], ambient [K], HT pump speed [rad/s]
    double q_pump = 0, pump_W = 0;            // HT pump flow [m^3/s] and shaft power [W]
    double y = 0, q_rad = 0, m_rad = 0;       // thermostat opening [-], radiator flow [m^3/s], [kg/s]
    bool heating_wanted = false;              // the cabin wants heat (hvac demand or balance point)
    bool valve_open = false;                  // heater loop in the circuit
    double q_heater = 0;                      // heater-loop flow [m^3/s]
    double e_pump_W = 0;                      // electric circulation pump power [W]
    double n_fan = 0;                         // fan speed [rad/s]
    AirPoint air{0.0, 0.0, 0.0};              // air path at the fan speed
    double fan_drive_W = 0;                   // fan power at its drive (clutch slip included) [W]
    double m_air = 0, C_air = 0;              // air mass flow [kg/s], capacity rate [W/K]
    double w_lt = 0, m_lt = 0;                // LT pump speed [rad/s], LT coolant flow [kg/s]
    double lt_hyd_W = 0, lt_in_W = 0;         // LT pump hydraulic and drive power [W]
    double G_lt = 0, G_ht = 0, pre = 0;       // radiator conductances [W/K], LT air preheat [-]
    bool heater_on = false;                   // convectors drawing heat (demand, their water warm)
    double heater_demand_W = 0;               // heater: the cabin's demand D [W] ...
    double heater_q0 = 0, heater_g = 0;       // ... or the convectors' q0 + g θ_v [W], [W/K]
    NetworkFluxes flux;                       // heat flows of the implicit update [W]
  };
  void substep(double h, const CoolingInputs& in);
  void htPumpAndThermostat(SubstepState& s) const;
  void fanAndAirFlow(const CoolingInputs& in, double rho_air, SubstepState& s) const;
  void ltPump(SubstepState& s) const;
  void heaterValve(const CoolingInputs& in, SubstepState& s);
  void heaterLoad(const CoolingInputs& in, SubstepState& s) const;
  void solveTemperatures(const CoolingInputs& in, SubstepState& s);
  void updateLags(const CoolingInputs& in, const SubstepState& s);
  void recordOutputs(const CoolingInputs& in, const SubstepState& s, double T_c_old);
  void checkTemperatures() const;
  void checkFinite(const CoolingInputs& in) const;
  CoolingParams p_;
  std::string file_;
  Radiator rad_ht_, rad_lt_;
  CoolantNetwork network_;
  double dp_rated_ = 0, dp0_ = 0, K_sys_ = 0, flow_free_r_ = 0;
  // State.
  NetworkState T_, T0_;  // node temperatures and those of the last reset [K]
  double T_w_ = 0, T_p_ = 0, eng_ = 0, w_lt_ = 0;
  bool heater_valve_open_ = false;
  bool convectors_warm_ = false;  // the convectors' lockout on the water they hold
  CoolingOutputs out_;
};

}  // namespace hbt::cooling
