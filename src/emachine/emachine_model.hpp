// 48 V P1 e-machine (PMSM on the crankshaft through a fixed ratio stage) with its inverter:
// torque envelopes vs speed and DC voltage (torque_envelope.hpp), physics-based losses
// (em_losses.hpp), a 4-node lumped-parameter thermal network solved exactly
// (thermal_network.hpp), thermal derating of the live torque limits and exact cumulative energy
// bookkeeping. ROS-free, deterministic, no allocation in step().
//
// CRANK CONVENTION. Everything the rest of the twin sees is at the crankshaft; torque > 0 =
// motoring (boost), < 0 = generating. With the ratio r = ω_em/ω_crank = 2.0 and the ratio-stage
// efficiency η = 0.98 (VECTO EM_ratio, EM_mech_efficiency):
//   ω_em = r ω_crank
//   motoring   (T_em > 0): T_crank = r η T_em      P_crank = η P_em      (stage loses (1−η) P_em)
//   generating (T_em < 0): T_crank = r T_em / η    P_crank = P_em / η    (|P_crank| > |P_em|)
//   ratio-stage loss P_ratio = P_em − P_crank >= 0, P_em = T_em ω_em (EM shaft power).
// The ratio-stage loss is heat to the engine/belt drive, not to the LT coolant.
//
// LIMITS at the EM shaft, from the envelopes at (ω_em, V_dc) and the thermal state:
//   λ = min(ramp(T_w; T_w,start → T_w,cont), ramp(T_mag; T_m,start → T_m,cont))   (1 → 0)
//   κ = min(ramp(T_w; T_w,cont → T_w,zero),  ramp(T_mag; T_m,cont → T_m,zero))    (1 → 0)
//   T_max,live = κ (T_max,cont + λ (T_max,peak − T_max,cont)),   T_min,live likewise (<= 0)
// i.e. peak limits until the first threshold, down to the continuous envelope at the second,
// to zero at the insulation (winding) or demagnetisation (magnet) limit. The derating is a pure
// function of the temperatures, never of a timer. derating_factor = min(T_max,live/T_max,peak,
// T_min,live/T_min,peak) (1 = none; 1 when a peak is 0). A request beyond the live limits (taken
// with the temperatures at the step start) is clamped; the delivered torque is reported.
//
// THERMAL NETWORK (nodes W winding, S stator iron, R rotor + magnets, H housing + coolant jacket;
// boundaries: LT coolant T_c and the engine T_e — the P1 housing is bolted to the flywheel
// housing and the rotor hub to the crankshaft flange, both at the engine structure's temperature):
//   C_W dT_W/dt = P_cu − G_WS (T_W − T_S) − G_WH (T_W − T_H)
//   C_S dT_S/dt = P_fe + G_WS (T_W − T_S) − G_SH (T_S − T_H) − G_RS (T_S − T_R)
//   C_R dT_R/dt = P_rotor + P_windage + G_RS (T_S − T_R) − G_RH (T_R − T_H) + G_RE (T_e − T_R)
//   C_H dT_H/dt = P_bearing + G_WH (T_W − T_H) + G_SH (T_S − T_H) + G_RH (T_R − T_H) − G_HC (T_H − T_c)
//                 + G_HE (T_e − T_H)
// Heat from the engine Q̇_e = G_RE (T_e − T_R) + G_HE (T_e − T_H) (> 0 into the machine).
// The inverter loss goes straight to the LT coolant (cold plate in the same circuit, small heat
// capacity): heat to the LT coolant = G_HC (T_H − T_c) + P_inv. Losses are evaluated with the
// state at the step start and held over the step; the network step is exact.
//
// ENERGY (cumulative since reset, J; >0 = into the machine from outside):
//   E_dc = E_dc,drawn (>= 0) + E_dc,returned (<= 0) = ∫ P_dc dt
//   W_crank = W_mot (>= 0) + W_gen (<= 0) = ∫ T_crank ω_crank dt
//   E_dc = W_crank + E_ratio + E_cu + E_fe + E_rotor + E_mech + E_inv          (algebraic)
//   E_cu + E_fe + E_rotor + E_mech + Q_engine = Q_housing→coolant + Σ C (T − T_0)   (network, exact)
//   residual = E_dc + Q_engine − W_crank − E_ratio − Q_to_coolant − ΔU_stored,
//   Q_to_coolant = Q_housing + E_inv
#pragma once
#include <string>

#include "emachine/em_losses.hpp"
#include "emachine/emachine_params.hpp"
#include "emachine/thermal_network.hpp"
#include "emachine/torque_envelope.hpp"

