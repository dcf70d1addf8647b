#include "cylinder/cylinder.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::cylinder {

Cylinder::Cylinder(const CylinderParams& params, const std::string& name)
    : P_(params),
      name_(name),
      thermo_(params.fuel, params.constant_cp, params.constant_cp_T_K),
      crank_(params.geometry),
      hot_zone_(thermo_, params.nox_hot_zone_residence_s) {
  if (P_.soi_main.empty()) P_.finalize();
  woschni_pre_ = P_.woschni.multiplier * P_.woschni.C0 * std::pow(P_.geometry.bore_m, -0.2);
  hohenberg_pre_ = P_.woschni.multiplier * P_.woschni.hohenberg_C;
  initialize(-360.0, 1e5, 300.0, 0.0);
}

void Cylinder::initialize(double theta_deg, double p, double T, double xb) {
  if (!(p > 0 && T > 0 && xb >= 0 && xb <= 1))
    throw InputError(name_, "initial state", "need p > 0, T > 0, 0 <= burned fraction <= 1");
  theta_deg_ = wrapCycleDeg(theta_deg);
  travel_ = crank_.travel(units::degToRad(theta_deg_));
  V_ = crank_.clearanceVolume() + crank_.pistonArea() * travel_;
  const double R = (1 - xb) * thermo_.group(kAir).R + xb * thermo_.group(kBurned).R;
  const double m = p * V_ / (R * T);
  mu_[kAir] = m * (1 - xb);
  mu_[kFuelVap] = 0.0;
  mu_[kBurned] = m * xb;
  for (double& x : mb_) x = 0.0;
  refreshPolys();
  Tu_ = Tb_ = T;
  p_ = p;
  Vu_ = V_;
  Vb_ = 0.0;
  two_zone_ = false;
  combustion_started_ = false;
  closed_ = theta_deg_ >= P_.ivc_deg && theta_deg_ < P_.evo_deg;
  pr_ = p;
  Vr_ = V_;
  Tr_ = T;
  nr_ = gamma();
  for (auto& k : pulses_) k = Pulse();
  deferred_kg_ = 0.0;
  n_NO_ = n_N_ = 0.0;
  nox_t_ = nox_Tt_ = nox_pt_ = nox_Vt_ = nox_deg_ = 0.0;
  hz_fuel_kg_ = hz_Tu_ = hz_p_ = 0.0;
  hz_yair_ivc_ = 0.0;
  acc_ = CycleResults();
  load_ = fuel_demand_kg_ / P_.fuel_ref_kg;
  P_.walls.evaluate(T_coolant_K_, load_, Thead_, Tliner_, Tpiston_);
}

void Cylinder::refreshPolys() {
  Pu_ = mixturePoly(thermo_, mu_);
  Pb_ = mixturePoly(thermo_, mb_);
  m_ = 0.0;
  for (int g = 0; g < kNumGroups; ++g) m_ += mu_[g] + mb_[g];
  mR_ = Pu_.R + Pb_.R;
}

double Cylinder::gasConstant_J_kgK() const { return mR_ / m_; }

double Cylinder::gamma() const {
  const double T = temperature_K();
  const double cp = Pu_.cp(T) + Pb_.cp(T);
  return cp / (cp - mR_);
}

double Cylinder::specificEnthalpy_J_kg() const {
  double H = Pu_.h(Tu_);
  if (two_zone_) H += Pb_.h(Tb_);
  return H / m_;
}

double Cylinder::enthalpyOf(double T, double xb) const {
  return (1 - xb) * thermo_.group(kAir).h(T) + xb * thermo_.group(kBurned).h(T);
}

double Cylinder::burnedFraction() const { return groupMass(kBurned) / mass_kg(); }

double Cylinder::dVdtheta_m3_rad() const { return crank_.dVdtheta(units::degToRad(theta_deg_)); }

double Cylinder::speciesMassFraction(Species s) const {
  double y = 0.0;
  for (int g = 0; g < kNumGroups; ++g) y += groupMass(Group(g)) * thermo_.massFraction(Group(g), s);
  return y / mass_kg();
}

double Cylinder::fmep_Pa(double omega) const {
  const double pmax = last_.pmax_Pa > 0 ? last_.pmax_Pa : std::max(acc_.pmax_Pa, p_);
  const double cm = crank_.meanPistonSpeed(omega);
  return T_oil_K_ > 0.0 ? P_.friction.fmepAtOil_Pa(pmax, cm, T_oil_K_) : P_.friction.fmep_Pa(pmax, cm, T_coolant_K_);
}

