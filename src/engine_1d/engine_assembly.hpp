// Gas-dynamic assembly of the n-cylinder engine (SPEC §3: n = 6), crank-angle resolved.
//
// Layout (two gasdyn networks, intake air gamma 1.4, exhaust gamma 1.33; they exchange gas only
// through the cylinders):
//   air-filter box (reservoir: p_1 = p_amb - K_af mdot^2 T/p, T_amb)
//     -> CompressorOutlet (turbo compressor map) -> compressor-outlet pipe (hot)
//     -> ChargeAirCoolerLink (air-to-air, eps(mdot), cooling air at T_amb, dp = K mdot^2 T/p)
//     -> charge-air duct pipe -> intake plenum (Volume) -> n runners -> Valve (2 intake valves)
//     -> cylinder k (0D, src/cylinder; seen by the valves as a reservoir at its p, T)
//     -> Valve (2 exhaust valves) -> exhaust runner k -> bank collector b(k) (Volume)
//     -> turbine-inlet pipe -> TurbineEntry 0 (with wastegate) / 1 -> turbine-outlet Volume
//     -> downpipe -> back-pressure reservoir (input, or p_amb + K_b mdot^2 T/p).
// Cylinders (config engine_1d/cylinders, firing_order, exhaust_bank): n cylinders, the j-th of
// the firing order at engine crank angle phase = j 720/n deg (cylinder 1 of a 1-5-3-6-2-4 six at
// 0), b(k) = exhaust_bank[k] - 1 (shipped: cylinders 1-3 -> entry 0, 4-6 -> entry 1). Sized once
// at construction; nothing is allocated in a step.
// Turbo shaft: J w dw/dt = eta_m P_t - P_c - k_f w^2 (turbo::TurboShaft), P_t and P_c the
// boundaries' powers, stepped with the network step.
//
// Coupled step of length dt (explicit, first order in the coupling; the cylinder state is
// frozen during one network step):
//   dt = min(CFL step of both networks, coupling_max_deg/omega,
//            coupling_cylinder_cfl min_k V_k/(c_k sum A_valve,eff,k))   (cylinderDt())
//   1. every cylinder's p, T -> its two valve reservoirs; turbo speed -> turbomachine boundaries
//   2. both networks advance one step (valve fluxes from the pipe end states at t)
//   3. each cylinder advances by dt (sub-steps of <= cylinder_substep_deg; outflow enthalpy
//      re-evaluated per sub-step) with the port flows it received: mdot_k = -pipe end flux,
//      inflow enthalpy mdot h_cyl(T0, x_b) with T0 = E/(mdot cp_pipe) from the face energy flux,
//      outflow mdot h_cyl (cylinder mixture); x_b of back flows: intake runners keep the mass
//      pushed back at IVO (buffer), exhaust back flow takes the bank's mean burned fraction
//   4. shaft step, one-cycle window accumulation (cycle_window.hpp)
// Mass is exchanged exactly; the enthalpy basis differs between the pipes (cp T, constant cp)
// and the cylinder (NASA polynomials, zero at 298.15 K): the port energy balance is therefore
// done in the cylinder's thermodynamics (EnergyTotals).
// Indicated torque from the exact work increments of the cylinders (trapezoidal p dV):
//   T_ind = sum_k dW_k/(omega dt);  friction T_f = sum_k FMEP_k V_d/(4 pi) (Chen-Flynn).
// Any crank speed omega >= 0 (the engine stopped, spinning down or cranked): the CFL steps of
// the networks do not depend on omega, the crank-angle cap (coupling_max_deg/omega) is then
// infinite; at omega = 0 the crank angle stands, the valves keep their areas, the gas relaxes
// in time and T_ind is the instantaneous gas torque sum_k p_k dV_k/dtheta (the limit of
// dW/(omega dt)). Per advance() the work of the interval (lastInterval()): the crank's energy
// exchange with the engine, W_ind - W_f = integral (T_ind - T_f) omega dt.
// Held rest (numerics/rest_hold_after_s, rest_hold_flow_kg_s): once the crank has stood for
// rest_hold_after_s and the cycle-mean air and exhaust flows are below rest_hold_flow_kg_s, the
// gas has reached the model's own steady state at rest (no piston motion; Woschni's and the
// pipes' Reynolds-analogy wall heat vanish at zero velocity; trapped gas keeps p and T) up to
// the explicit valve coupling's limit cycle (README "Stop and restart"). advance() then holds
// every gas state instead of stepping it: no coupled steps, the window records zero flows and
// the standing gas torque; the turbocharger coasts down on its bearing friction (a coasting
// wheel with no flow does no work). The hold ends when the crank moves or
// a boundary pressure (air-filter box, back pressure) moves by more than kHoldPressureTol_Pa
// from its value at the start of the hold; the gas then relaxes again for rest_hold_after_s.
#pragma once
#include "common/units.hpp"
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "cylinder/cylinder.hpp"
#include "engine_1d/cycle_window.hpp"
#include "engine_1d/engine_1d_params.hpp"
#include "engine_1d/gas_exchange.hpp"
#include "engine_1d/turbo_adapters.hpp"
#include "gasdyn/network.hpp"
#include "turbo/turbo_config.hpp"