namespace hbt::emachine {

struct EMachineInputs {
  double torque_request_Nm = 0.0;   // at the crank [Nm], > 0 motoring
  double crank_speed_rad_s = 0.0;   // [rad/s] (negative values are taken as 0)
  double dc_voltage_V = 48.0;       // battery terminal voltage [V]
  double coolant_T_K = 298.15;      // LT coolant temperature [K]
  double engine_T_K = 298.15;       // engine structure (flywheel housing, crankshaft) [K]
};

/// Torque limits at the crank [Nm] (max >= 0, min <= 0).
struct CrankLimits {
  double max_live = 0, min_live = 0, max_peak = 0, min_peak = 0, max_cont = 0, min_cont = 0;
  double derating_factor = 1.0;
};

struct EMachineOutputs {
  // Operating point over the last step.
  double torque_request_Nm = 0, torque_Nm = 0;  // crank
  double crank_speed_rad_s = 0, em_speed_rad_s = 0, em_torque_Nm = 0;
  double dc_voltage_V = 0, dc_power_W = 0, dc_current_A = 0;  // P_dc > 0 drawn from the battery
  double phase_current_A = 0;
  LossBreakdown loss;               // machine + inverter losses of the last step [W]
  double ratio_loss_W = 0;
  double total_loss_W = 0;          // machine + inverter + ratio stage
  double lt_heat_W = 0;             // mean heat into the LT coolant over the last step
  double engine_heat_W = 0;         // mean heat conducted in from the engine over the last step (> 0 in)
  // End-of-step state.
  double winding_T_K = 0, stator_T_K = 0, magnet_T_K = 0, housing_T_K = 0;
  CrankLimits limits;               // at the last speed/voltage and the end-of-step temperatures
  // Cumulatives since reset [J].
  double mech_motoring_J = 0, mech_generating_J = 0;
  double dc_J = 0, dc_drawn_J = 0, dc_returned_J = 0;
  double copper_J = 0, iron_J = 0, rotor_J = 0, mechanical_J = 0, inverter_J = 0, ratio_J = 0;
  double heat_to_coolant_J = 0;     // housing -> coolant + inverter
  double heat_from_engine_J = 0;    // engine -> housing and rotor (> 0 into the machine)
  double stored_change_J = 0;       // Σ C (T − T_0)
  double energy_residual_J = 0;
  double time_s = 0;
};

class EMachineModel {
 public:
  /// Validates p (InputError naming `file` and the key), reads the .vemp (path relative to
  /// `base_dir` unless absolute) and builds the network.
  explicit EMachineModel(const EMachineParams& p, const std::string& file = "(emachine parameters)",
                         const std::string& base_dir = "");
  /// Cold start: every node at T_K, cumulatives 0, limits at standstill and nominal voltage.
  void reset(double T_K);
  /// Advances by dt_s with the inputs held. Throws ModelDivergence for non-finite inputs or a
  /// temperature leaving [min, max].
  void step(double dt_s, const EMachineInputs& in);
  const EMachineOutputs& outputs() const { return out_; }
  const EMachineParams& params() const { return p_; }
  const TorqueEnvelope& envelope() const { return env_; }
  const LossModel& lossModel() const { return loss_; }
  const ThermalNetwork& network() const { return net_; }
  /// Crank limits at crank speed w [rad/s], voltage V and winding/magnet temperatures.
  CrankLimits limits(double crank_speed_rad_s, double V, double T_winding_K, double T_magnet_K) const;
  /// Node heat inputs [W] (W, S, R, H) of a loss breakdown.
  static ThermalNetwork::Vec nodeHeat(const LossBreakdown& b);
  /// DC power [W] (> 0 drawn from the battery) of crank torque T_crank [Nm] at crank speed [rad/s],
  /// voltage V, winding and magnet temperatures [K]: EM shaft power + machine and inverter losses
  /// (the ratio stage's loss is inside the EM torque). The power step() books for a request inside
  /// the live limits.
  double dcPower(double crank_torque_Nm, double crank_speed_rad_s, double V, double T_winding_K,
                 double T_magnet_K) const;
  /// Crank torque of an EM torque and back.
  double crankTorque(double T_em) const;
  double emTorque(double T_crank) const;

 private:
  void checkTemperatures() const;
  EMachineParams p_;
  std::string file_;
  TorqueEnvelope env_;
  LossModel loss_;
  ThermalNetwork net_;
  ThermalNetwork::Vec x_ = ThermalNetwork::Vec::Zero(), x0_ = ThermalNetwork::Vec::Zero();
  EMachineOutputs out_;
};

}  // namespace hbt::emachine