double Cylinder::frictionTorque_Nm(double omega) const {
  return fmep_Pa(omega) * crank_.displacement() / (4.0 * units::kPi);
}

void Cylinder::diverged(const char* quantity, double value) const {
  std::ostringstream os;
  os << "non-physical value " << value << " at crank angle " << theta_deg_ << " deg";
  throw ModelDivergence("cylinder " + name_, quantity, os.str());
}

void Cylinder::advance(double dt, double omega, const PortFlows& f) {
  if (!(dt >= 0.0) || !std::isfinite(omega) || omega < 0.0) diverged("time step / speed", dt);
  if (dt == 0.0) return;
  const double dth = omega * dt / units::kRad_per_deg;
  const int n = std::max(1, static_cast<int>(std::ceil(dth / P_.max_substep_deg)));
  for (int i = 0; i < n; ++i) substep(dt / n, omega, f);
}

void Cylinder::substep(double dt, double omega, const PortFlows& f) {
  SubstepState s = beginSubstep(dt, omega, f);
  exchangeValveFlows(f, s);
  // Injection, ignition and burn are scheduled in crank angle: a crank at rest (omega = 0,
  // the stopped engine) advances none of them; its gas still exchanges mass and wall heat.
  const bool turning = s.dth > 0.0;
  if (closed_ && combustion_on_ && turning) {
    injectFuel(s);
    advanceIgnitionDelay(s);
  }
  if (combustion_on_ && turning) burnFuel(s);
  qwall_W_ = 0.0;
  if (heat_transfer_on_) transferWallHeat(s);
  clampUnburnedMasses();
  solveZoneEnergies(s);
  accumulateCycleResults(s);
  if (P_.nox_enabled && (two_zone_ || hz_fuel_kg_ > 0.0)) accumulateNox(s);
  advanceCrankAngle(s);
}

Cylinder::SubstepState Cylinder::beginSubstep(double dt, double omega, const PortFlows& f) {
  SubstepState s;
  s.dt = dt;
  s.omega = omega;
  s.dth = omega * dt / units::kRad_per_deg;
  s.th0 = theta_deg_;
  s.th1 = s.th0 + s.dth;
  s.flowing = f.intake.mdot_kg_s != 0.0 || f.exhaust.mdot_kg_s != 0.0;
  if (s.flowing && two_zone_) mergeZones();
  s.travel0 = travel_;
  s.travel1 = crank_.travel(units::degToRad(s.th1));
  s.V0 = V_;
  s.V1 = crank_.clearanceVolume() + crank_.pistonArea() * s.travel1;
  s.p0 = p_;
  s.Vu0 = two_zone_ ? Vu_ : s.V0;
  s.Vb0 = two_zone_ ? Vb_ : 0.0;
  s.mR0 = mR_;
  s.Uu = Pu_.u(Tu_);
  s.Ub = two_zone_ ? Pb_.u(Tb_) : 0.0;
  s.hu0 = Pu_.h(Tu_) / m_;  // single zone whenever valves flow (merged above)
  return s;
}

// 1. valve flows (single zone): inflow with its burned fraction, outflow of the mixture.
void Cylinder::exchangeValveFlows(const PortFlows& f, SubstepState& s) {
  const PortFlow* ports[2] = {&f.intake, &f.exhaust};
  for (int i = 0; i < 2; ++i) {
    const PortFlow& pf = *ports[i];
    const double dm = pf.mdot_kg_s * s.dt, dH = pf.Hdot_W * s.dt;
    if (dm > 0.0) {
      mu_[kAir] += dm * (1.0 - pf.burned_frac);
      mu_[kBurned] += dm * pf.burned_frac;
    } else if (dm < 0.0) {
      double m = 0.0;
      for (double x : mu_) m += x;
      const double h = s.hu0;
      if (std::fabs(pf.Hdot_W / pf.mdot_kg_s - h) > 0.1 * std::fabs(h) + 2e4)
        diverged("outflow enthalpy (use specificEnthalpy_J_kg)", pf.Hdot_W / pf.mdot_kg_s);
      if (-dm >= m) diverged("mass (outflow exceeds content)", m + dm);
      for (double& x : mu_) x *= 1.0 + dm / m;
    }
    s.Uu += dH;
    if (i == 0) acc_.intake_mass_kg += dm;
    if (i == 1) {
      acc_.exhaust_mass_kg -= dm;
      acc_.exhaust_enthalpy_J -= dH;
    }
  }
}

