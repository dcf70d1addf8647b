// Burn-rate, ignition-delay and injection sub-models (pure functions, no allocation).
//
// Wiebe law of one combustion mode, normalised so that it reaches exactly 1 at θ_f:
//   τ = (θ − θ_i)/(θ_f − θ_i),  x(θ) = (1 − exp(−a τ^(m+1))) / (1 − exp(−a))   for 0 ≤ τ ≤ 1,
//   x = 0 before θ_i, x = 1 after θ_f;  dx/dθ = a (m+1) τ^m exp(−a τ^(m+1)) / ((1−e^−a)(θ_f−θ_i)).
//   Inverse: θ(x) = θ_i + (θ_f − θ_i) (−ln(1 − x (1 − e^−a)) / a)^(1/(m+1)).
// (a = 6.908 gives 99.9 % at θ_f in the un-normalised form; normalising moves x by < 0.1 %.)
// Double Wiebe (premixed + diffusive):  x_b = β x_1(θ) + (1 − β) x_2(θ).
//
// Ignition delay, Hardenberg & Hase (SAE 790493), in crank-angle degrees:
//   τ_id = (0.36 + 0.22 c_m) exp[E_A (1/(R_u T) − 1/17190) (21.2/(p − 12.4))^0.63],
//   E_A = 618 840/(CN + 25) J/mol, p in bar, T in K, c_m in m/s.
// Used in Livengood–Wu form: ignition when ∫ dt/τ_id(p(t),T(t)) = 1 with τ_id in seconds.
// Premixed fraction, Watson (SAE 800029):  β = 1 − 0.926 φ^0.37 / τ_id[ms]^0.26, clipped to [0, 1].
//
// Injection rate through the nozzle (incompressible orifice):
//   ṁ_inj = C_d n_h (π d_h²/4) sqrt(2 ρ_f (p_rail − p_cyl))   [kg/s].
#pragma once

namespace hbt::cylinder {

struct Wiebe {
  double theta_i_deg = 0.0;   // start
  double duration_deg = 1.0;  // θ_f − θ_i
  double a = 6.908;
  double m = 2.0;
  double x(double theta_deg) const;
  double rate(double theta_deg) const;  // 1/deg
  double inverse(double x) const;       // deg
};

struct DoubleWiebe {
  double beta = 0.0;  // premixed fraction
  Wiebe premixed, diffusive;
  double x(double theta_deg) const { return beta * premixed.x(theta_deg) + (1 - beta) * diffusive.x(theta_deg); }
  double rate(double theta_deg) const {
    return beta * premixed.rate(theta_deg) + (1 - beta) * diffusive.rate(theta_deg);
  }
  double end_deg() const;
};

/// Hardenberg–Hase ignition delay [deg CA].
double hardenbergHaseDelayDeg(double p_Pa, double T_K, double cm_m_s, double cetane);
/// Watson premixed fraction for overall equivalence ratio φ and ignition delay [ms].
double watsonPremixedFraction(double phi, double tau_ms);

struct Nozzle {
  int holes = 8;
  double hole_diameter_m = 0.15e-3;
  double discharge_coeff = 0.75;
  double fuel_density_kg_m3 = 830.0;
  double massRate(double p_rail_Pa, double p_cyl_Pa) const;  // kg/s
};

}  // namespace hbt::cylinder
