// Engine1D: the crank-angle-resolved 1D gas-dynamic engine (SPEC §3) behind the same kind of
// interface as engine_map::MapEngine, so a ROS node only forwards inputs and outputs.
//
//   Engine1D eng(Engine1DParams::load(repo_root), repo_root);
//   eng.reset(speed_rad_s, torque_Nm, ambient_T_K);
//   const Engine1DOutputs& o = eng.step(dt_macro_s, inputs);
//
// One step(): controllers (controllers.hpp) from the previous step's cycle means -> fuel per
// cylinder-cycle and wastegate opening; then EngineAssembly::advance(dt, w) (many coupled
// gas-dynamic/cylinder steps, engine_assembly.hpp); then the outputs.
// Output definitions (all SI):
//   brake torque     T_b = <T_ind> - <T_f>: one-cycle (720 deg) moving mean of the indicated
//                    torque sum_k dW_k/dt / w minus the Chen-Flynn friction torque
//   crank torque     T_c = (W_ind - W_f)/(w dt): the mean over the macro step (the exact energy
//                    exchange with the crank, compression pulses resolved); at w = 0 the gas
//                    torque sum_k p_k dV_k/dtheta less the friction torque. What the twin's
//                    crank sees while the engine is off (engine_1d_model.hpp)
//   flows            one-cycle means (fuel: injected mass / time; air: compressor delivery;
//                    exhaust: downpipe outlet into the back-pressure reservoir)
//   exhaust T        <H_out>/(<mdot_out> cp_exh) at the downpipe outlet (total temperature)
//   composition      mass fractions of the cylinders' outflow over the last cycle: burned
//                    fraction x_b -> y_s = (1-x_b) Y_air,s + x_b Y_burned,s; y_NOx = NOx/exhaust
//   lambda           global: <mdot_air>/(AFR_st <mdot_fuel>) (0 when no fuel)
//   NOx              engine-out NO as NO2 (Zeldovich, released at exhaust-valve opening)
//   heat             friction P_f = <T_f> w, wall heat <Q_wall>: into the oil f_o P_f, into the
//                    metal <Q_wall> + (1 - f_o) P_f (common/friction_heat.hpp), all of it
//   back pressure    input if > 0, else p_amb + K_b <mdot_exh>^2 T/p (orifice law of the ATS)
// Limits: full-load and motoring torque from the reference (map) curve at w.
// Any crank speed w >= 0 (engine_assembly.hpp; below 1e-6 rad/s the crank stands, w = 0): the
// gas dynamics, turbocharger and cylinders run down to standstill and at rest (the gas relaxes in
// time); the means are over one cycle or, when a cycle takes longer than
// numerics/cycle_window_max_s (below 400 rpm), over that time.
// Errors: InputError (file, key) at construction; ModelDivergence naming the element (pipe, cell,
// volume, cylinder, turbine, shaft) in step(); every output is checked finite.
#pragma once
#include <memory>
#include <string>

#include "common/units.hpp"
#include "engine_1d/controllers.hpp"
#include "engine_1d/engine_assembly.hpp"
#include "engine_map/map_engine.hpp"