// 2. injection (liquid fuel evaporates into the unburned zone).
void Cylinder::injectFuel(SubstepState& s) {
  const double rate = P_.nozzle.massRate(sched_.rail_pressure_Pa, s.p0);
  double dm_inj = 0.0;
  for (auto& k : pulses_) {
    if (k.mass <= 0.0 || k.injected >= k.mass || s.th1 <= k.soi) continue;
    const double frac = (s.th1 - std::max(s.th0, k.soi)) / s.dth;
    const double d = std::min(k.mass - k.injected, rate * s.dt * frac);
    k.injected += d;
    dm_inj += d;
  }
  if (dm_inj > 0.0) {
    mu_[kFuelVap] += dm_inj;
    s.Uu += dm_inj * (thermo_.group(kFuelVap).h(P_.fuel_temperature_K) - P_.fuel.hfg_J_kg);
    acc_.fuel_injected_kg += dm_inj;
  }
}

// 3. ignition: Livengood–Wu integral of the Hardenberg–Hase delay.
void Cylinder::advanceIgnitionDelay(const SubstepState& s) {
  const double cm = crank_.meanPistonSpeed(s.omega);
  for (auto& k : pulses_) {
    if (k.ignited || k.injected <= 0.0) continue;
    const double tau_s = P_.ignition_delay_multiplier *
                         hardenbergHaseDelayDeg(s.p0, Tu_, cm, P_.cetane_number) * units::kRad_per_deg / s.omega;
    const double portion = (s.th1 - std::max(s.th0, k.soi)) / s.dth;
    const double lw1 = k.lw + s.dt * portion / tau_s;
    if (lw1 >= 1.0) {
      const double back = s.dth * portion * (lw1 - 1.0) / (lw1 - k.lw);
      ignite(k, s.th1 - back, s.omega);
    }
    k.lw = lw1;
  }
}

// 4. combustion: double-Wiebe demand of every ignited pulse, limited by vapour and air.
void Cylinder::burnFuel(SubstepState& s) {
  double demand = deferred_kg_;
  for (auto& k : pulses_) {
    if (!k.ignited || k.done) continue;
    if (s.th0 >= k.wiebe.end_deg()) k.done = true;  // x = 1 reached in an earlier step
    const double x1 = k.wiebe.x(s.th1);
    demand += k.mass * (x1 - k.x_prev);
    k.x_prev = x1;
  }
  const double afr = thermo_.afrStoich();
  const double dm_fb = std::max(0.0, std::min({demand, mu_[kFuelVap], mu_[kAir] / afr}));
  deferred_kg_ = demand - dm_fb;
  if (dm_fb > 0.0) {
    hotZoneReactants(s, dm_fb);
    releaseCombustionHeat(s, dm_fb, afr);
    acc_.fuel_burned_kg += dm_fb;
    acc_.heat_release_J += P_.fuel.lhv_J_kg * dm_fb;
    markBurnAngles(s, dm_fb);
  }
}

// Moves dm_fb [kg] of burned fuel and its air into the burned products, in the burned zone
// (split off at the first burn) while the charge is closed, else in the single zone.
void Cylinder::releaseCombustionHeat(SubstepState& s, double dm_fb, double afr) {
  // Air taken into the burned zone: λ_flame·AFR per kg, but never more than the unburned
  // zone can spare for all the fuel of this cycle still to burn — vapour, deferred demand
  // and fuel not yet injected (rich limit: stoichiometric). Counting only the present
  // vapour let the early flame take the air of the late-injected fuel, which then waited
  // (air-limited) until the zones merged at EVO and burned there in one step.
  const double to_burn =
      std::max(mu_[kFuelVap] + deferred_kg_, fuel_cycle_kg_ - acc_.fuel_burned_kg);
  const double spare = mu_[kAir] / std::max(to_burn, dm_fb);
  const double dm_air = dm_fb * std::max(afr, std::min(afr * P_.flame_lambda, spare));
  const double q = (P_.fuel.lhv_J_kg + P_.fuel.hfg_J_kg) * dm_fb;
  if (closed_ && !s.flowing && !zones_merged_) {
    if (!two_zone_) {
      two_zone_ = true;
      Tb_ = Tu_ + 2000.0;
    }
    const double Hreac = dm_fb * thermo_.group(kFuelVap).h(Tu_) +
                         dm_air * thermo_.group(kAir).h(Tu_);
    s.Uu -= Hreac;
    s.Ub += Hreac + q;
    mu_[kFuelVap] -= dm_fb;
    mu_[kAir] -= dm_air;
    mb_[kBurned] += (1.0 + afr) * dm_fb;
    mb_[kAir] += dm_air - afr * dm_fb;
  } else {
    s.Uu += q;
    mu_[kFuelVap] -= dm_fb;
    mu_[kAir] -= afr * dm_fb;
    mu_[kBurned] += (1.0 + afr) * dm_fb;
  }
}

