// 0D multi-zone diesel cylinder, to be connected by the engine assembly to intake and exhaust
// pipe ends through valve boundaries (owned by the gas-dynamics library).
//
// Zones. Mass is accounted in three groups (thermo.hpp): fresh charge AIR (with residual / EGR
// carried as BURNED gas), vaporised FUEL, BURNED gas. While the valves are closed and combustion
// has started, the charge is split into two thermal zones at a common pressure p:
//   unburned zone u = air + residual + fuel vapour at T_u,   burned zone b = products at T_b
// (burned zone: stoichiometric products plus (λ_flame − 1)·AFR_st air per kg fuel burned).
// Otherwise a single zone (T_u) holds everything; the zones merge (energy-conserving) at
// exhaust-valve opening or as soon as a valve flow is reported.
//
// First law of each open zone i (sensible energies, thermo.hpp):
//   dU_i = −p dV_i − δQ_wall,i + Σ_in h dm − Σ_out h dm  (+ δQ_comb = (LHV + h_fg) dm_fb in zone b)
//   p V_i = m_i R_i T_i,   V_u + V_b = V(θ)
// Valve flows: dm = ṁ dt, dH = Ḣ dt (PortFlow, positive into the cylinder); inflow composition
// from its burned fraction. Injection: dm_inj brings (h_FUEL(T_fuel) − h_fg) per kg.
// Combustion: fuel burned per step dm_fb = Σ_pulses m_k Δx_k (double Wiebe of each pulse,
// started at its Livengood–Wu ignition point), limited by the vapour and air available.
// Wall heat (explicit, state at the step start): Q̇ = h_Woschni Σ_s A_s (T − T_s), split between
// zones by volume fraction.
//
// Time integration per (sub)step dt from θ to θ + ω dt: sources explicit, then the zone
// temperatures solve the trapezoidal energy equations
//   m_i u_i(T_i') = U_i* − ½(p + p')(V_i' − V_i),   p' = (Σ m_i R_i T_i')/V',  V_i' = m_i R_i T_i'/p'
// by Newton (1 or 2 unknowns, analytic Jacobian): total energy is conserved exactly per step and
// the compression is second-order accurate. Steps larger than max_substep_deg are sub-stepped with
// the flows held constant. Cost ≈ a few hundred ns per step, no allocation (see README).
//
// Enthalpy convention at the ports: h is the sensible enthalpy of thermo.hpp (zero at 298.15 K).
// The integrator computes inflow Ḣ = ṁ·enthalpyOf(T0_upstream, x_b) and outflow
// Ḣ = ṁ·specificEnthalpy() (ṁ < 0), and removes/adds the same Ḣ on the pipe side.
#pragma once
#include <array>
#include <string>

#include "cylinder/cylinder_params.hpp"
#include "cylinder/equilibrium.hpp"
#include "cylinder/flame_temperature.hpp"
#include "cylinder/hot_zone_no_table.hpp"
#include "cylinder/zeldovich.hpp"

namespace hbt::cylinder {

struct PortFlow {
  double mdot_kg_s = 0.0;    // > 0 into the cylinder
  double Hdot_W = 0.0;       // total enthalpy flow, same sign convention
  double burned_frac = 0.0;  // burned-gas mass fraction of inflowing gas (EGR / backflow)
};
struct PortFlows {
  PortFlow intake;   // sum over the intake valves
  PortFlow exhaust;  // sum over the exhaust valves
};

struct InjectionPulse {
  double soi_deg = 0.0;
  double mass_kg = 0.0;
};
struct InjectionSchedule {
  std::array<InjectionPulse, 3> pulse{};  // pilot, main, post (unused: mass 0)
  double rail_pressure_Pa = 1.5e8;
};

struct CycleResults {
  int index = 0;
  double speed_rpm = 0;
  double work_gross_J = 0, work_net_J = 0;  // ∫p dV over −180…180 and over −360…360
  double imep_gross_Pa = 0, imep_net_Pa = 0, pmep_Pa = 0;
  double pmax_Pa = 0, theta_pmax_deg = 0, Tmax_mean_K = 0, Tmax_burned_K = 0;
  double trapped_mass_kg = 0, trapped_air_kg = 0, residual_frac = 0, lambda = 0;
  double fuel_injected_kg = 0, fuel_burned_kg = 0;
  double heat_release_J = 0;     // LHV × fuel burned (chemical release net of evaporation)
  double heat_wall_J = 0;        // to head + liner + piston (→ coolant/oil)
  double intake_mass_kg = 0, exhaust_mass_kg = 0, exhaust_enthalpy_J = 0;
  double ca10_deg = 0, ca50_deg = 0, ca90_deg = 0;
  double soc_main_deg = 0, ignition_delay_main_deg = 0;
  double no_mass_kg = 0, nox_no2eq_kg = 0;
  double eta_ind_gross = 0, eta_ind_net = 0;
};

class Cylinder {
 public:
  /// params must be finalize()d. name appears in ModelDivergence messages.
  Cylinder(const CylinderParams& params, const std::string& name);

