// Euro VI aftertreatment system DOC -> DPF -> SCR -> ASC of the bus engine: brick temperatures,
// DOC oxidation, urea dosing, SCR NH3 storage and NOx reduction, NH3 slip catalyst, pressure drop
// (engine back-pressure), energy and nitrogen balances. ROS-free, deterministic, no allocation in
// step(). The bus's node is src/aftertreatment/node.
//
// Per step (inputs held over dt; walls and bricks swept in flow direction):
//  0. Exhaust line upstream of the DOC (ExhaustLine, exhaust_line.hpp): exhaust manifold, turbine
//     housing, down-pipe, pipe to the one-box, the box's inlet chamber -- lumped walls that store
//     heat, take it from the gas and lose it outside. The engine publishes the turbine-outlet
//     gas; the manifold and turbine-housing walls exchange heat with that gas (the only state
//     the engine publishes), the engine models are unchanged.
//  1. DOC, per slice i at wall temperature T_i, residence time tau_i = V_s / Vdot_i with
//     Vdot_i = F_tot R T_i / p (F_tot total molar flow, p brick pressure of the last step):
//       CO, HC: X = 1 - exp(-k(T_i) tau_i), k(T) = k_ref exp(-E/R (1/T - 1/T_ref)) [1/s]
//         (first-order light-off: the conversion depends on T and on the space velocity
//          SV = Vdot/V through k/SV; k_ref set so that CO/HC light off (50 %) near 200/230 degC
//          at SV ~ 50,000 1/h, Russell & Epling, "Diesel oxidation catalysts", Catal. Rev. 53 (2011));
//       NO + 1/2 O2 <-> NO2: NO2/NOx relaxes towards the equilibrium fraction
//         f_eq = K sqrt(p_O2) / (1 + K sqrt(p_O2)), K = exp(-(dH - T dS)/(R T)) [atm^-1/2],
//         dH = -57.1 kJ/mol, dS = -73.2 J/(mol K), at the rate k_f + k_r, k_r = k_f / (K sqrt(p_O2)):
//         f_out = f_eq + (f_in - f_eq) exp(-(k_f + k_r) tau_i);
//       heat released on the slice: 283 kJ/mol CO, LHV x HC, 57.1 kJ/mol NO2 formed.
//  2. DPF: soot deposition and NO2 oxidation per slice (SootFilter, soot_filter.hpp: passive
//     regeneration, the NO2 consumed reaches the SCR as NO), its reaction heat, the thermal model,
//     wall-flow pressure drop at the current soot load. Then the box's mixer section (DPF outlet
//     cone, decomposition mixer, SCR inlet cone) as one lumped wall.
//  3. Urea dosing at the SCR inlet (after the mixer wall): if the gas entering the SCR is at or above the release
//     temperature, NH3 feed = ANR_eff * NOx feed [mol/s] with
//       ANR_eff = anr s,  s = clamp((fill_stop - phi)/(fill_stop - fill_start), 0, 1),
//     phi = stored NH3 / target, target = Omega V sum_i theta_eq(T_i, ref_nh3_ppm)/N (the Temkin
//     equilibrium storage, falling with T): a proportional storage controller -- a store below
//     fill_start x target is fed at ANR = anr, dosing falls to zero as the store reaches
//     fill_stop x target, and in steady state s settles where the feed equals consumption + slip.
//     Urea = NH3/2 (CO(NH2)2 + H2O -> 2 NH3 + CO2); AdBlue = urea / 0.325. Evaporating and
//     decomposing the AdBlue takes adblue_heat_J_kg from the gas (counted as (negative) reaction
//     heat); the mass of the AdBlue is not added to the gas (< 0.3 % of the exhaust).
//  4. SCR: ScrStorage (NH3 storage + standard/fast SCR + NH3 oxidation, Runge-Kutta 5(4)).
//  5. ASC: NH3 -> N2 (selectivity 1), X = 1 - exp(-k_asc(T_i) tau_i), 316.8 kJ/mol NH3; then
//     the box's outlet chamber as one lumped wall (the tailpipe gas leaves it).
//  6. Pressure: from the tailpipe (ambient) upstream: muffler + pipes K rho u_pipe^2/2, then each
//     brick at its mean gas temperature (Brick::pressureDrop): back-pressure at the turbine outlet
//     p_bp = p_amb + sum dp (the pipe between turbine and DOC is not counted separately).
// The thermal model of every brick is Brick (brick.hpp). Reaction heat is computed with the wall
// temperatures at the start of the step and deposited over the step (explicit coupling).
//
// Balances (cumulative, exact up to round-off / solver tolerance):
//   energy: H_in - H_out - Q_can - Q_line + Q_reaction - dE_wall = 0,
//     H = mdot cp(T_in) (T - 298.15 K) dt with cp of the step frozen at the inlet temperature and
//     composition, H_in at the turbine outlet, H_out at the tailpipe, Q_line the outer losses of
//     the line walls, dE_wall the change of the bricks' and the line walls' energy;
//   soot:   captured = stored - stored_0 + burnt (CO2 + CO), engine-out = captured + slip;
//   NOx:    NO2 reduced on the soot = NO formed (NOx moles unchanged by the DPF);
//   NH3:    dosed = stored - stored_0 + reacted (standard + 2 x fast + 4/3 NO2-SCR) + oxidised (SCR)
//           + slip (SCR).
// SCR light-off: first time at which the filtered SCR NOx conversion 1 - F_out/F_in >= 50 %
// (F = NOx mass flows low-passed with lightoff/filter_s), with F_in >= lightoff/min_nox_kg_s and
// the SCR mean wall temperature >= the dosing release temperature (the brick is warm).
#pragma once
#include "common/units.hpp"
#include <array>
#include <memory>
#include <vector>