// CA10 / CA50 / CA90: crank angles [deg] at which 10 / 50 / 90 % of the cycle's fuel has
// burned, interpolated within the sub-step that burned dm_fb [kg].
void Cylinder::markBurnAngles(const SubstepState& s, double dm_fb) {
  while (ca_next_ < 3 && fuel_cycle_kg_ > 0.0) {
    const double target = (ca_next_ == 0 ? 0.1 : ca_next_ == 1 ? 0.5 : 0.9) * fuel_cycle_kg_;
    if (acc_.fuel_burned_kg < target) break;
    const double before = acc_.fuel_burned_kg - dm_fb;
    ca_marks_[ca_next_++] = s.th0 + s.dth * (target - before) / dm_fb;
  }
}

// 5. wall heat transfer (Woschni, explicit).
void Cylinder::transferWallHeat(SubstepState& s) {
  const double h = wallHeatCoefficient(s);
  const Geometry& G = crank_.geometry();
  const double Ah = crank_.headArea(), Ap = crank_.pistonCrownArea(),
               Al = units::kPi * G.bore_m * (s.travel0 + G.top_land_height_m);
  const double A = Ah + Ap + Al, AT = Ah * Thead_ + Ap * Tpiston_ + Al * Tliner_;
  const double fu = s.Vu0 / s.V0, fb = s.Vb0 / s.V0;
  const double Qu = h * fu * (A * Tu_ - AT), Qb = two_zone_ ? h * fb * (A * Tb_ - AT) : 0.0;
  qwall_W_ = Qu + Qb;
  s.Uu -= Qu * s.dt;
  s.Ub -= Qb * s.dt;
  acc_.heat_wall_J += qwall_W_ * s.dt;
}

// Heat-transfer coefficient [W/(m² K)] at the sub-step start: Hohenberg or Woschni.
double Cylinder::wallHeatCoefficient(const SubstepState& s) const {
  const double Tm = s.p0 * s.V0 / s.mR0;
  const double cm = crank_.meanPistonSpeed(s.omega);
  const Geometry& G = crank_.geometry();
  if (P_.woschni.hohenberg) {
    // hohenbergCoefficient() with C_H and the multiplier folded in: V^−0.06 p[bar]^0.8 T^−0.4 (c_m+1.4)^0.8
    return hohenberg_pre_ * std::exp(-0.06 * std::log(s.V0) + 0.8 * std::log(s.p0 * 1e-5) -
                                     0.4 * std::log(Tm) + 0.8 * std::log(cm + 1.4));
  }
  const bool comb = closed_ && combustion_started_;
  const double pmot = comb ? pr_ * std::exp(nr_ * std::log(Vr_ / s.V0)) : s.p0;
  const double w = P_.woschni.velocity(!closed_, comb, cm, G.bore_m, G.stroke_m,
                                       crank_.displacement(), Tr_, pr_, Vr_, s.p0, pmot);
  // woschniCoefficient() with the bore factor precomputed: C0 B^−0.2 (p[kPa] w)^0.8 T^−0.55
  return woschni_pre_ * std::exp(0.8 * std::log(s.p0 * 1e-3 * std::max(w, 1e-6)) -
                                 0.55 * std::log(Tm));
}

// Unburned-zone masses below zero by round-off (<= 1e-12 kg) are set to zero; more diverges.
void Cylinder::clampUnburnedMasses() {
  for (int g = 0; g < kNumGroups; ++g) {
    if (mu_[g] < 0.0) {
      if (mu_[g] < -1e-12) diverged("unburned-zone mass", mu_[g]);
      mu_[g] = 0.0;
    }
  }
}

