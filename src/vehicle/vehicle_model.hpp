// Longitudinal bus model: chassis + wheels, axle, 6-speed automatic with torque converter and
// lock-up, crankshaft, driver (speed PI + feed-forward), idle governor, auxiliaries, with
// cumulative energy bookkeeping. ROS-free; stepped at the co-simulation macro step.
//
// Bodies: crank (J_E = engine + TC pump inertia, speed ω_e), gearbox input (J_GI = turbine +
// input shaft, speed ω_in), vehicle (M = m + Σ J_wheel/r², speed v). k_g = i_g i_a / r [1/m].
// Torques at the crank: engine brake torque T_e (input, from the engine one exchange late),
// e-machine T_em (input), aux T_aux = P_aux ω_e/max(ω_e, ω_idle)², gearbox drag T_d: the
// loss map's drag L(ω, 0) at the crank when locked/shifting, on the turbine side at ω_t in 1C
// (T_d,in), and only the neutral spin loss T_N (neutral_drag_torque_Nm) at ω_e in neutral.
// Gearbox load loss T_gl at ω_in, retarder T_r and axle loss T_ax = (1-η_a)|T_axle,in| at the
// gearbox output ω_out = v i_a/r. Road: F_road = F_roll + F_aero + F_grade; brake F_b.
// Temperatures: F_roll carries the tyre factor f_t(T_amb) (road_load.hpp); T_d and T_N carry the
// cold-oil factor φ(T_oil,gb) of the gearbox oil node (driveline_oil.hpp), held over a macro
// step. The oil nodes take, per macro step, the heat of their unit's losses: gearbox = drag +
// load loss + converter + shift clutches + retarder (one ATF sump); axle = axle loss.
//
//   locked gL:  (M + (J_E+J_GI) k_g²) dv/dt = k_g (T_e + T_em - T_aux - T_d - T_gl)
//                                             - (i_a/r)(T_r + T_ax) - F_road - F_b,  ω_e = k_g v
//   1C (TC):    J_E dω_e/dt = T_e + T_em - T_aux - T_d - T_p(ω_e, ω_in)
//               (M + J_GI k_1²) dv/dt = k_1 (T_t - T_gl - T_d,in) - (i_a/r)(T_r + T_ax) - F_road - F_b
//               (T_d = 0 on the crank in 1C)
//   neutral:    (J_E + J_GI) dω_e/dt = T_e + T_em - T_aux - T_N;   M dv/dt = -(i_a/r) T_r - F_road
//   gear change g -> h (slip phase, shift_duration_s = t_s > 0; the engine and gearbox input
//   turn at ω_e, the on-coming clutch transmits T_c into gear h):
//               (J_E+J_GI) dω_e/dt = T_e + T_em - T_aux - T_d - T_c
//               M dv/dt = k_h (T_c - T_gl) - (i_a/r)(T_r + T_ax) - F_road - F_b
//               T_c = T_crank + (J_E+J_GI) s_0/t_s (slip s = ω_e - k_h v synchronised at the
//               constant rate s_0/t_s), set to 0 if it would oppose the slip (power-on downshift /
//               coasting upshift: the engine revs freely, torque interrupted); clutch loss
//               T_c s is a shift loss; at s = 0 the gear locks (remaining impulse booked).
//               Upshift torque intervention (TCU): the engine torque request is lowered by
//               (J_E+J_GI) s_0/t_s during the slip phase, keeping the output torque smooth.
//   1C -> 1L lock-up likewise: the lock-up clutch torque T_lu = T_crank - T_p + J_E s_0/t_lu
//               acts in parallel with the converter (engine side -T_lu, turbine side +T_lu)
//               until ω_e = k_1 v; its slip heat is booked as TC loss.
// with T_p, T_t from the torque converter (torque_converter.hpp). Rolling resistance and brake
// are Coulomb forces: the bus stops exactly (no reversal) and is held while |F_other| <=
// F_roll + F_b. Mode changes (shift, lock-up, engage, neutral) are instantaneous clutch
// impulses conserving momentum through the ratios, e.g. into gL:
//   v' = (M v + (J_E ω_e + J_GI ω_in) k_g) / (M + (J_E+J_GI) k_g²);
// their kinetic-energy loss is booked as shift loss (no torque interruption modelled).
// Integration: Heun (RK2) substeps <= max_substep_s within the macro step with the inputs held;
// every power term is booked with its stage-averaged value times the mid-step speed, so that
//   W_engine + W_em = E_aux + E_drag + E_tc + E_gear + E_ret + E_axle + E_shift + E_roll
//                     + E_aero + E_grade(= m g Δh) + E_brake + ΔE_kin
// holds to rounding (checked in the tests against the kinetic energy of the state).
//
// Macro-step timing (lock-step co-simulation, exchange every Δt): step(Δt, in) uses the engine
// torque of the previous exchange, integrates [t, t+Δt], then evaluates the driver and the idle
// governor at t+Δt against in.target_speed_m_s (the target for t+Δt) and outputs the imposed
// engine speed ω_e(t+Δt) and the engine torque request for the next engine step. The model
// integrates the targets into s_target (trapezoid) for the driver's distance error.
// Accelerator pedal a → crank torque T_floor + a (T_max - T_floor): T_floor = motoring torque
// when locked, the idle-holding torque (aux + T_p(ω_idle, ω_t)) in 1C.
#pragma once
#include <string>