namespace hbt::engine_1d {

struct Engine1DInputs {
  double speed_rad_s = 0.0;        // imposed crank speed [rad/s]
  double torque_request_Nm = 0.0;  // requested brake torque [Nm]
  double ambient_T_K = 298.15;     // [K]
  double ambient_p_Pa = units::kStandardAtmosphere_Pa;  // [Pa]
  double back_pressure_Pa = 0.0;   // turbine-outlet system back pressure [Pa]; <= 0: default model
  double coolant_T_K = 363.15;     // [K]
  double oil_T_K = 0.0;            // friction oil [K]; <= 0: coolant + cylinder friction/oil_minus_coolant_K
  bool fuel_enabled = true;        // false: fuel cut / engine off
};

struct ExhaustComposition {  // mass fractions [-]
  double y_O2 = 0, y_N2 = 0, y_CO2 = 0, y_H2O = 0, y_Ar = 0, y_NOx = 0;
};

struct Engine1DOutputs {
  double brake_torque_Nm = 0;          // one-cycle mean (see header)
  double crank_torque_Nm = 0;          // mean over the last macro step (see header)
  double indicated_torque_Nm = 0;      // one-cycle mean, net (incl. pumping)
  double friction_torque_Nm = 0;       // Chen-Flynn
  double fuel_mass_flow_kg_s = 0;
  double fuel_mass_kg = 0;             // cumulative since reset
  double fuel_per_cycle_kg = 0;        // commanded, per cylinder
  double boost_pressure_Pa = 0;        // intake plenum, cycle mean
  double boost_target_Pa = 0;
  double intake_manifold_T_K = 0;
  double turbo_speed_rad_s = 0;
  double wastegate_opening = 0;        // [0, 1]
  double lambda = 0;
  double air_mass_flow_kg_s = 0;
  double exhaust_mass_flow_kg_s = 0;   // turbine outlet system -> aftertreatment
  double exhaust_T_K = 0;
  ExhaustComposition exhaust;
  double back_pressure_Pa = 0;
  double nox_mass_flow_kg_s = 0;       // engine-out, as NO2
  double nox_mass_kg = 0;              // cumulative
  double coolant_heat_W = 0;           // into the metal: wall heat + the metal's friction share [W]
  double coolant_heat_J = 0;           // cumulative
  double oil_heat_W = 0;               // friction heat into the oil [W]
  double oil_heat_J = 0;               // cumulative
  double friction_W = 0;               // friction work rate <T_f> w [W]
  double peak_cylinder_pressure_Pa = 0;  // max over cylinders of the last completed cycles
  double turbine_inlet_p_Pa = 0, turbine_inlet_T_K = 0;  // cycle means, mean of both entries
  double max_torque_Nm = 0, min_torque_Nm = 0;           // reference full-load / motoring at w
  double brake_work_J = 0;     // sum of T_b w dt over macro steps (T_b the published torque) [J]
  double positive_work_J = 0;  // its positive part [J]
  double motoring_work_J = 0;  // its negative part (<= 0) [J]
  bool fuel_cut = false, smoke_limited = false;
  double cpu_time_s = 0;               // thread CPU time of this step
  double cpu_time_total_s = 0;         // since reset
  double sim_time_s = 0;               // since reset
  long gas_steps = 0;                  // coupled steps since reset
};

class Engine1D {
 public:
  /// Builds the turbocharger (maps under repo_root/../shared/data/turbo), the reference map
  /// engine and the assembly. Throws InputError (file, key).
  Engine1D(const Engine1DParams& p, const std::string& repo_root);
  ~Engine1D();

  /// Restarts at speed w [rad/s] with an initial state estimated for torque T [Nm].
  void reset(double speed_rad_s, double torque_Nm = 0.0, double ambient_T_K = 298.15,
             double ambient_p_Pa = units::kStandardAtmosphere_Pa, double coolant_T_K = 363.15);
  const Engine1DOutputs& step(double dt_macro_s, const Engine1DInputs& in);
  const Engine1DOutputs& outputs() const { return out_; }

  double fullLoadTorque(double w) const { return ref_->fullLoadTorque(w); }
  double motoringTorque(double w) const { return ref_->motoringTorque(w); }
  const engine_map::MapEngine& reference() const { return *ref_; }
  const Engine1DParams& params() const { return P_; }
  EngineAssembly& assembly() { return *asm_; }
  const EngineAssembly& assembly() const { return *asm_; }
  const ControlCommand& command() const { return cmd_; }

 private:
  void computeOutputs(double dt, double w, const Engine1DInputs& in);
  void computeCrankTorque(double w);
  Engine1DParams P_;
  std::unique_ptr<turbo::Turbocharger> tc_;
  std::unique_ptr<engine_map::MapEngine> ref_;
  EngineAssembly::FlowMaps maps_;
  std::unique_ptr<EngineAssembly> asm_;
  std::unique_ptr<EngineControllers> ctl_;
  ControlCommand cmd_;
  Engine1DOutputs out_;
  double back_p_ = 0.0;
};

}  // namespace hbt::engine_1d
