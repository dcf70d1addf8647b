// Energy manager of the 48 V P1 hybrid: each step it splits the driver's crank torque demand
// between the engine and the crank-mounted e-machine, blends regenerative and friction braking,
// and stops/restarts the engine at standstill. ROS-free; the node only converts messages.
//
// Torques are at the crankshaft [Nm], speeds ω [rad/s], powers [W]. Per step, in this order:
//
// 1. Stop-start state machine RUNNING -> STOPPED -> CRANKING -> RUNNING:
//    stop when the bus stands held in neutral, the engine and the ATS are warm (warm-up inhibit,
//    SPEC §6), SOC >= soc_min_to_stop, the battery offers min_discharge_power_W and the engine
//    has run min_on_time_s; restart when the driver wants to go or SOC < soc_restart or the
//    engine cools below coolant_warm_K (cabin heating at 0 °C); cranking: engine_on = false and
//    T_em = min(crank_torque, T_em,max live, P_dis η_m/ω) until ω >= firing_speed, then fuel on.
// 2. Regenerative braking first (gear locked, ω >= min_engine_speed, driver brakes with T_b at
//    the wheels, i = i_g i_a):  T_regen = min(-T_em,min live, P_chg/(ω η_g), T_b / i)
//    T_em = -T_regen,   friction brake T_f = T_b - i T_regen  (>= 0),   engine request = demand
//    (the engine motors, fuel cut).
// 3. Otherwise adaptive ECMS: over a grid of T_em in [T_lo, T_hi]
//    J(T_em) = ṁ_f(ω, T_d - T_em) LHV + s P_el(T_em),
//    P_el = T_em ω / η_m (T_em > 0), T_em ω η_g (T_em < 0)          [W, > 0 from the battery]
//    s = clamp(s0 + kp (SOC* - SOC) + ki ∫(SOC* - SOC) dt, s_min, s_max)
//    T_hi = min(T_em,max live, P_dis f_T η_m / ω, T_d - T_e,min)  (0 while warming up, SOC < soc_min)
//    T_lo = max(T_em,min live, -P_chg / (ω η_g), T_d - T_e,max)   (0 above soc_max)
//    f_T = clamp((T_zero - T_bat)/(T_zero - T_start), 0, 1): assist fades 40 -> 45 °C.
//    ṁ_f(ω, T) is the controller's engine model (a steady fuel map, FuelModel); the plant may be
//    the map or the 1D engine.
//    Battery bounds: the pack's power limits less a margin (battery/limit_margin: they move over
//    the step) and less its other DC load (P_dcdc) are what the
//    e-machine may draw or return. With an EmLimitModel the bound is the torque whose DC power by
//    the e-machine's own loss model meets it exactly (bisection, 1e-6 Nm), so the battery is never
//    asked beyond its limits; without one, the controller's constant efficiencies above.
//    T_em,max/min live: the limits valid for the step commanded. With an EmLimitModel they are
//    evaluated at this step's crank speed ω, the DC voltage the e-machine will use (the battery's
//    latest terminal voltage) and its winding/magnet temperatures at the step start: the very
//    limits the e-machine clamps with, so a request inside them is never clamped. Without one,
//    the limits the e-machine published for the previous step (at its speed and voltage: a
//    request may then exceed the live limit by the change over one step). The minimiser of J is taken (ties: the smallest |T_em|); |T_em| <
//    min_boost_torque is set to 0.
// Every decision carries a Mode and a Reason (published; see the enums).
#pragma once
#include <cstdint>

#include "ems/ems_params.hpp"