#include "common/table1d.hpp"
#include "vehicle/driveline_oil.hpp"
#include "vehicle/driver.hpp"
#include "vehicle/road_load.hpp"
#include "vehicle/shift_strategy.hpp"
#include "vehicle/torque_converter.hpp"
#include "vehicle/transmission_losses.hpp"
#include "vehicle/vehicle_params.hpp"

namespace hbt::vehicle {

struct VehicleInputs {
  double target_speed_m_s = 0.0;      // driver target (for the end of this step) [m/s]
  double target_accel_m_s2 = 0.0;     // target acceleration (feed-forward) [m/s²]
  double road_grade = 0.0;            // rise/run [-], used unless a grade profile is set
  double engine_torque_Nm = 0.0;      // actual engine brake torque (previous exchange) [Nm]
  double engine_max_torque_Nm = 0.0;  // engine full-load torque at its speed [Nm]
  double engine_min_torque_Nm = 0.0;  // engine motoring torque at its speed [Nm] (< 0)
  double em_torque_Nm = 0.0;          // P1 e-machine torque on the crank [Nm] (hybrid)
  double em_max_torque_Nm = 0.0;      // its live (derated) motoring limit at the crank [Nm] (hybrid):
                                      // the driver's full pedal asks engine + e-machine maximum
  bool brake_override = false;        // hybrid: the EMS sets the friction brake of this step
  double friction_brake_force_N = 0.0;  // ... to this force at the tyres [N] (regen took the rest)
  bool engine_on = true;              // false: engine stopped/being cranked (hybrid stop-start):
                                      // no idle governor, its torque T_e <= 0 is friction
                                      // opposing ω_e (T_e > 0, gas expanding: drives the crank),
                                      // the gearbox stays in neutral until it runs again
  bool has_fan_power = false;         // true when the cooling node provides fan_power_W
  double fan_power_W = 0.0;           // fan shaft power [W] (may be < 0: windmilling)
  // HVAC (the hvac participant, hvac:=on): the A/C compressor's shaft power on the crank [W] and
  // the HVAC's 24 V electric load [W] (with the cooling's heater circulation pump), fed the way
  // the aux set feeds its 24 V consumers (the alternator on the crank, or the 48 V DC/DC:
  // AuxParams::electricViaDcdc()).
  double hvac_compressor_W = 0.0;
  double hvac_electric_W = 0.0;
  double ambient_T_K = 293.15;        // air density, tyre factor, oil nodes' surroundings [K]
  bool neutral_request = false;       // force neutral (coast-down, sailing)
  bool driver_enabled = true;         // false: pedals below are applied open-loop
  double accel_pedal_cmd = 0.0;       // [0, 1] when !driver_enabled
  double brake_pedal_cmd = 0.0;       // [0, 1] when !driver_enabled
};

/// Cumulative energies since reset() [J]; losses >= 0, grade = potential-energy gain.
struct VehicleEnergy {
  double engine_J = 0.0, em_J = 0.0;                    // work delivered to the crank
  double aux_J = 0.0, gearbox_drag_J = 0.0, tc_loss_J = 0.0, gear_load_loss_J = 0.0;
  // aux_J split by consumer (each a part of aux_J; they add up to it): cooling fan (signed:
  // < 0 while the ram air drives it), steering pump, pneumatic system (air compressor),
  // electric system (alternator). Booked as the consumer's share P_i/P_aux of each macro
  // step's aux work (all consumers see the same crank-speed factor, see auxPower()).
  double fan_J = 0.0, steering_J = 0.0, pneumatic_J = 0.0, electric_J = 0.0;
  // HVAC on the crank: A/C compressor + its electric load through the alternator (part of aux_J).
  double hvac_J = 0.0;
  // Hybrid stop-start: while the engine is stopped the crank-driven steering pump and air
  // compressor stand, but their demand (air used by doors and kneeling, steering) is not gone:
  // it is deferred and paid back after the restart on top of their normal power (at most doubling
  // it) until repaid. aux_deferred_J = the demand still owed [J] (>= 0, not part of aux_J).
  double aux_deferred_J = 0.0;
  double dcdc_J = 0.0;  // electric energy of the 24 V consumers drawn via the DC/DC [J] (battery
                        // side; electric, not part of the crank balance below)
  double retarder_J = 0.0, axle_loss_J = 0.0, shift_loss_J = 0.0;
  double rolling_J = 0.0, aero_J = 0.0, grade_J = 0.0, brake_J = 0.0;
  double wheel_J = 0.0;                                 // work at the wheel hubs
  double kinetic_J = 0.0, kinetic_initial_J = 0.0;      // vehicle + rotating parts
  double correction_J = 0.0;                            // numerical clamps (should be ~0)
  double residual_J() const {
    return engine_J + em_J -
           (aux_J + gearbox_drag_J + tc_loss_J + gear_load_loss_J + retarder_J + axle_loss_J +
            shift_loss_J + rolling_J + aero_J + grade_J + brake_J + correction_J) -
           (kinetic_J - kinetic_initial_J);
  }
};

struct VehicleOutputs {
  double engine_speed_rad_s = 0.0;        // imposed crank speed ω_e [rad/s]
  double engine_torque_request_Nm = 0.0;  // for the engine (= crank demand - em_torque)
  double crank_torque_demand_Nm = 0.0;    // driver/idle-governor demand at the crank [Nm]
  double accel_pedal = 0.0, brake_pedal = 0.0;  // [0, 1]
  double brake_force_N = 0.0;             // driver's brake force for the next step [N]
  double applied_brake_force_N = 0.0;     // friction brake force applied in the last step [N]
  double crank_to_wheel_ratio = 0.0;      // i_g i_a with a gear locked (torque path crank ->
                                          // wheels closed), else 0 (converter, neutral, shift)
  bool start_request = false;             // the driver wants to move (target speed > stop)
  double speed_m_s = 0.0, accel_m_s2 = 0.0, distance_m = 0.0, altitude_m = 0.0;
  double grade = 0.0;                     // rise/run at the vehicle's position [-]
  int gear = 0;                           // 0 = neutral
  DriveMode mode = DriveMode::Neutral;
  bool tc_locked = false;
  double tc_speed_ratio = 0.0;            // ν [-] (1 when locked)
  double tc_pump_torque_Nm = 0.0, tc_turbine_torque_Nm = 0.0;
  double gearbox_input_speed_rad_s = 0.0;
  double aux_power_W = 0.0;               // mechanical aux incl. fan [W]
  double dcdc_input_power_W = 0.0;        // 48 V DC/DC input for the 24 V consumers [W] (hybrid)
  bool gear_changed = false;              // a gear change happened at the start of this step
  bool stop_hold = false;
  // Temperature-dependent losses (of the last macro step):
  double tyre_rr_factor = 1.0;            // f_t(T_amb) on the rolling resistance [-]
  double gearbox_drag_factor = 1.0;       // φ(T_oil) on the gearbox spin losses [-]
  double gearbox_oil_T_K = 0.0, axle_oil_T_K = 0.0;  // oil node temperatures [K]
  double gearbox_oil_heat_W = 0.0;        // loss power into the ATF (drag + load + TC + shift + retarder) [W]
  double axle_oil_heat_W = 0.0;           // axle loss power into its oil [W]
  double gearbox_cooler_W = 0.0;          // ATF cooler heat rejection [W]
  VehicleEnergy energy;
};

class VehicleModel {
 public:
  /// Loads the TC, loss maps (relative paths against base_dir). Throws InputError.
  explicit VehicleModel(const VehicleParams& p, const std::string& base_dir = "");

