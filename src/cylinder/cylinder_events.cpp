// Cycle events of the Cylinder: inlet-valve closure (reference state, injection schedule),
// ignition of a pulse (double-Wiebe parameters), exhaust-valve opening (NO frozen, zones merged),
// end of cycle (per-cycle results), and the batched NO kinetics.
#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "cylinder/cylinder.hpp"

namespace hbt::cylinder {
namespace {
constexpr double kM_NO = 30.0061e-3, kM_NO2 = 46.0055e-3;
}  // namespace

void Cylinder::onIVC(double omega) {
  closed_ = true;
  zones_merged_ = false;
  combustion_started_ = false;
  deferred_kg_ = 0.0;
  pr_ = p_;
  Vr_ = V_;
  Tr_ = temperature_K();
  nr_ = gamma();
  acc_.trapped_mass_kg = mass_kg();
  acc_.trapped_air_kg = groupMass(kAir);
  acc_.residual_frac = burnedFraction();
  // The flame entrains the charge as trapped (air + residual, uniformly mixed); the unburned
  // zone's own air fraction falls during the burn because the two-zone bookkeeping takes only air
  // into the burned zone, so the hot zone uses the trapped charge's air fraction.
  {
    const double gas = mu_[kAir] + mu_[kBurned];
    hz_yair_ivc_ = gas > 0.0 ? mu_[kAir] / gas : 0.0;
  }
  // (ω·30)/π, not units::radpsToRpm(ω) = ω/(π/30): a last-bit difference in the rpm of the
  // injection maps moves the 1D engine's NOx by ~1e-7 (relative) in a 20 s Urban run.
  const double rpm = omega * 30.0 / units::kPi;
  if (use_override_) {
    sched_ = override_;
  } else {
    const double m = std::max(fuel_demand_kg_, 0.0);
    const double L = m / P_.fuel_ref_kg;
    const double soi = P_.soi_main(rpm, L);
    const double mp = std::clamp(P_.pilot_frac(rpm, L), 0.0, 0.5) * m;
    const double mpo = std::clamp(P_.post_frac(rpm, L), 0.0, 0.5) * m;
    sched_.rail_pressure_Pa = P_.rail_pressure(rpm, L) * 1e5;
    sched_.pulse[0] = {soi - P_.pilot_dwell(rpm, L), mp};
    sched_.pulse[1] = {soi, std::max(m - mp - mpo, 0.0)};
    sched_.pulse[2] = {soi + P_.post_offset(rpm, L), mpo};
  }
  fuel_cycle_kg_ = 0.0;
  for (std::size_t i = 0; i < pulses_.size(); ++i) {
    pulses_[i] = Pulse();
    pulses_[i].soi = sched_.pulse[i].soi_deg;
    pulses_[i].mass = combustion_on_ ? sched_.pulse[i].mass_kg : 0.0;
    fuel_cycle_kg_ += pulses_[i].mass;
  }
  load_ = fuel_cycle_kg_ / P_.fuel_ref_kg;
  P_.walls.evaluate(T_coolant_K_, load_, Thead_, Tliner_, Tpiston_);
  n_NO_ = n_N_ = 0.0;
  nox_t_ = nox_Tt_ = nox_pt_ = nox_Vt_ = nox_deg_ = 0.0;
  hz_fuel_kg_ = hz_Tu_ = hz_p_ = 0.0;
  ca_next_ = 0;
  ca_marks_[0] = ca_marks_[1] = ca_marks_[2] = 0.0;
}

void Cylinder::ignite(Pulse& k, double theta_soc, double omega) {
  const double rpm = omega * 30.0 / units::kPi, L = load_;  // as in onIVC()
  const double deg_per_s = omega / units::kRad_per_deg;
  k.ignited = true;
  k.soc = theta_soc;
  k.x_prev = 0.0;
  const double tau_ms = 1e3 * (theta_soc - k.soi) / deg_per_s;
  const double phi = acc_.trapped_air_kg > 0.0
                         ? thermo_.afrStoich() * fuel_cycle_kg_ / acc_.trapped_air_kg
                         : 1.0;
  // Watson premixed fraction, at most the share of the pulse injected before ignition.
  const double beta = std::min(watsonPremixedFraction(phi, tau_ms), k.injected / k.mass);
  const double rate = P_.nozzle.massRate(sched_.rail_pressure_Pa, p_);
  const double remaining_deg = rate > 0.0 ? (k.mass - k.injected) / rate * deg_per_s : 0.0;
  k.wiebe.beta = beta;
  k.wiebe.premixed = {theta_soc, P_.premix_dur(rpm, L), P_.wiebe_a, P_.premix_m(rpm, L)};
  k.wiebe.diffusive = {theta_soc,
                       P_.diffusion_injection_factor * remaining_deg + P_.diff_tail(rpm, L),
                       P_.wiebe_a, P_.diff_m(rpm, L)};
  // The largest pulse is the "main" for the reported ignition delay.
  const Pulse* main = &pulses_[0];
  for (const auto& q : pulses_)
    if (q.mass > main->mass) main = &q;
  if (&k == main) {
    acc_.soc_main_deg = theta_soc;
    acc_.ignition_delay_main_deg = theta_soc - k.soi;
  }
  combustion_started_ = true;
}

// The batch's burned fuel at its fuel-weighted reactant state forms one hot-zone packet whose NO
// is frozen into the cylinder's NO (hot_zone_no.hpp).
void Cylinder::hotZoneInterval() {
  nox_deg_ = 0.0;
  if (!(hz_fuel_kg_ > 0.0)) return;
  const double m = hz_fuel_kg_, T_u = hz_Tu_ / m, p = hz_p_ / m;
  hz_fuel_kg_ = hz_Tu_ = hz_p_ = 0.0;
  const double n = hot_zone_.noMoles(m, T_u, hz_yair_ivc_, p, P_.nox_min_temperature_K);
  if (!(n >= 0.0) || !std::isfinite(n)) diverged("hot-zone NO (flame temperature)", T_u);
  n_NO_ += n;
}

void Cylinder::noxInterval() {
  if (P_.nox_hot_zone) {
    hotZoneInterval();
    return;
  }
  if (nox_t_ <= 0.0) return;
  const double T_f = nox_Tt_ / nox_t_, p = nox_pt_ / nox_t_, Vb_f = nox_Vt_ / nox_t_;
  double T, Vb, x[kNumSpecies];
  if (noxConditions(T_f, p, Vb_f, T, x, Vb)) {
    nox_.setConditions(T, p, x);
    double cNO = n_NO_ / Vb, cN = n_N_ / Vb;
    nox_.integrate(nox_t_, cNO, cN, true);
    if (!(cNO >= 0.0) || !std::isfinite(cNO)) diverged("NO concentration", cNO);
    n_NO_ = cNO * Vb;
    n_N_ = cN * Vb;
  }
  nox_t_ = nox_Tt_ = nox_pt_ = nox_Vt_ = nox_deg_ = 0.0;
}

// Stages: element moles and frozen mass fractions of the burned zone; its equilibrium at the
// frozen temperature T_f, or (nox/dissociation) at the dissociated temperature of the same
// enthalpy (flame_temperature.hpp); the zone volume at that state, V = V_f n T/(n_f T_f) at the
// same pressure, so that concentrations and the zone's NO moles agree.
bool Cylinder::noxConditions(double T_f, double p, double Vb_f, double& T, double x[kNumSpecies],
                             double& V) {
  double mb = 0.0;
  std::array<double, 5> b{};
  double Y[kNumSpecies] = {};
  for (int g = 0; g < kNumGroups; ++g) {
    mb += mb_[g];
    for (int e = 0; e < 5; ++e) b[e] += mb_[g] * thermo_.elements(Group(g))[e];
    for (int s = 0; s < kNumSpecies; ++s) Y[s] += mb_[g] * thermo_.massFraction(Group(g), Species(s));
  }
  if (!(mb > 0.0 && Vb_f > 0.0)) return false;
  for (double& v : b) v /= mb;
  for (double& v : Y) v /= mb;
  T = T_f;
  V = Vb_f;
  if (!P_.nox_dissociation) {
    if (!equil_.solve(b, T_f, p, x)) {
      equil_.reset();
      if (!equil_.solve(b, T_f, p, x)) diverged("burned-zone equilibrium", T_f);
    }
    return true;
  }
  DissociatedFlame::Result r;
  if (!flame_.solve(b, Y, T_f, p, r)) {
    flame_.reset();
    if (!flame_.solve(b, Y, T_f, p, r)) diverged("dissociated burned-zone temperature", T_f);
  }
  double n_f = 0.0;
  for (int s = 0; s < kNumSpecies; ++s) n_f += Y[s] / species(Species(s)).M;
  T = r.T_K;
  for (int s = 0; s < kNumSpecies; ++s) x[s] = r.x[s];
  V = Vb_f * (r.n_mol_kg * T) / (n_f * T_f);
  return true;
}

void Cylinder::mergeZones() {
  if (!two_zone_) return;
  if (nox_t_ > 0.0 || hz_fuel_kg_ > 0.0) noxInterval();
  const double U = Pu_.u(Tu_) + Pb_.u(Tb_);
  const double Tguess = (Pu_.R * Tu_ + Pb_.R * Tb_) / (Pu_.R + Pb_.R);
  for (int g = 0; g < kNumGroups; ++g) {
    mu_[g] += mb_[g];
    mb_[g] = 0.0;
  }
  refreshPolys();
  const Poly& P = Pu_;
  const double T = temperatureFromU(P, U, Tguess);
  if (!(T > 0.0)) diverged("temperature after zone merge", T);
  Tu_ = Tb_ = T;
  two_zone_ = false;
  Vu_ = V_;
  Vb_ = 0.0;
  p_ = P.R * T / V_;
}

void Cylinder::onEVO() {
  if (nox_t_ > 0.0 || hz_fuel_kg_ > 0.0) noxInterval();
  acc_.no_mass_kg = n_NO_ * kM_NO;
  acc_.nox_no2eq_kg = n_NO_ * kM_NO2;
  mergeZones();
  closed_ = false;
}

void Cylinder::onCycleEnd(double omega) {
  const double Vd = crank_.displacement();
  acc_.index = ++cycles_;
  acc_.speed_rpm = units::radpsToRpm(omega);
  acc_.imep_gross_Pa = acc_.work_gross_J / Vd;
  acc_.imep_net_Pa = acc_.work_net_J / Vd;
  acc_.pmep_Pa = acc_.imep_gross_Pa - acc_.imep_net_Pa;
  acc_.lambda = acc_.fuel_injected_kg > 0.0
                    ? acc_.trapped_air_kg / (thermo_.afrStoich() * acc_.fuel_injected_kg)
                    : 0.0;
  const double Qf = acc_.fuel_injected_kg * P_.fuel.lhv_J_kg;
  acc_.eta_ind_gross = Qf > 0.0 ? acc_.work_gross_J / Qf : 0.0;
  acc_.eta_ind_net = Qf > 0.0 ? acc_.work_net_J / Qf : 0.0;
  acc_.ca10_deg = ca_marks_[0];
  acc_.ca50_deg = ca_marks_[1];
  acc_.ca90_deg = ca_marks_[2];
  last_ = acc_;
  acc_ = CycleResults();
  theta_deg_ -= 720.0;
}

}  // namespace hbt::cylinder