#include "aftertreatment/ats_params.hpp"
#include "aftertreatment/brick.hpp"
#include "aftertreatment/exhaust_line.hpp"
#include "aftertreatment/gas.hpp"
#include "aftertreatment/scr_storage.hpp"
#include "aftertreatment/soot_filter.hpp"

namespace hbt::aftertreatment {

enum BrickId { kDOC = 0, kDPF = 1, kSCR = 2, kASC = 3, kNumBricks = 4 };
/// The three parts of the exhaust line: before the DOC, between DPF and SCR, after the ASC.
enum LinePart { kLineUpstream = 0, kLineMixer = 1, kLineOutlet = 2, kNumLineParts = 3 };

struct AtsInputs {
  double exhaust_mass_flow_kg_s = 0.0;  ///< [kg/s]
  double exhaust_T_K = 298.15;          ///< gas at the turbine outlet [K]
  GasComposition comp;                  ///< mass fractions [-]
  double nox_mass_flow_kg_s = 0.0;      ///< engine-out NOx as NO2 [kg/s]
  double hc_mass_flow_kg_s = 0.0;       ///< [kg/s]
  double co_mass_flow_kg_s = 0.0;       ///< [kg/s]
  double ambient_T_K = 298.15;
  double ambient_p_Pa = units::kStandardAtmosphere_Pa;
  double vehicle_speed_m_s = 0.0;
};

/// Cumulative energy terms since reset() [J].
struct AtsEnergy {
  double enthalpy_in_J = 0.0, enthalpy_out_J = 0.0, can_loss_J = 0.0;
  double line_loss_J = 0.0;      ///< outer losses of the exhaust-line walls
  double reaction_heat_J = 0.0;  ///< released in the walls minus AdBlue evaporation
  double stored_change_J = 0.0;  ///< wall energy change since reset (bricks and line)
  double residual_J() const {
    return enthalpy_in_J - enthalpy_out_J - can_loss_J - line_loss_J + reaction_heat_J - stored_change_J;
  }
};

/// Cumulative soot and NO2-soot counters since reset().
struct AtsSoot {
  double engine_out_kg = 0.0;       ///< soot entering the DPF
  double captured_kg = 0.0;         ///< deposited in the DPF
  double slip_kg = 0.0;             ///< passing the DPF
  double burnt_kg = 0.0;            ///< carbon oxidised by NO2 (to CO2 and CO)
  double carbon_co2_mol = 0.0, carbon_co_mol = 0.0;
  double no2_to_no_mol = 0.0;       ///< NO2 reduced to NO on the soot
  double stored_change_kg = 0.0;    ///< soot in the DPF now - at reset
  double residual_kg() const { return captured_kg - burnt_kg - stored_change_kg; }
};

/// Cumulative NH3 / NOx counters since reset() [mol].
struct AtsNitrogen {
  double nh3_dosed_mol = 0.0;
  double nh3_stored_change_mol = 0.0;  ///< stored now - stored at reset
  double nh3_scr_reacted_mol = 0.0;    ///< consumed by standard, fast and NO2 SCR
  double nh3_scr_oxidised_mol = 0.0;
  double nh3_scr_slip_mol = 0.0;       ///< leaving the SCR
  double nh3_asc_oxidised_mol = 0.0;
  double nh3_tailpipe_mol = 0.0;
  double nox_scr_in_mol = 0.0, nox_scr_out_mol = 0.0;
  double residual_mol() const {
    return nh3_dosed_mol - nh3_stored_change_mol - nh3_scr_reacted_mol - nh3_scr_oxidised_mol -
           nh3_scr_slip_mol;
  }
};

struct AtsOutputs {
  std::array<double, kNumBricks> brick_T_K{};      ///< mean wall temperature per brick
  std::array<double, kNumBricks> brick_out_T_K{};  ///< gas leaving each brick
  std::array<double, kNumBricks> brick_dp_Pa{};    ///< pressure drop per brick
  double muffler_dp_Pa = 0.0;
  double outlet_T_K = 298.15;             ///< tailpipe gas temperature (after the outlet chamber)
  double doc_inlet_T_K = 298.15;          ///< gas entering the DOC (after the upstream line)
  double scr_inlet_T_K = 298.15;          ///< gas entering the SCR (after mixer and dosing)
  double scr_inlet_no2_fraction = 0.0;    ///< NO2/NOx entering the SCR (after the soot) [-]
  double soot_mass_kg = 0.0;              ///< soot in the DPF
  double soot_load_g_L = 0.0;             ///< soot per litre of DPF
  double back_pressure_Pa = units::kStandardAtmosphere_Pa;     ///< absolute, turbine outlet
  double tailpipe_nox_kg_s = 0.0, tailpipe_nox_kg = 0.0;   ///< as NO2
  double engine_nox_kg = 0.0;
  double nh3_slip_kg_s = 0.0, nh3_slip_kg = 0.0;           ///< at the tailpipe (after ASC)
  double adblue_kg_s = 0.0, adblue_kg = 0.0;               ///< AdBlue (32.5 % urea) dosed
  double urea_kg = 0.0;                                    ///< pure urea dosed
  double nox_conversion = 0.0;            ///< SCR, step average [-]
  double nox_conversion_filtered = 0.0;   ///< SCR, low-passed (light-off criterion) [-]
  double doc_no2_fraction = 0.0;          ///< NO2/NOx leaving the DOC [-]
  double doc_co_conversion = 0.0;
  double nh3_stored_mol = 0.0;
  double anr = 0.0;                       ///< NH3/NOx feed ratio of the step
  bool light_off = false;
  double light_off_time_s = -1.0;         ///< -1 until light-off
};

/// The SCR kinetics and brick heat-transfer parameters of an AtsParams.
ScrKinetics scrKinetics(const AtsParams& p);
HeatTransferParams heatTransfer(const AtsParams& p);

class Aftertreatment {
 public:
  explicit Aftertreatment(const AtsParams& p);