namespace hbt::engine_1d {

/// Channels of the one-cycle window (rates; means over the last 720 deg).
enum Channel {
  kIndTorque, kFricTorque, kFuel, kAir, kExhOut, kExhEnth, kBoost, kImT, kP3, kT3, kWallHeat,
  kNox, kBurnedOut, kCylOut, kBankOut0, kBankOut1, kBankBurned0, kBankBurned1, kNumChannels
};

struct CycleMeans {
  std::array<double, kNumChannels> v{};
  double operator[](int c) const { return v[c]; }
};

/// Cumulative energy bookkeeping at the cylinder ports (cylinder thermodynamics) [J], [kg].
struct EnergyTotals {
  double fuel_kg = 0, fuel_energy_J = 0;  // injected, LHV
  double indicated_work_J = 0, friction_work_J = 0, wall_heat_J = 0;
  double intake_enthalpy_J = 0, exhaust_enthalpy_J = 0;  // net into the cylinders / out of them
  double nox_kg = 0;
};

class EngineAssembly {
 public:
  /// Uniform initial state: boost p_im [Pa], T_im [K], exhaust p3 [Pa], T3 [K], turbo speed
  /// [rad/s], ambient p [Pa], T [K]; cylinder k at its phase of the firing order.
  struct Initial {
    double p_im = 1.2e5, T_im = 310.0, p3 = 1.3e5, T3 = 700.0, turbo_rad_s = 4000.0;
    double p_amb = units::kStandardAtmosphere_Pa, T_amb = 298.15, fuel_per_cycle_kg = 0.0, coolant_K = 363.15;
  };
  /// Flow maps tabulated once per turbocharger (shared between resets).
  struct FlowMaps {
    std::shared_ptr<CompressorFlowMap> compressor;
    std::array<std::shared_ptr<TurbineFlowMap>, 2> turbine;  // entry 0 with the wastegate
    static FlowMaps build(const turbo::Turbocharger& tc);
  };
  EngineAssembly(const Engine1DParams& p, const turbo::Turbocharger& tc, const FlowMaps& maps,
                 const Initial& init);
  EngineAssembly(const EngineAssembly&) = delete;
  EngineAssembly& operator=(const EngineAssembly&) = delete;

