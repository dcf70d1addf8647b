// 48 V Li-ion pack of the P1 mild hybrid: Ns cells in series x Np parallel strings of identical
// cells, each a 1-RC equivalent circuit, in a housing with thermostat-controlled ventilation fans
// (pack_thermal.hpp, pack_ventilation.hpp, pack_fan.hpp). ROS-free, deterministic, no allocation in step().
//
// States: SOC s [-], RC voltage v1 of one cell [V], cell temperature T [K] (all cells alike),
// housing temperature T_w [K], fan on/off.
// Per cell (current i = I/Np [A], > 0 discharge; table values at (s, T), cell_table.hpp):
//   v_t = OCV(s,T) - i R0(s,T) - v1                                   terminal voltage [V]
//   dv1/dt = (i R1 - v1)/tau1,   C1 = tau1/R1                         RC pair [V/s]
//   ds/dt = -i/(3600 Q),   Q [Ah], coulombic efficiency 1            coulomb counting [1/s]
// Pack: V_t = Ns v_t [V], I = Np i [A], P = V_t I [W] (> 0 discharge).
// Thermal: the cells' heat Qdot = Ns Np (i^2 R0 + v1^2/R1) [W] (ohmic + RC-resistor losses;
//   reversible entropic heat not modelled) and the fan's electric power P_f enter the network
//   cells (C_c = Ns Np m c_p) -> enclosure air -> housing wall (C_w) -> ambient of pack_thermal.hpp;
//   with the fans on, ambient air is drawn through the enclosure (ventilation heat m_dot c_p (T_air - T_amb)).
// Fan: on/off with hysteresis on T (pack_fan.hpp); P_f is added to the terminal power request
//   (it is drawn from the pack like the e-machine and the DC/DC) and dissipated in the enclosure.
//
// One step of length h with the request P held (operator splitting, exact per piece):
//  1. Freeze OCV, R0, R1, tau1 at the start-of-step (s_0, T_0) (one 0.01 s macro step moves SOC
//     by < 1e-5 and T by < 1e-3 K).
//  2. With i held, the RC pair is exact: v1(t) = a + b e^{-t/tau1}, a = i R1, b = v1_0 - a. The
//     step-mean terminal voltage is then linear in i:
//        v̄_t = E - i R_eff,  E = OCV - f v1_0,  R_eff = R0 + R1 (1 - f),  f = (tau1/h)(1 - e^{-h/tau1})
//     and P = Ns Np i v̄_t -> R_eff i^2 - E i + p = 0, p = P/(Ns Np); the root on the rising
//     branch, i = 2p/(E + sqrt(E^2 - 4 R_eff p)) (no cancellation; i = 0 at p = 0).
//  3. Limits for this step, cell current i in [-j_c, i_d]:
//        i_d = min( E/(2 R_eff)            (maximum of P(i): matched load, P = Ns Np E^2/(4 R_eff)),
//                   (E - V_min)/R_eff      (step-mean terminal voltage >= V_min),
//                   I_d,max f_hot(T) f_soc,d(s) )
//        j_c = min( (V_max - E)/R_eff,  I_c,max f_cold(T) f_hot(T) f_soc,c(s) )
//     f_cold = clamp((T - T_c0)/(T_c1 - T_c0)), f_hot = clamp((T_max - T)/(T_max - T_h0)),
//     f_soc,d = clamp((s - s_min)/Δs), f_soc,c = clamp((s_max - s)/Δs); power limits
//     P_d = Ns Np i_d (E - i_d R_eff), P_c = Ns Np j_c (E + j_c R_eff). Since the cut-off voltage
//     is above E/2, the V_min limit binds before the matched-load maximum. A request outside
//     [-P_c, P_d] is delivered at the limit current (request_limited, unmet power reported).
//  4. s_1 = s_0 - i h/(3600 Q);  v1_1 = v1_0 e + a (1 - e),  e = e^{-h/tau1}.
//  0. (first) The fan's state from T_0; the request is P = P_ext + P_f.
//  5. Thermal network with Qdot (step mean) and P_f held, exact (pack_thermal.hpp).
//
// Energy bookkeeping, exact integrals over each step (pack, cumulative, J):
//   chemical  W_ch = Σ Ns Np OCV i h                       (energy released by the cells' EMF)
//   terminal  W_t  = Σ P h = Σ Ns Np i v̄_t h
//   ohmic     W_0  = Σ Ns Np i^2 R0 h
//   RC        W_1  = Σ Ns Np (1/R1) ∫ v1^2 dt,  ∫ v1^2 dt = a^2 h + 2ab tau1(1-e) + b^2 tau1/2 (1-e^2)
//   RC store  ΔE_C = Σ Ns Np C1 (v1_1^2 - v1_0^2)/2        (C1 of that step)
//   fan       W_f  = Σ P_f h                                (drawn through the terminals, part of W_t)
//   heat to the ambient Q_a = Σ G_o ∫(T_w - T_amb) dt       (exact integral, pack_thermal.hpp)
//   ventilation heat   Q_v = Σ ∫ m_dot c_p (T_air - T_amb) dt  (exact integral, pack_thermal.hpp)
//   stored heat ΔH = C_c (T - T_0) + C_w (T_w - T_w,0)        (from the state; 0: at reset)
//   residual = W_ch - W_t + W_f - Q_a - Q_v - ΔH - ΔE_C      (0 to round-off)
// (Electrically W_ch = W_t + W_0 + W_1 + ΔE_C exactly; thermally W_0 + W_1 + W_f = Q_a + Q_v + ΔH.) ΔE_C is
// the sum of the per-step changes: C1 changes between steps with (s, T), so it differs from
// C1 v1^2/2 of the present state by that parameter drift (tiny).
//
// Errors: bad parameters or table -> InputError(file, key); a non-finite request or air
// temperature, a step dt <= 0, or a state leaving its bounds -> ModelDivergence("battery", quantity, ...).
#pragma once
#include <string>