  /// Cold start: every brick (substrate, washcoat, can) at T_K, SCR coverage from the parameters.
  void reset(double T_K, double ambient_p_Pa = units::kStandardAtmosphere_Pa);
  /// Warm start: every brick at brick_T_K, the SCR's NH3 store at nh3_fill x the dosing's storage
  /// target at that temperature (storageTarget_mol: equilibrium with dosing/ref_nh3_ppm), the
  /// same coverage in every slice; balances count from this state.
  void resetWarm(double brick_T_K, double nh3_fill, double ambient_p_Pa = units::kStandardAtmosphere_Pa);
  /// Advances by dt [s]. Throws ModelDivergence (naming brick and quantity) on a non-physical
  /// state or input.
  void step(double dt, const AtsInputs& in);

  const AtsOutputs& outputs() const { return out_; }
  const AtsEnergy& energy() const { return energy_; }
  const AtsNitrogen& nitrogen() const { return n_; }
  const AtsSoot& soot() const { return soot_; }
  const Brick& brick(int b) const { return *bricks_[b]; }
  const ExhaustLine& line(int part) const { return *line_[part]; }
  const SootFilter& sootFilter() const { return *filter_; }
  const ScrStorage& scr() const { return *scr_; }
  const AtsParams& params() const { return p_; }
  double time() const { return t_; }
  /// Pressure drop of brick b for a mass flow at temperature T and pressure p (tests, reports).
  PressureDrop brickPressureDrop(int b, double mdot_kg_s, double T_K, double p_Pa,
                                 const GasComposition& g = {}) const;
  /// NH3 storage target used by the dosing rule [mol].
  double storageTarget_mol() const;