  /// Advances by `interval` [s] at crank speed omega >= 0 [rad/s] (many coupled steps).
  void advance(double interval, double omega);
  /// Work of the last advance(): indicated (p dV) and friction [J], its duration [s].
  struct Interval {
    double indicated_J = 0.0, friction_J = 0.0, duration_s = 0.0;
  };
  const Interval& lastInterval() const { return interval_; }
  /// True while the gas at rest is held (header "Held rest"; the last advance() took no step).
  bool restHeld() const { return held_; }
  /// Boundary pressure change that ends a held rest [Pa] (header "Held rest"): 0.1 % of an
  /// atmosphere. The back pressure the aftertreatment returns moves with the engine's own
  /// residual flow (its bricks' laminar drop, 2-10 Pa at 0.1-0.5 g/s): the hold's zero flow must
  /// not end it; a change of 100 Pa moves the held gas states by < 0.1 %.
  static constexpr double kHoldPressureTol_Pa = 100.0;
  /// Instantaneous indicated (gas) torque sum_k p_k dV_k/dtheta at the present crank angle [Nm].
  double gasTorque_Nm() const;
  /// Largest coupled step [s] at omega [rad/s] from the current state; `limiter` (if given,
  /// allocates): the limiting pipe/volume/boundary, "crank-angle cap" or "cylinder valves".
  double stableDt(double omega, std::string* limiter = nullptr) const;

  // --- inputs between steps ---
  void setFuelPerCycle(double m_kg);
  void setCoolantTemperature(double T_K);
  void setOilTemperature(double T_K);           // friction oil; <= 0: coolant + offset
  void setAmbient(double p_Pa, double T_K);     // air-filter box and intercooler cooling air
  void setBackPressure(double p_Pa, double T_K);
  void setWastegateOpening(double a);
  void setCombustion(bool on);

  // --- state / outputs ---
  void cycleMeans(CycleMeans& m) const { window_.mean(m.v); }
  bool windowFull() const { return window_.fullCycle(); }
  const EnergyTotals& totals() const { return totals_; }
  double frictionTorque() const { return fric_torque_; }  // [Nm] at the last speed
  double turboSpeed() const { return shaft_.omega(); }     // [rad/s]
  double compressorMassFlow() const;                       // instantaneous [kg/s]
  double intakeManifoldPressure() const { return plenum_->p(); }
  double peakPressureLastCycles() const;                   // max of the cylinders' last pmax
  double intercoolerHeat() const { return cac_->heatRemoved(); }
  double wastegateOpening() const { return turb_map_[0]->wastegateOpening(); }
  double airFilterPressure() const { return filter_->p(); }
  long steps() const { return steps_; }
  double time() const { return t_; }
  int cylinders() const { return static_cast<int>(cyl_.size()); }
  /// Swept volume of all cylinders [m^3].
  double displacement_m3() const;
  /// Firing angle of cylinder i (0-based) on the engine crank [deg]: its firing TDC when the
  /// engine crank (cylinder 1's firing TDC = 0) is there.
  double firingPhase_deg(int i) const { return cyl_[i].phase_deg; }
  const cylinder::Cylinder& cylinder(int i) const { return *cyl_[i].cyl; }
  cylinder::Cylinder& cylinder(int i) { return *cyl_[i].cyl; }
  gasdyn::Network& intakeNetwork() { return intake_; }
  gasdyn::Network& exhaustNetwork() { return exhaust_; }
  const Engine1DParams& params() const { return P_; }
  /// Mass-weighted burned fraction of the gas leaving the cylinders over the last cycle.
  double exhaustBurnedFraction() const;

 private:
  void build(const Initial& init);
  double cylinderDt(double omega) const;  // explicit cylinder/valve coupling limit [s] (inf: off)
  gasdyn::Pipe& pipe(gasdyn::Network& n, const std::string& name, const PipeSpec& s,
                     double friction, bool hot);