#include "battery/battery_params.hpp"
#include "battery/cell_table.hpp"
#include "battery/pack_fan.hpp"
#include "battery/pack_thermal.hpp"

namespace hbt::battery {

struct BatteryInputs {
  double power_request_W = 0.0;   // DC power requested at the pack terminals [W] (> 0 discharge)
  double air_T_K = 298.15;        // ambient air around the housing [K]
  double air_speed_m_s = 0.0;     // air speed over the housing (vehicle speed) [m/s]
};

/// Operating envelope for a step of a given length from the present state (per cell and pack).
struct StepEnvelope {
  double emf_V = 0.0;             // E: cell EMF seen over the step (OCV - f v1_0) [V]
  double r_eff_Ohm = 0.0;         // R_eff of one cell over the step [Ohm]
  double discharge_cell_current_A = 0.0;  // i_d >= 0
  double charge_cell_current_A = 0.0;     // j_c >= 0 (magnitude)
  double discharge_power_W = 0.0;         // P_d >= 0 (pack)
  double charge_power_W = 0.0;            // P_c >= 0 (pack, magnitude)
};

struct BatteryOutputs {
  // State at the end of the last step (after reset: the initial state).
  double soc = 0.0;                      // [-]
  double cell_T_K = 0.0;                 // [K]
  double ocv_V = 0.0;                    // pack open-circuit voltage Ns OCV(s, T) [V]
  double rc_voltage_V = 0.0;             // pack RC voltage Ns v1 [V]
  // Means over the last step (after reset: at rest).
  double terminal_voltage_V = 0.0;       // Ns v̄_t [V]; power_W = terminal_voltage_V current_A
  double current_A = 0.0;                // pack current [A] (> 0 discharge)
  double power_W = 0.0;                  // delivered terminal power [W] (> 0 discharge)
  double request_W = 0.0;                // requested terminal power [W]
  double unmet_power_W = 0.0;            // request - delivered when limited, else 0 [W]
  bool request_limited = false;          // request outside [-P_c, P_d]: delivered at the limit
  double ohmic_loss_W = 0.0, rc_loss_W = 0.0;
  double loss_power_W = 0.0;             // ohmic + RC = heat generated in the cells [W]
  double heat_to_air_W = 0.0;            // housing -> ambient air [W]
  double ventilation_heat_W = 0.0;       // carried out by the ventilation air, G_v (T_air - T_amb) [W]
  bool fan_on = false;                   // ventilation fans on over the last step
  double fan_power_W = 0.0;              // its electric power, part of request_W [W]
  double housing_T_K = 0.0;              // housing wall at the end of the step [K]
  double enclosure_air_T_K = 0.0;        // air inside the housing at the end of the step [K]
  double overall_conductance_W_K = 0.0;  // cells -> ambient, steady state, last step's fan and speed
  double ventilation_conductance_W_K = 0.0;  // G_v = m_dot c_p of the ventilation air (0 fan off)
  // Limits for the next step (length limits/horizon_s) from the present state.
  double discharge_power_limit_W = 0.0, charge_power_limit_W = 0.0;      // >= 0
  double discharge_current_limit_A = 0.0, charge_current_limit_A = 0.0;  // pack, >= 0
  // Cumulative since reset.
  double chemical_energy_J = 0.0, terminal_energy_J = 0.0;
  double ohmic_loss_J = 0.0, rc_loss_J = 0.0, loss_energy_J = 0.0;
  double heat_to_air_J = 0.0, stored_heat_change_J = 0.0, rc_stored_energy_change_J = 0.0;
  double ventilation_heat_J = 0.0;       // Σ heat carried out by the ventilation air
  double fan_energy_J = 0.0;             // Σ P_f h (the fan's share of terminal_energy_J)
  double fan_on_time_s = 0.0;
  double energy_residual_J = 0.0;
  double unmet_energy_J = 0.0;           // Σ (request - delivered) h
  double charge_throughput_Ah = 0.0;     // Σ |I| h / 3600
  double limited_time_s = 0.0;           // time with request_limited
  double time_s = 0.0;
};

class BatteryModel {
 public:
  /// Validates p (InputError naming `file` and the key), reads the cell table.
  explicit BatteryModel(const BatteryParams& p, const std::string& file = "(battery parameters)");
  /// Cold start: T = air_T_K, SOC = pack/initial_soc, v1 = 0, cumulatives 0.
  void reset(double air_T_K);
  /// Same with an explicit initial SOC.
  void reset(double air_T_K, double soc);
  /// Cells at cells_T_K, housing at housing_T_K (a warm start), SOC = pack/initial_soc.
  void resetWarm(double cells_T_K, double housing_T_K);
  /// Advances by dt_s with the inputs held. Throws ModelDivergence naming the quantity.
  void step(double dt_s, const BatteryInputs& in);
  const BatteryOutputs& outputs() const { return out_; }
  const BatteryParams& params() const { return p_; }
  const CellTable& cellTable() const { return table_; }
  /// Envelope of a step of length h from the present state.
  StepEnvelope envelope(double h) const;
  double heatCapacity_J_K() const { return thermal_.params().cells_heat_capacity_J_K; }
  const PackThermal& thermal() const { return thermal_; }
  double cellRcVoltage_V() const { return v1_; }
  int cells() const { return n_cells_; }

 private:
  void updateStateOutputs();
  void resetState(double cells_T_K, double housing_T_K, double soc);
  BatteryParams p_;
  std::string file_;
  CellTable table_;
  int n_cells_ = 0;
  double Q_As_ = 0.0;       // cell capacity [A s]
  PackThermal thermal_;
  PackFan fan_;
  // State.
  double soc_ = 0.5, v1_ = 0.0, T_ = 298.15;
  BatteryOutputs out_;
};

}  // namespace hbt::battery