 private:
  // The quantities of one step that its stages pass on (inputs held over dt).
  struct StepState {
    double dt = 0;                          // [s]
    double mdot = 0, cp = 0;                // exhaust mass flow [kg/s], cp at the inlet [J/(kg K)]
    double M = 0, R = 0;                    // molar mass [kg/mol], gas constant [J/(kg K)]
    double n_tot = 0, mcp = 0;              // molar flow [mol/s], mdot cp [W/K]
    double Tamb = 0, v = 0;                 // ambient [K], vehicle speed [m/s]
    double x_O2 = 0;                        // O2 mole fraction [-]
    double n_NOx = 0, n_NO2 = 0;            // NOx and NO2 leaving the DOC [mol/s]
    double n_NH3 = 0, adblue = 0;           // NH3 dosed [mol/s], AdBlue [kg/s]
    double Q_adblue = 0, T_scr_in = 0;      // evaporation heat [W], gas entering the SCR [K]
    ScrStepResult scr{};                    // SCR amounts of the step [mol]
    double nox_in_mol = 0, nox_out_mol = 0; // NOx into and out of the SCR over the step [mol]
    double n_slip = 0, n_slip_in = 0;       // NH3 leaving and entering the ASC [mol/s]
    double co2_kg_s = 0;                    // CO2 in the exhaust (engine-out soot) [kg/s]
    double T_tailpipe = 0;                  // gas leaving the outlet chamber [K]
    SootStep soot{};                        // DPF soot amounts of the step
    BrickEnergy e[kNumBricks]{};            // energy terms of each brick's thermal step
    BrickEnergy e_line[kNumLineParts]{};    // energy terms of each line part's step
    double Tg_in[kNumBricks]{}, Tg_out[kNumBricks]{};  // gas entering / leaving each brick [K]
  };
  static void checkStepInputs(double dt, const AtsInputs& in);
  StepState beginStep(double dt, const AtsInputs& in) const;
  void stepUpstreamLine(const AtsInputs& in, StepState& s);
  void stepDoc(const AtsInputs& in, StepState& s);
  void stepDpf(StepState& s);
  void doseUrea(StepState& s);
  void stepScr(StepState& s);
  void stepAsc(StepState& s);
  void updateBackPressure(const AtsInputs& in, const StepState& s);
  void accumulateBalances(const AtsInputs& in, const StepState& s);
  void accumulateSoot(const StepState& s);
  void updateOutputs(const StepState& s);
  void updateLightOff(const AtsInputs& in, const StepState& s);
  double energyStored() const;
  AtsParams p_;
  DpfFlowParams dpf_;
  std::array<std::unique_ptr<Brick>, kNumBricks> bricks_;
  std::unique_ptr<ScrStorage> scr_;
  std::array<std::unique_ptr<ExhaustLine>, kNumLineParts> line_;
  std::unique_ptr<SootFilter> filter_;
  std::vector<double> qr_, heat_J_, T_wall_;
  std::array<double, kNumBricks> p_brick_{};  ///< mean pressure in each brick (last step)
  AtsOutputs out_;
  AtsEnergy energy_;
  AtsNitrogen n_;
  AtsSoot soot_;
  double soot0_kg_ = 0.0;
  double t_ = 0.0, E0_ = 0.0, stored0_ = 0.0, F_in_ = 0.0, F_out_ = 0.0, T_amb_last_ = 298.15;
};

}  // namespace hbt::aftertreatment