// 6. implicit energy equations.
void Cylinder::solveZoneEnergies(SubstepState& s) {
  refreshPolys();
  if (two_zone_) mergeConsumedUnburnedZone(s);
  travel_ = s.travel1;
  solveTemperatures(s.V0, s.V1, s.Vu0, s.Vb0, s.Uu, s.Ub);
}

// Unburned zone (nearly) consumed by the flame: below 0.1 % of the charge its explicit
// exchanges (entrainment at h, wall heat) can leave it less energy than any temperature
// allows and the two-zone Newton degenerates (seen in coupled Urban runs). Its remaining
// mass, energy and volume join the burned gas as one zone (energy conserved exactly). Fuel
// still burning in this cycle then burns in that one zone, and the NO kinetics freeze (the
// late, diluted combustion adds no NO; re-splitting would put the cycle's NO moles into a
// near-empty burned zone).
void Cylinder::mergeConsumedUnburnedZone(SubstepState& s) {
  double m_u = 0.0, m_b = 0.0;
  for (int g = 0; g < kNumGroups; ++g) {
    m_u += mu_[g];
    m_b += mb_[g];
  }
  if (m_u < 1e-3 * (m_u + m_b)) {
    mergeZones();
    zones_merged_ = true;  // rest of this cycle: one zone (NO frozen), no re-split
    s.Uu += s.Ub;
    s.Ub = 0.0;
    s.Vu0 += s.Vb0;
    s.Vb0 = 0.0;
  }
}

// Work (net over the cycle, gross over -180…180 deg), peak pressure and peak temperatures.
void Cylinder::accumulateCycleResults(const SubstepState& s) {
  const double dW = 0.5 * (s.p0 + p_) * (s.V1 - s.V0);
  acc_.work_net_J += dW;
  const double thm = 0.5 * (s.th0 + s.th1);
  if (thm >= -180.0 && thm < 180.0) acc_.work_gross_J += dW;
  if (p_ > acc_.pmax_Pa) {
    acc_.pmax_Pa = p_;
    acc_.theta_pmax_deg = s.th1;
  }
  acc_.Tmax_mean_K = std::max(acc_.Tmax_mean_K, temperature_K());
  if (two_zone_) acc_.Tmax_burned_K = std::max(acc_.Tmax_burned_K, Tb_);
}

// Hot-zone reactants of the sub-step's burned fuel dm_fb [kg], weighted by dm_fb: the unburned
// zone's temperature and the pressure at the step start (air fraction: the trapped charge's).
void Cylinder::hotZoneReactants(const SubstepState& s, double dm_fb) {
  if (!(P_.nox_enabled && P_.nox_hot_zone && closed_ && hz_yair_ivc_ > 0.0)) return;
  hz_fuel_kg_ += dm_fb;
  hz_Tu_ += Tu_ * dm_fb;
  hz_p_ += s.p0 * dm_fb;
}

// 7. NO kinetics, batched over nox_interval_deg: hot zone (fuel burned in the batch) or
// burned zone (Zeldovich at the batch's mean burned-zone state).
void Cylinder::accumulateNox(const SubstepState& s) {
  if (P_.nox_hot_zone) {
    nox_deg_ += s.dth;
    if (nox_deg_ >= P_.nox_interval_deg) hotZoneInterval();
    return;
  }
  if (Tb_ >= P_.nox_min_temperature_K) {
    nox_t_ += s.dt;
    nox_Tt_ += Tb_ * s.dt;
    nox_pt_ += p_ * s.dt;
    nox_Vt_ += Vb_ * s.dt;
    nox_deg_ += s.dth;
    if (nox_deg_ >= P_.nox_interval_deg) noxInterval();
  } else if (nox_t_ > 0.0) {
    noxInterval();
  }
}

// 8. crank angle and cycle events.
void Cylinder::advanceCrankAngle(const SubstepState& s) {
  theta_deg_ = s.th1;
  if (s.th0 < P_.ivc_deg && s.th1 >= P_.ivc_deg) onIVC(s.omega);
  if (s.th0 < P_.evo_deg && s.th1 >= P_.evo_deg) onEVO();
  if (s.th1 >= 360.0) onCycleEnd(s.omega);
}

namespace {
// Relative temperature correction below which a Newton iteration that did not reach its 1e-11
// tolerance is taken as converged at round-off level (1e-6 K per 1000 K).
constexpr double kNewtonRoundoff = 1e-9;
}  // namespace

