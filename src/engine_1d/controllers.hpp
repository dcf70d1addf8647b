// Engine controllers of the 1D engine (ECU functions, evaluated once per macro step).
//
// Torque (fuel) controller — injected fuel per cylinder and cycle m_f [kg]:
//   T_req' = clamp(T_req, T_mot(w), T_fl(w))                  (reference full-load curve)
//   m_ff   = F_ref(w, T_req') / (z w/(4 pi))                  feed-forward from the reference
//            map's steady fuel flow F_ref [kg/s], z = engine_1d/cylinders, w/(4 pi) cycles per second
//   m_f    = clamp(m_ff + PI(T_model - T_b), 0, m_smoke),  |PI| <= fuel_trim_max m_ff,rated
//   T_model = the brake torque expected from the past requests T_req' (torque_response_model.hpp:
//            dead angle torque_dead_angle_deg, then the one-cycle mean like T_b), so the PI trims
//            the feed-forward's steady error (1D engine vs reference map) and not the response
//            time of the engine: with the error T_req' - T_b it integrated the ~0.13 s (700 rpm)
//            lag of every request change and overshot by ~40 % of a step (engine_1d README "Torque control")
//   m_smoke = m_air,cyc / (lambda_smoke AFR_st)             smoke limiter on the cycle-mean air
//            flow per cylinder-cycle m_air,cyc = mdot_air / (z w/(4 pi))
//   fuel cut (m_f = 0, integrator cleared) if fuel is disabled or T_req <= T_mot.
//   The integrator is frozen while the smoke limit holds the output and the error pushes further.
// Boost (wastegate) controller — opening a in [0, 1] (0 = closed) of the wastegate on entry 0:
//   p_target = PR_map(n [rpm], T_req'/T_fl) p_amb             (bilinear table, clamped)
//   a = clamp(PI(p_boost - p_target), 0, 1)                   (too much boost -> open)
// T_b and p_boost are the one-cycle means of the brake torque and the intake-plenum pressure.
// Injection timing (SOI), pilot and rail pressure come from the cylinder model's maps over speed
// and load (cylinder/injection/*, latched at inlet-valve closure).
#pragma once
#include "common/units.hpp"
#include "common/pid.hpp"
#include "common/table2d.hpp"
#include "cylinder/cylinder_params.hpp"
#include "engine_1d/engine_1d_params.hpp"
#include "engine_1d/torque_response_model.hpp"

namespace hbt::engine_1d {

struct ControlInputs {
  double omega = 0;              // [rad/s]
  double torque_request = 0;     // [Nm] (raw)
  double full_load = 0;          // T_fl(w) [Nm]
  double motoring = 0;           // T_mot(w) [Nm] (< 0)
  double brake_torque = 0;       // cycle mean [Nm]
  double boost = 0;              // cycle-mean intake manifold pressure [Pa]
  double ambient_p = units::kStandardAtmosphere_Pa;   // [Pa]
  double air_flow = 0;           // cycle-mean air mass flow [kg/s]
  double feedforward_fuel_kg_s = 0;  // F_ref(w, T_req') [kg/s]
  bool fuel_enabled = true;
};

struct ControlCommand {
  double fuel_per_cycle_kg = 0;  // per cylinder
  double feedforward_kg = 0;     // m_ff
  double smoke_limit_kg = 0;     // m_smoke
  bool smoke_limited = false;
  bool fuel_cut = false;
  double wastegate_opening = 0;
  double boost_target_Pa = 0;
  double torque_target_Nm = 0;   // T_req'
  double torque_model_Nm = 0;    // T_model: the brake torque expected now from the past T_req'
};

class EngineControllers {
 public:
  EngineControllers(const Engine1DConfig& cfg, double afr_stoich, double fuel_ref_kg);
  /// Starts the integrators so that the outputs equal the feed-forward and `wastegate_opening`,
  /// the torque response model in steady state at torque_Nm (the clamped request of the reset).
  void reset(double wastegate_opening, double torque_Nm);
  ControlCommand update(double dt, const ControlInputs& in);
  double boostTarget(double omega, double load, double p_amb) const;  // [Pa]
  /// Clamped torque request T_req' [Nm].
  static double limitedRequest(double req, double full_load, double motoring);

 private:
  Engine1DConfig cfg_;
  Table2D boost_;
  Pid fuel_pid_, wg_pid_;
  TorqueResponseModel torque_model_;
  double afr_, fuel_ref_;
};

}  // namespace hbt::engine_1d