  /// One cylinder with its valves, runners and bookkeeping (elements owned by the networks).
  struct CylinderSlot {
    std::unique_ptr<cylinder::Cylinder> cyl;
    double phase_deg = 0.0;  // firing angle on the engine crank [deg]
    int bank = 0;            // turbine entry / bank collector (0, 1)
    gasdyn::Volume *res_in = nullptr, *res_ex = nullptr;  // the cylinder as its valves see it
    CrankValveArea *area_in = nullptr, *area_ex = nullptr;
    gasdyn::Pipe *run_in = nullptr, *run_ex = nullptr;
    double back_m = 0.0, back_xb = 0.0;  // intake back-flow buffer [kg], burned fraction [-]
    double prev_work = 0.0, prev_wall = 0.0, prev_inj = 0.0;  // at the last step [J], [J], [kg]
    int prev_cycles = 0;
  };
  /// Sums over the cylinders of one coupled step.
  struct StepSums {
    double work_J = 0.0, wall_J = 0.0;     // indicated work, wall heat [J]
    double fuel_kg = 0.0, nox_kg = 0.0;    // fuel injected, NOx (as NO2) of cycles ended [kg]
  };
  void coupledStep(double dt, double omega);
  void stepNetworks(double dt, double omega);
  double intakePortFlow(CylinderSlot& s, double dt, cylinder::PortFlow& pf);
  double exhaustPortFlow(const CylinderSlot& s, cylinder::PortFlow& pf,
                         std::array<double, kNumChannels>& x) const;
  void advanceCylinder(CylinderSlot& s, double dt, double omega, int nsub_closed, int nsub_open,
                       std::array<double, kNumChannels>& x);
  void accumulateCylinder(CylinderSlot& s, StepSums& sums);
  void stepTurboShaft(double dt);
  void accumulateTotals(const StepSums& sums, double dt, double omega);
  void recordStep(const StepSums& sums, double dt, double omega, std::array<double, kNumChannels>& x);
  void gasStateChannels(std::array<double, kNumChannels>& x) const;  // boost, T_im, p3, T3
  bool holdsRest(double omega);  // header "Held rest": starts, keeps or ends the hold
  void holdRest(double interval);

  Engine1DParams P_;
  const turbo::Turbocharger& tc_;
  turbo::TurboShaft shaft_;
  gasdyn::Network intake_, exhaust_;
  std::vector<CylinderSlot> cyl_;  // engine_1d/cylinders of them, sized by the constructor
  // elements (owned by the networks)
  gasdyn::Volume *filter_ = nullptr, *plenum_ = nullptr, *turb_out_ = nullptr, *back_ = nullptr;
  std::array<gasdyn::Volume*, 2> junction_{};
  gasdyn::Pipe *comp_pipe_ = nullptr, *cac_pipe_ = nullptr, *down_pipe_ = nullptr;
  std::array<gasdyn::Pipe*, 2> turb_pipe_{};
  gasdyn::CompressorOutlet* comp_ = nullptr;
  std::array<gasdyn::TurbineEntry*, 2> turb_{};
  gasdyn::OpenEnd* back_end_ = nullptr;
  ChargeAirCoolerLink* cac_ = nullptr;
  std::shared_ptr<CompressorFlowMap> comp_map_;
  std::array<std::shared_ptr<TurbineFlowMap>, 2> turb_map_;
  CycleWindow<kNumChannels> window_;
  EnergyTotals totals_;
  Interval interval_;
  double fric_torque_ = 0.0, t_ = 0.0, T_amb_ = 298.15, cp_in_ = 1004.5, cp_ex_ = 1160.0;
  double xb_bank_[2] = {0.3, 0.3};
  double substep_deg_ = 2.0;       // cylinder sub-step, valves closed (IVC..EVO) [deg crank]
  double substep_open_deg_ = 2.0;  // cylinder sub-step, a valve open [deg crank]
  long steps_ = 0;
  double standing_s_ = 0.0;  // time the crank has stood (omega = 0) before this advance() [s]
  bool held_ = false;        // the gas at rest is held (header "Held rest")
  double held_filter_p_ = 0.0, held_back_p_ = 0.0;  // boundary pressures at the hold's start [Pa]
};

}  // namespace hbt::engine_1d