void Cylinder::solveTemperatures(double V0, double V1, double Vu0, double Vb0, double Uu,
                                 double Ub) {
  const double p0 = p_;
  const Poly& Pu = Pu_;
  if (!two_zone_) {
    // Predictor: isentropic change over the step (linearised), then Newton.
    const double cv = Pu.cp(Tu_) - Pu.R;
    double T = Tu_ * (1.0 - Pu.R / cv * (V1 - V0) / V1) + (Uu - Pu.u(Tu_)) / cv;
    for (int it = 0; it < 40; ++it) {
      const double p1 = Pu.R * T / V1;
      const double F = Pu.u(T) - Uu + 0.5 * (p0 + p1) * (V1 - Vu0);
      const double J = Pu.cp(T) - Pu.R + 0.5 * Pu.R / V1 * (V1 - Vu0);
      const double dT = std::clamp(-F / J, -0.5 * T, 0.5 * T);
      T += dT;
      if (std::fabs(dT) < 1e-11 * T) break;
      // Newton stalled at round-off (no 1e-11 step in 40 iterations, last step tiny): accept.
      if (it == 39 && !(std::fabs(dT) < kNewtonRoundoff * T))
        diverged("temperature (energy equation did not converge)", T);
    }
    if (!(T > 0.0) || !std::isfinite(T)) diverged("temperature", T);
    Tu_ = T;
    V_ = Vu_ = V1;
    Vb_ = 0.0;
    p_ = Pu.R * T / V1;
    return;
  }
  const Poly& Pb = Pb_;
  double Tu = Tu_, Tb = Tb_;
  const double Ru = Pu.R, Rb = Pb.R;
  for (int it = 0; it < 40; ++it) {
    const double S = Ru * Tu + Rb * Tb;
    const double p1 = S / V1, pb = 0.5 * (p0 + p1);
    const double Vu1 = V1 * Ru * Tu / S, Vb1 = V1 - Vu1;
    const double Fu = Pu.u(Tu) - Uu + pb * (Vu1 - Vu0);
    const double Fb = Pb.u(Tb) - Ub + pb * (Vb1 - Vb0);
    const double dVu_dTu = V1 * Ru * Rb * Tb / (S * S), dVu_dTb = -V1 * Ru * Tu * Rb / (S * S);
    const double a11 = Pu.cp(Tu) - Ru + 0.5 * Ru / V1 * (Vu1 - Vu0) + pb * dVu_dTu;
    const double a12 = 0.5 * Rb / V1 * (Vu1 - Vu0) + pb * dVu_dTb;
    const double a21 = 0.5 * Ru / V1 * (Vb1 - Vb0) - pb * dVu_dTu;
    const double a22 = Pb.cp(Tb) - Rb + 0.5 * Rb / V1 * (Vb1 - Vb0) - pb * dVu_dTb;
    const double det = a11 * a22 - a12 * a21;
    const double dTu = std::clamp((-Fu * a22 + Fb * a12) / det, -0.3 * Tu, 0.3 * Tu);
    const double dTb = std::clamp((-Fb * a11 + Fu * a21) / det, -0.3 * Tb, 0.3 * Tb);
    Tu += dTu;
    Tb += dTb;
    if (std::fabs(dTu) < 1e-11 * Tu && std::fabs(dTb) < 1e-10 * Tb) break;
    // Converged in T, or residuals at round-off level of the zone energies (tiny new zone).
    const double eps = 1e-14 * (std::fabs(Uu) + std::fabs(Ub) + p0 * V1);
    if (std::fabs(Fu) < eps && std::fabs(Fb) < eps) break;
    // Newton stalled at round-off (e.g. a nearly empty zone makes the 1e-11 step unreachable):
    // accept when the last corrections are far below any physical significance.
    if (it == 39 && !(std::fabs(dTu) < kNewtonRoundoff * Tu && std::fabs(dTb) < kNewtonRoundoff * Tb))
      diverged("zone temperatures (energy equations did not converge)", Tb);
  }
  if (!(Tu > 0.0 && Tb > 0.0) || !std::isfinite(Tu + Tb)) diverged("zone temperature", Tb);
  Tu_ = Tu;
  Tb_ = Tb;
  const double S = Ru * Tu + Rb * Tb;
  p_ = S / V1;
  V_ = V1;
  Vu_ = V1 * Ru * Tu / S;
  Vb_ = V1 - Vu_;
}

}  // namespace hbt::cylinder