  /// Single-zone state at local crank angle θ [deg, firing TDC = 0].
  void initialize(double theta_deg, double p_Pa, double T_K, double burned_frac);
  /// Fuel per cycle [kg] for the next cycle (latched at IVC; injection from the maps).
  void setFuelPerCycle(double m_kg) { fuel_demand_kg_ = m_kg; }
  void setCoolantTemperature(double T_K) { T_coolant_K_ = T_K; }
  /// Oil temperature of the friction [K]; <= 0: coolant + friction oil_minus_coolant_K.
  void setOilTemperature(double T_K) { T_oil_K_ = T_K; }
  /// Explicit schedule instead of the maps (tests, calibration); latched at IVC.
  void setInjectionOverride(const InjectionSchedule& s) { override_ = s; use_override_ = true; }
  void clearInjectionOverride() { use_override_ = false; }
  void setWallHeatTransfer(bool on) { heat_transfer_on_ = on; }
  void setCombustion(bool on) { combustion_on_ = on; }

  void advance(double dt_s, double omega_rad_s, const PortFlows& flows);

  // --- state for the valve boundaries (mixture of all zones) ---
  double pressure_Pa() const { return p_; }
  double temperature_K() const { return p_ * V_ / mR_; }  // mean: p V / (m R)
  double gasConstant_J_kgK() const;      // mixture R
  double gamma() const;                  // cp/cv of the mixture at the mean temperature
  double specificEnthalpy_J_kg() const;  // enthalpy of the gas leaving through a valve
  double enthalpyOf(double T_K, double burned_frac) const;  // air/burned mixture at T
  double burnedFraction() const;         // burned-gas mass fraction of the whole charge
  double mass_kg() const { return m_; }
  double volume_m3() const { return V_; }
  double dVdtheta_m3_rad() const;
  double crankAngle_deg() const { return theta_deg_; }
  // --- zones ---
  bool twoZone() const { return two_zone_; }
  double unburnedTemperature_K() const { return Tu_; }
  double burnedTemperature_K() const { return two_zone_ ? Tb_ : Tu_; }
  double groupMass(Group g) const { return mu_[g] + mb_[g]; }
  double unburnedGroupMass(Group g) const { return mu_[g]; }
  double burnedZoneGroupMass(Group g) const { return mb_[g]; }
  double speciesMassFraction(Species s) const;  // N2 O2 Ar CO2 H2O, kFuel (unburned HC)
  double noMoles() const { return n_NO_; }
  // --- outputs ---
  double indicatedTorque_Nm() const { return p_ * dVdtheta_m3_rad(); }
  double heatToWall_W() const { return qwall_W_; }
  double fmep_Pa(double omega_rad_s) const;
  double frictionTorque_Nm(double omega_rad_s) const;
  double fuelBurnedThisCycle_kg() const { return acc_.fuel_burned_kg; }
  double heatReleaseThisCycle_J() const { return acc_.heat_release_J; }
  double wallHeatThisCycle_J() const { return acc_.heat_wall_J; }
  double workThisCycle_J() const { return acc_.work_net_J; }
  int cyclesCompleted() const { return cycles_; }
  const CycleResults& lastCycle() const { return last_; }
  const GasThermo& thermo() const { return thermo_; }
  const SliderCrank& crank() const { return crank_; }
  const CylinderParams& params() const { return P_; }
  long noxCvodeSteps() const { return nox_.stepsTaken(); }
  /// Burn law and start of combustion of pulse i (0 pilot, 1 main, 2 post) of the current cycle.
  const DoubleWiebe& pulseWiebe(int i) const { return pulses_.at(i).wiebe; }
  bool pulseIgnited(int i) const { return pulses_.at(i).ignited; }
  double pulseInjected_kg(int i) const { return pulses_.at(i).injected; }