  /// Initial state: speed [m/s], gear (0 = neutral), engine speed [rad/s] (used in neutral and
  /// 1C; locked gears impose k_g v), distance [m]. Clears energies and controller states.
  void reset(double v_m_s, int gear, double engine_speed_rad_s, double distance_m = 0.0);
  /// Road grade (rise/run) vs the vehicle's own distance [m]; replaces inputs.road_grade.
  void setGradeProfile(const std::vector<double>& distance_m, const std::vector<double>& grade);
  /// Advances by dt_s (the macro step). Throws ModelDivergence on non-finite inputs/state.
  const VehicleOutputs& step(double dt_s, const VehicleInputs& in);
  const VehicleOutputs& outputs() const { return out_; }
  /// Oil temperatures [K] from now on (start:=warm); without this call after reset() both oil
  /// nodes start at the ambient temperature of the first step (a cold start).
  void setOilTemperatures(double gearbox_K, double axle_K);
  const OilThermalNode& gearboxOil() const { return gb_oil_; }
  const OilThermalNode& axleOil() const { return axle_oil_; }

  // Characteristics (for tests and tools).
  double vehicleInertiaMass_kg() const { return inertia_mass_kg_; }  // m + Σ J_wheel / r²
  double kineticEnergy() const;
  const RoadLoad& roadLoad() const { return road_; }
  const TorqueConverter& torqueConverter() const { return tc_; }
  const GearLossMap& gearLossMap() const { return gear_loss_map_; }
  const VehicleParams& params() const { return p_; }
  double ratio(int gear) const { return k_[gear]; }  // k_g = i_g i_a / r [1/m]

