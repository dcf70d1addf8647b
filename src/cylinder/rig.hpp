// Single-cylinder test/calibration rig: one Cylinder between constant-pressure intake and
// exhaust reservoirs, connected by quasi-steady isentropic valve orifices. It stands in for the
// pipes and valve boundaries of the gas-dynamics library so that full four-stroke cycles can run
// in tests and calibration.
//
// Valve lift (per valve, n_v valves):  L(θ) = L_max sin²(π φ/Δ), φ = (θ − θ_open) mod 720 ∈ [0, Δ)
// Effective area:  A_eff = n_v C_d min(π D L, π D²/4)   (curtain area, capped by the port area)
// Orifice flow from the upstream stagnation state (p0, T0, R, γ) to the downstream pressure p2:
//   π = max(p2/p0, π*),  π* = (2/(γ+1))^(γ/(γ−1))
//   ṁ = A_eff p0/sqrt(R T0) · sqrt( 2γ/(γ−1) (π^(2/γ) − π^((γ+1)/γ)) )          [kg/s]
// Inflow carries Ḣ = ṁ h(T_reservoir, x_b,reservoir), outflow Ḣ = ṁ h_cylinder. The exhaust
// reservoir's burned fraction is the mass-averaged burned fraction of the previous cycle's outflow.
#pragma once
#include "cylinder/cylinder.hpp"

namespace hbt::cylinder {

struct ValveProfile {
  double open_deg = 0.0, duration_deg = 220.0, max_lift_m = 0.012, diameter_m = 0.035;
  double count = 2.0, discharge_coeff = 0.70;
  double lift(double theta_deg) const;
  double effectiveArea(double theta_deg) const;
};

/// Isentropic orifice mass flow [kg/s] (≥ 0) from (p0, T0) to p2.
double orificeMassFlow(double A_eff, double p0, double T0, double R, double gamma, double p2);

struct RigParams {
  double speed_rpm = 1400.0;
  double p_intake_Pa = 1.9e5, T_intake_K = 320.0, intake_burned_frac = 0.0;
  double p_exhaust_Pa = 1.75e5, T_exhaust_K = 750.0;
  double fuel_per_cycle_kg = 64e-6;
  double coolant_K = 363.15;
  double step_deg = 0.1;
  ValveProfile intake{350.0, 220.0, 0.0125, 0.036, 2.0, 0.70};
  ValveProfile exhaust{130.0, 240.0, 0.0115, 0.033, 2.0, 0.70};
  void declare(ParamSet& ps);  // keys "cylinder_rig/..."
};

class SingleCylinderRig {
 public:
  SingleCylinderRig(const CylinderParams& cp, const RigParams& rp);
  Cylinder& cylinder() { return cyl_; }
  const RigParams& params() const { return rp_; }
  /// Advances one step of step_deg; returns the flows applied.
  PortFlows step();
  /// Runs whole cycles; returns the last completed cycle.
  CycleResults runCycles(int n);
  /// Runs until IMEP and trapped mass change by less than tol between cycles (≤ max_cycles).
  CycleResults runToPeriodic(int max_cycles, double tol);
  double exhaustBurnedFraction() const { return xb_exh_; }

 private:
  PortFlow valveFlow(const ValveProfile& v, double p_res, double T_res, double xb_res) const;
  RigParams rp_;
  Cylinder cyl_;
  double xb_exh_ = 0.3, out_m_ = 0.0, out_mxb_ = 0.0;
};

}  // namespace hbt::cylinder