 private:
  struct Pulse {
    double soi = 0, mass = 0, injected = 0, lw = 0, soc = 0, x_prev = 0;
    bool ignited = false, done = false;
    DoubleWiebe wiebe;
  };
  // One crank-angle sub-step: its start state (frozen) and the zone energies that its stages
  // update in turn (sources explicit, then the implicit energy equations).
  struct SubstepState {
    double dt = 0, omega = 0;          // [s], [rad/s]
    double dth = 0, th0 = 0, th1 = 0;  // crank-angle step, start and end [deg]
    bool flowing = false;              // a valve flow is reported (single zone)
    double travel0 = 0, travel1 = 0;   // piston travel at start and end [m]
    double V0 = 0, V1 = 0;             // volume at start and end [m³]
    double p0 = 0;                     // pressure at start [Pa]
    double Vu0 = 0, Vb0 = 0;           // zone volumes at the step start [m³]
    double mR0 = 0;                    // Σ m R at start [J/K]
    double Uu = 0, Ub = 0;             // zone sensible energies, updated by the stages [J]
    double hu0 = 0;                    // specific enthalpy of the charge at start [J/kg]
  };
  void substep(double dt, double omega, const PortFlows& f);
  SubstepState beginSubstep(double dt, double omega, const PortFlows& f);
  void exchangeValveFlows(const PortFlows& f, SubstepState& s);
  void injectFuel(SubstepState& s);
  void advanceIgnitionDelay(const SubstepState& s);
  void burnFuel(SubstepState& s);
  void releaseCombustionHeat(SubstepState& s, double dm_fb, double afr);
  void markBurnAngles(const SubstepState& s, double dm_fb);
  void transferWallHeat(SubstepState& s);
  double wallHeatCoefficient(const SubstepState& s) const;
  void clampUnburnedMasses();
  void solveZoneEnergies(SubstepState& s);
  void mergeConsumedUnburnedZone(SubstepState& s);
  void accumulateCycleResults(const SubstepState& s);
  void hotZoneReactants(const SubstepState& s, double dm_fb);
  void accumulateNox(const SubstepState& s);
  void advanceCrankAngle(const SubstepState& s);
  void onIVC(double omega);
  void onEVO();
  void onCycleEnd(double omega);
  void mergeZones();
  void refreshPolys();  // zone polynomials, mass and m·R after any mass change
  void solveTemperatures(double V0, double V1, double Vu0, double Vb0, double Uu, double Ub);
  void noxInterval();
  void hotZoneInterval();  // nox/model hot_zone: NO of the batch's burned fuel (hot_zone_no.hpp)
  /// Burned-zone state for the NO kinetics over the interval [T_f mean, p mean]: temperature
  /// (dissociated if nox/dissociation), equilibrium mole fractions, and the zone volume
  /// scaled to that state. Returns false if the burned zone is empty.
  bool noxConditions(double T_f, double p, double Vb, double& T, double x[kNumSpecies],
                     double& V);
  void ignite(Pulse& k, double theta_soc, double omega);
  [[noreturn]] void diverged(const char* quantity, double value) const;

  CylinderParams P_;
  std::string name_;
  GasThermo thermo_;
  SliderCrank crank_;
  Equilibrium equil_;      // burned-zone equilibrium at the frozen temperature (no dissociation)
  DissociatedFlame flame_;  // burned-zone equilibrium at the dissociated temperature
  ZeldovichNO nox_;
  HotZoneNOTable hot_zone_;  // declared after P_ and thermo_, which it reads

  double theta_deg_ = -360.0, V_ = 0, p_ = 1e5;
  double mu_[kNumGroups] = {}, mb_[kNumGroups] = {};
  double Tu_ = 300, Tb_ = 300, Vu_ = 0, Vb_ = 0, travel_ = 0;
  Poly Pu_, Pb_;            // extensive zone polynomials of the current masses
  double m_ = 0, mR_ = 0;   // total mass and Σ m R
  double woschni_pre_ = 0;    // multiplier C0 B^−0.2
  double hohenberg_pre_ = 0;  // multiplier C_H
  bool two_zone_ = false, closed_ = false, combustion_started_ = false;
  bool zones_merged_ = false;  // unburned zone consumed this cycle (mergeConsumedUnburnedZone)
  // IVC reference for Woschni
  double pr_ = 1e5, Vr_ = 1e-3, Tr_ = 300, nr_ = 1.35;
  double fuel_demand_kg_ = 0, T_coolant_K_ = 363.15, T_oil_K_ = 0, load_ = 0;
  double Thead_ = 450, Tliner_ = 400, Tpiston_ = 550;
  InjectionSchedule override_{}, sched_{};
  bool use_override_ = false, heat_transfer_on_ = true, combustion_on_ = true;
  std::array<Pulse, 3> pulses_{};
  double deferred_kg_ = 0, fuel_cycle_kg_ = 0, qwall_W_ = 0;
  // NOx: moles in the burned zone and interval accumulators
  double n_NO_ = 0, n_N_ = 0, nox_t_ = 0, nox_Tt_ = 0, nox_pt_ = 0, nox_Vt_ = 0, nox_deg_ = 0;
  // hot zone: fuel burned in the batch [kg] and its fuel-weighted T_u [K kg], p [Pa kg];
  // air mass fraction of the trapped charge (air + residual) at IVC [-]
  double hz_fuel_kg_ = 0, hz_Tu_ = 0, hz_p_ = 0, hz_yair_ivc_ = 0;
  CycleResults acc_{}, last_{};
  int cycles_ = 0;
  double ca_marks_[3] = {0, 0, 0};
  int ca_next_ = 0;
};

}  // namespace hbt::cylinder