namespace hbt::ems {

// Engine on-time [s] at a reset: the engine is running and has been for longer than any minimum
// on-time (stop-start may stop it at once).
constexpr double kRunningForever_s = 1e9;

/// The controller's engine model: steady fuel flow [kg/s] at crank speed [rad/s] and brake
/// torque [Nm] (0 at or below the motoring torque). Implemented over the VECTO map by the node.
class FuelModel {
 public:
  virtual ~FuelModel() = default;
  virtual double fuelRate_kg_s(double speed_rad_s, double torque_Nm) const = 0;
};

/// The controller's model of the e-machine's live torque limits at the crank [Nm]: max >= 0 and
/// min <= 0 at crank speed [rad/s], DC voltage [V], winding and magnet temperatures [K].
/// Implemented over the e-machine model by the node (the function the e-machine clamps with).
class EmLimitModel {
 public:
  virtual ~EmLimitModel() = default;
  virtual void liveLimits(double crank_speed_rad_s, double dc_voltage_V, double winding_T_K, double magnet_T_K,
                          double& max_Nm, double& min_Nm) const = 0;
  /// DC power [W] (> 0 drawn) of crank torque T [Nm] at crank speed [rad/s], voltage [V] and
  /// winding temperature [K]: the e-machine's own loss model (machine, inverter, ratio stage).
  virtual double dcPower_W(double crank_torque_Nm, double crank_speed_rad_s, double dc_voltage_V,
                           double winding_T_K, double magnet_T_K) const = 0;
};

enum class Mode : uint8_t { EngineOnly = 0, Boost = 1, Regen = 2, LoadPointShift = 3, Stopped = 4, Cranking = 5 };
enum class Reason : uint8_t {
  EcmsOptimum = 0,        // ECMS minimum inside the limits
  WarmupInhibit = 1,      // engine or ATS warming up: no boost, no stop
  BatteryHot = 2,         // assist faded by battery temperature (>= 40 °C)
  SocLow = 3,             // SOC below soc_min: no boost
  SocHigh = 4,            // SOC above soc_max: no charging by load-point shift
  EmLimit = 5,            // the e-machine's live (derated) limit bounds the optimum / regen
  BatteryLimit = 6,       // the battery's power limit bounds the optimum / regen
  StandstillStop = 8,     // (7 unused: regen short of the demand names its limit, 5 or 6)     // engine stopped at standstill
  DriveOff = 9,           // restart: the driver wants to go
  SocRestart = 10,        // restart: SOC fell below soc_restart
  CooledRestart = 11,     // restart: the coolant fell below coolant_warm_K
  NotConnected = 12,      // converter open / neutral / shifting / low speed: no regen
  StopStartDisabled = 13, // standing but stop-start is off (config stop_start/enabled)
  Overrun = 14,           // no traction demand: engine motoring, EM idle
  ClimateRequest = 15,    // standing, no stop / restart: the HVAC's belt-driven A/C needs the engine
};

struct EmsInputs {
  // from the vehicle (DriverDemand)
  double crank_torque_demand_Nm = 0.0;
  double wheel_brake_demand_Nm = 0.0;
  double engine_speed_rad_s = 0.0;
  double crank_to_wheel_ratio = 0.0;  // i_g i_a when locked, else 0
  bool stopped = false, start_request = false;
  double engine_max_torque_Nm = 0.0, engine_min_torque_Nm = 0.0;
  // from the e-machine: its published live limits at the crank [Nm] (of the previous step) and
  // its temperatures at the step start [K]
  double em_max_torque_Nm = 0.0, em_min_torque_Nm = 0.0;
  double em_winding_T_K = 298.15, em_magnet_T_K = 298.15;
  // DC voltage the e-machine steps with: the battery's latest terminal voltage [V]
  double dc_voltage_V = 48.0;
  // the pack's other DC load (the DC/DC converter to the 24 V net) [W], drawn beside the e-machine
  double dcdc_power_W = 0.0;
  // from the battery
  double soc = 0.5, battery_T_K = 298.15, discharge_limit_W = 0.0, charge_limit_W = 0.0;
  // warm-up state (cooling, aftertreatment); without the thermal nodes: warm
  double coolant_T_K = 363.15, scr_T_K = 573.15;
  // from the hvac (hvac:=on): its A/C compressor is on the belt and the cabin is too warm
  bool climate_run_request = false;
};

struct EmsDecision {
  double engine_torque_request_Nm = 0.0;
  double em_torque_request_Nm = 0.0;
  double friction_brake_Nm = 0.0;      // at the wheels
  bool engine_on = true;
  Mode mode = Mode::EngineOnly;
  Reason reason = Reason::EcmsOptimum;
  double equivalence_factor = 0.0;     // s used this step [-]
  double cost_W = 0.0;                 // J at the chosen split [W of fuel power]
  bool warm = false;                   // engine and ATS warm
  // cumulative counters since reset()
  int engine_stops = 0, engine_starts = 0;
  double stopped_time_s = 0.0, cranking_time_s = 0.0, warmup_inhibit_time_s = 0.0;
};

class EmsModel {
 public:
  /// em_limits: the e-machine's limit model (nullptr: the published limits, see above); it must
  /// outlive the EmsModel.
  EmsModel(const EmsParams& p, const FuelModel& fuel, const EmLimitModel* em_limits = nullptr);
  /// Engine running, counters and the SOC integral cleared.
  void reset();
  /// Decides the split for the next step of length dt_s [s]. Throws ModelDivergence on
  /// non-finite inputs or a start that exceeds max_crank_time_s.
  const EmsDecision& step(double dt_s, const EmsInputs& in);
  const EmsDecision& decision() const { return d_; }
  double equivalenceFactor(double soc) const;  // s without the integral part (for tests)

 private:
  enum class State { Running, Stopped, Cranking };
  /// The inputs with the e-machine's limits valid for this step (EmLimitModel, see above).
  EmsInputs withLiveLimits(const EmsInputs& in) const;
  const EmsDecision& decide(double dt_s, const EmsInputs& in);
  /// The crank torque within [0, T_em] (T_em > 0 motoring, < 0 generating) whose DC power stays
  /// within the battery's share P_avail_W >= 0 (drawn when motoring, returned when generating).
  double batteryBound(double T_em_Nm, double P_avail_W, const EmsInputs& in) const;
  /// The e-machine's share of the pack's discharge (charge) limit [W]: the limit less the margin
  /// battery/limit_margin, less (plus) the DC/DC's draw; f_T the assist fade.
  double dischargeShare_W(const EmsInputs& in, double f_T) const;
  double chargeShare_W(const EmsInputs& in) const;
  void regen(const EmsInputs& in);
  void ecms(const EmsInputs& in, bool warm, double dt_s);

  EmsParams p_;
  const FuelModel& fuel_;
  const EmLimitModel* em_limits_ = nullptr;
  State state_ = State::Running;
  double soc_integral_ = 0.0, on_time_s_ = kRunningForever_s, crank_time_s_ = 0.0;
  EmsDecision d_;
};

}  // namespace hbt::ems