 private:
  struct StepConst {  // held over one macro step
    double T_e, T_em, P_aux, F_brake, grade, rho;
    bool engine_on = true;  // false: T_e <= 0 acts as friction -|T_e| sgn(ω_e), T_e > 0 as is
    double rr_factor = 1.0;    // tyre temperature factor f_t on F_roll [-]
    double drag_factor = 1.0;  // cold-oil factor φ on the gearbox spin losses [-]
  };
  struct Rates {
    double T_eng = 0, T_em = 0, T_aux = 0, T_drag = 0, T_pump = 0, T_turb = 0, T_gload = 0;
    double T_drag_in = 0;  // gearbox drag on the input (turbine) shaft in 1C
    double T_ret = 0, T_axl = 0, F_roll = 0, F_aero = 0, F_grade = 0, F_brake = 0;
    double T_clutch = 0;  // on-coming clutch torque during a gear change
    double dw = 0, dv = 0;
  };
  // driveline_dynamics.cpp
  Rates rates(double v, double w, const StepConst& c, int coulomb_dir) const;
  bool held(const StepConst& c, int* dir) const;
  void substep(double h, const StepConst& c, int depth = 0);
  void book(const Rates& r, double v0, double v2, double w0, double w2, double h);
  /// Mode change; gear changes / lock-up start a slip phase when allow_slip (else impulse).
  void transition(const GearState& to, bool allow_slip = true);
  double gearboxInputSpeed(double v, double w) const;
  // vehicle_model.cpp
  void evaluateDriver(double dt, const VehicleInputs& in);
  double auxPower(const VehicleInputs& in) const;
  /// HVAC's load on the crank [W]: compressor + electric / alternator efficiency (alternator sets).
  double hvacCrankPower(const VehicleInputs& in) const;
  /// Splits one macro step's aux work dE_aux_J (at aux power P_aux_W) over the consumers.
  void bookAuxConsumers(double dE_aux_J, double P_aux_W, const VehicleInputs& in);
  /// ATF heat so far: gearbox drag + load loss + converter + shift + retarder [J].
  double gearboxOilHeat_J() const;
  /// Steps both oil nodes with the heat of this macro step (energies since gb_J0 / axle_J0).
  void stepOilNodes(double dt, double gb_J0, double axle_J0, double ambient_T_K);

  VehicleParams p_;
  RoadLoad road_;
  TorqueConverter tc_;
  GearLossMap gear_loss_map_;
  RetarderLoss ret_;
  OilThermalNode gb_oil_, axle_oil_;
  bool oil_set_ = false;  // oil temperatures given (setOilTemperatures) or taken at the first step
  ShiftStrategy shift_;
  Driver driver_;
  Table1D grade_profile_;
  std::vector<double> k_;  // k_[0] unused, k_[g] = i_g i_a / r
  double inertia_mass_kg_ = 0.0;              // m + Σ J_wheel / r² [kg]
  double engine_inertia_kg_m2_ = 0.0;         // engine + torque-converter pump [kg m²]
  double gearbox_input_inertia_kg_m2_ = 0.0;  // gearbox input side [kg m²]
  double axle_ratio_per_radius_1_m_ = 0.0;    // i_a / r: axle speed per vehicle speed [1/m]
  double F_brake_max_ = 0.0;

  // State.
  double v_ = 0.0, w_ = 0.0, s_ = 0.0, h_ = 0.0, t_since_shift_ = kNoShiftYet_s;
  GearState gear_state_;
  double T_in_est_ = 0.0, T_ax_est_ = 0.0;  // transmitted torques (loss evaluation)
  double brake_force_ = 0.0, accel_pedal_ = 0.0, idle_integral_ = 0.0;
  double crank_accel_ = 0.0;  // dω_e/dt over the last macro step (idle governor D) [rad/s²]
  double aux_payback_W_ = 0.0;  // extra steering + compressor power this step (stop-start debt)
  bool hold_ = false, start_request_ = false;
  double last_dv_ = 0.0;
  double s_target_ = 0.0, v_target_prev_ = 0.0;  // ∫ v_target dt (driver's distance reference)
  double shift_slip0_ = 0.0, shift_elapsed_ = 0.0;  // slip phase of a gear change / lock-up
  bool locking_ = false;                            // lock-up clutch slipping (in 1C)
  VehicleOutputs out_;
};

}  // namespace hbt::vehicle
