#include "aftertreatment/aftertreatment.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/errors.hpp"

namespace hbt::aftertreatment {

namespace {
// Fill ratio (stored NH3 / storage target) [-] taken when the target is 0: the store counts as
// full and nothing is dosed.
constexpr double kFullStoreFillRatio = 1e9;
constexpr double kDH_CO = 283.0e3;     // J/mol CO -> CO2
constexpr double kDH_NO2 = 57.1e3;     // J/mol NO + 1/2 O2 -> NO2
constexpr double kDS_NO2 = -73.2;      // J/(mol K)
constexpr double kDH_NH3ox = 316.8e3;  // J/mol NH3 -> N2 + H2O

double arrhenius(double k_ref, double E, double T_ref, double T) {
  return k_ref * std::exp(-E / kRu * (1.0 / T - 1.0 / T_ref));
}

void checkInput(double v, const char* what, bool positive) {
  if (!std::isfinite(v) || (positive ? v <= 0.0 : v < 0.0))
    throw ModelDivergence("aftertreatment input", what, "non-physical value " + std::to_string(v));
}
}  // namespace

ScrKinetics scrKinetics(const AtsParams& p) {
  ScrKinetics k;
  k.omega_mol_m3 = p.scr_site_density_mol_m3;
  k.k_ads = p.scr_k_ads_m3_mol_s;
  k.k_des = p.scr_k_des_1_s;
  k.E_des = p.scr_E_des_J_mol;
  k.alpha = p.scr_temkin_alpha;
  k.k_std_ref = p.scr_k_std_ref_m3_mol_s;
  k.E_std = p.scr_E_std_J_mol;
  k.k_fast_ref = p.scr_k_fast_ref_m6_mol2_s;
  k.E_fast = p.scr_E_fast_J_mol;
  k.k_no2_ref = p.scr_k_no2_ref_m3_mol_s;
  k.E_no2 = p.scr_E_no2_J_mol;
  k.k_ox_ref = p.scr_k_ox_ref_1_s;
  k.E_ox = p.scr_E_ox_J_mol;
  k.T_ref = p.scr_T_ref_K;
  k.T_ox_ref = p.scr_T_ox_ref_K;
  return k;
}

HeatTransferParams heatTransfer(const AtsParams& p) {
  HeatTransferParams h;
  h.nusselt = p.nusselt;
  h.insulation_thickness_m = p.insulation_thickness_m;
  h.insulation_k_W_mK = p.insulation_k_W_mK;
  h.h_natural_W_m2K = p.h_natural_W_m2K;
  h.can_emissivity = p.can_emissivity;
  h.underbody_air_factor = p.underbody_air_factor;
  h.can_length_factor = p.can_length_factor;
  return h;
}

namespace {
std::unique_ptr<ExhaustLine> makeLine(const AtsParams& p, std::vector<std::string> names,
                                      std::vector<PipeSegmentParams> segs) {
  return std::make_unique<ExhaustLine>(std::move(names), std::move(segs), p.line, p.h_natural_W_m2K);
}
}  // namespace

Aftertreatment::Aftertreatment(const AtsParams& p) : p_(p) {
  const HeatTransferParams h = heatTransfer(p);
  bricks_[kDOC] = std::make_unique<Brick>("DOC", p.doc, h, false);
  bricks_[kDPF] = std::make_unique<Brick>("DPF", p.dpf, h, true);
  bricks_[kSCR] = std::make_unique<Brick>("SCR", p.scr, h, false);
  bricks_[kASC] = std::make_unique<Brick>("ASC", p.asc, h, false);
  dpf_.soot_load_g_L = p.dpf_soot_load_g_L;
  dpf_.wall_permeability_m2 = p.dpf_wall_permeability_m2;
  dpf_.soot_permeability_m2 = p.dpf_soot_permeability_m2;
  dpf_.soot_cake_density_kg_m3 = p.dpf_soot_cake_density_kg_m3;
  const LineParams& l = p.line;
  line_[kLineUpstream] = makeLine(p, {"manifold", "turbine_housing", "downpipe", "rear_pipe", "box_inlet"},
                                  {l.manifold, l.turbine_housing, l.downpipe, l.rear_pipe, l.box_inlet});
  line_[kLineMixer] = makeLine(p, {"box_mixer"}, {l.box_mixer});
  line_[kLineOutlet] = makeLine(p, {"box_outlet"}, {l.box_outlet});
  filter_ = std::make_unique<SootFilter>(p.soot, p.dpf.slices, bricks_[kDPF]->sliceVolume());
  scr_ = std::make_unique<ScrStorage>(scrKinetics(p), p.scr.slices, bricks_[kSCR]->sliceVolume(),
                                      p.rtol, p.atol_theta, p.max_steps);
  int nmax = 0;
  for (const auto& b : bricks_) nmax = std::max(nmax, b->slices());
  qr_.assign(nmax, 0.0);
  heat_J_.assign(nmax, 0.0);
  T_wall_.assign(nmax, 0.0);
  reset(298.15);
}

double Aftertreatment::energyStored() const {
  double e = 0.0;
  for (const auto& b : bricks_)
    for (int i = 0; i < b->slices(); ++i) e += b->sliceHeatCapacity() * b->T(i);
  for (const auto& l : line_) e += l->energyStored();
  return e;
}

void Aftertreatment::reset(double T_K, double ambient_p_Pa) {
  for (auto& b : bricks_) b->setUniformTemperature(T_K);
  for (auto& l : line_) l->setUniformTemperature(T_K);
  filter_->setUniformLoad(p_.dpf_soot_load_g_L);
  dpf_.soot_load_g_L = filter_->load_g_L();
  soot_ = AtsSoot{};
  soot0_kg_ = filter_->mass_kg();
  scr_->setCoverage(p_.scr_initial_coverage);
  p_brick_.fill(ambient_p_Pa);
  out_ = AtsOutputs{};
  energy_ = AtsEnergy{};
  n_ = AtsNitrogen{};
  t_ = 0.0;
  F_in_ = F_out_ = 0.0;
  E0_ = energyStored();
  stored0_ = scr_->storedMol();
  T_amb_last_ = T_K;
  for (int b = 0; b < kNumBricks; ++b) {
    out_.brick_T_K[b] = T_K;
    out_.brick_out_T_K[b] = T_K;
  }
  out_.outlet_T_K = T_K;
  out_.doc_inlet_T_K = T_K;
  out_.scr_inlet_T_K = T_K;
  out_.soot_mass_kg = soot0_kg_;
  out_.soot_load_g_L = filter_->load_g_L();
  out_.back_pressure_Pa = ambient_p_Pa;
  out_.nh3_stored_mol = stored0_;
}

void Aftertreatment::resetWarm(double brick_T_K, double nh3_fill, double ambient_p_Pa) {
  reset(brick_T_K, ambient_p_Pa);
  const double capacity_mol = p_.scr_site_density_mol_m3 * bricks_[kSCR]->sliceVolume() * bricks_[kSCR]->slices();
  scr_->setCoverage(std::clamp(nh3_fill * storageTarget_mol() / capacity_mol, 0.0, 1.0));
  stored0_ = scr_->storedMol();
  out_.nh3_stored_mol = stored0_;
}

double Aftertreatment::storageTarget_mol() const {
  const Brick& s = *bricks_[kSCR];
  const double p = p_brick_[kSCR];
  double sum = 0.0;
  for (int i = 0; i < s.slices(); ++i) {
    const double c = p_.dosing_ref_nh3_ppm * 1e-6 * p / (kRu * s.T(i));
    sum += scr_->equilibriumCoverage(s.T(i), c);
  }
  return sum * p_.scr_site_density_mol_m3 * s.sliceVolume();
}

PressureDrop Aftertreatment::brickPressureDrop(int b, double mdot, double T, double p,
                                               const GasComposition& g) const {
  const double rho = p * molarMass(g) / (kRu * T);
  return bricks_[b]->pressureDrop(mdot / rho, T, rho, b == kDPF ? &dpf_ : nullptr,
                                  p_.contraction_k);
}

void Aftertreatment::step(double dt, const AtsInputs& in) {
  checkStepInputs(dt, in);
  StepState s = beginStep(dt, in);
  stepUpstreamLine(in, s);
  stepDoc(in, s);
  stepDpf(s);
  doseUrea(s);
  stepScr(s);
  stepAsc(s);
  updateBackPressure(in, s);
  accumulateBalances(in, s);
  updateOutputs(s);
  updateLightOff(in, s);
}

void Aftertreatment::checkStepInputs(double dt, const AtsInputs& in) {
  checkInput(dt, "time step", true);
  checkInput(in.exhaust_mass_flow_kg_s, "exhaust mass flow", false);
  checkInput(in.exhaust_T_K, "exhaust temperature", true);
  checkInput(in.nox_mass_flow_kg_s, "NOx mass flow", false);
  checkInput(in.hc_mass_flow_kg_s, "HC mass flow", false);
  checkInput(in.co_mass_flow_kg_s, "CO mass flow", false);
  checkInput(in.ambient_T_K, "ambient temperature", true);
  checkInput(in.ambient_p_Pa, "ambient pressure", true);
  checkInput(in.vehicle_speed_m_s, "vehicle speed", false);
  checkInput(in.comp.y_O2 + in.comp.y_CO2 + in.comp.y_H2O, "composition", false);
}

Aftertreatment::StepState Aftertreatment::beginStep(double dt, const AtsInputs& in) const {
  StepState s;
  s.dt = dt;
  s.mdot = in.exhaust_mass_flow_kg_s;
  s.cp = cpMix(in.comp, in.exhaust_T_K);
  s.M = molarMass(in.comp);
  s.R = kRu / s.M;
  s.n_tot = s.mdot / s.M;
  s.mcp = s.mdot * s.cp;
  s.Tamb = in.ambient_T_K;
  s.v = in.vehicle_speed_m_s;
  s.x_O2 = in.comp.y_O2 * s.M / species::kO2_kg_mol;
  s.co2_kg_s = in.comp.y_CO2 * s.mdot;
  return s;
}

// Exhaust line from the turbine outlet to the DOC face: the gas entering the DOC.
void Aftertreatment::stepUpstreamLine(const AtsInputs& in, StepState& s) {
  s.Tg_in[kDOC] = line_[kLineUpstream]->step(s.dt, s.mdot, s.cp, in.exhaust_T_K, s.Tamb, s.v,
                                              s.e_line[kLineUpstream]);
}

// DOC: CO and HC oxidation and NO -> NO2 per slice at its wall temperature, then its thermal step.
void Aftertreatment::stepDoc(const AtsInputs& in, StepState& s) {
  Brick& doc = *bricks_[kDOC];
  s.n_NOx = in.nox_mass_flow_kg_s / kM_NO2;
  s.n_NO2 = p_.engine_no2_fraction * s.n_NOx;
  double n_CO = in.co_mass_flow_kg_s / kM_CO, m_HC = in.hc_mass_flow_kg_s;
  const double n_CO_in = n_CO;
  {
    const double p = p_brick_[kDOC];
    const double sqrt_pO2 = std::sqrt(std::max(0.0, s.x_O2 * p / kAtm_Pa));
    for (int i = 0; i < doc.slices(); ++i) {
      const double T = doc.T(i);
      qr_[i] = 0.0;
      if (s.n_tot <= 0.0) continue;
      const double tau = doc.sliceVolume() / (s.n_tot * kRu * T / p);
      const double X_co = -std::expm1(-arrhenius(p_.doc_co_k_ref_1_s, p_.doc_co_E_J_mol, p_.doc_co_T_ref_K, T) * tau);
      const double X_hc = -std::expm1(-arrhenius(p_.doc_hc_k_ref_1_s, p_.doc_hc_E_J_mol, p_.doc_hc_T_ref_K, T) * tau);
      double dNO2 = 0.0;
      if (s.n_NOx > 0.0 && sqrt_pO2 > 0.0) {
        const double K = std::exp(-(-kDH_NO2 - T * kDS_NO2) / (kRu * T));
        const double f_eq = K * sqrt_pO2 / (1.0 + K * sqrt_pO2);
        const double kf = arrhenius(p_.doc_no_k_ref_1_s, p_.doc_no_E_J_mol, p_.doc_no_T_ref_K, T);
        const double kr = kf / (K * sqrt_pO2);
        const double f = s.n_NO2 / s.n_NOx;
        const double f1 = f_eq + (f - f_eq) * std::exp(-(kf + kr) * tau);
        dNO2 = (f1 - f) * s.n_NOx;
        s.n_NO2 += dNO2;
      }
      qr_[i] = kDH_CO * n_CO * X_co + p_.hc_heating_value_J_kg * m_HC * X_hc + kDH_NO2 * dNO2;
      n_CO *= 1.0 - X_co;
      m_HC *= 1.0 - X_hc;
    }
  }
  out_.doc_no2_fraction = s.n_NOx > 0.0 ? s.n_NO2 / s.n_NOx : 0.0;
  out_.doc_co_conversion = n_CO_in > 0.0 ? 1.0 - n_CO / n_CO_in : 0.0;
  s.Tg_out[kDOC] = doc.stepThermal(s.dt, s.mdot, s.cp, s.Tg_in[kDOC], qr_.data(), s.Tamb, s.v, s.e[kDOC]);
}

// DPF: soot deposition and NO2 oxidation at the wall temperatures of the step start (the NO2
// consumed leaves as NO), its thermal step with the reaction heat, the soot load of the pressure
// drop; then the mixer section of the box.
void Aftertreatment::stepDpf(StepState& s) {
  Brick& dpf = *bricks_[kDPF];
  for (int i = 0; i < dpf.slices(); ++i) T_wall_[i] = dpf.T(i);
  s.soot = filter_->step(s.dt, s.co2_kg_s, s.n_NO2, s.n_tot, p_brick_[kDPF], T_wall_.data(), qr_.data());
  s.n_NO2 = s.soot.n_NO2_out_mol_s;
  dpf_.soot_load_g_L = filter_->load_g_L();
  s.Tg_in[kDPF] = s.Tg_out[kDOC];
  s.Tg_out[kDPF] = dpf.stepThermal(s.dt, s.mdot, s.cp, s.Tg_in[kDPF], qr_.data(), s.Tamb, s.v, s.e[kDPF]);
  s.T_scr_in = line_[kLineMixer]->step(s.dt, s.mdot, s.cp, s.Tg_out[kDPF], s.Tamb, s.v, s.e_line[kLineMixer]);
}

// Urea dosing at the SCR inlet (storage controller) and the gas cooling by its evaporation.
void Aftertreatment::doseUrea(StepState& s) {
  out_.anr = 0.0;
  if (s.T_scr_in >= p_.dosing_release_T_K && s.n_NOx > 0.0 && s.mcp > 0.0) {
    const double target = storageTarget_mol();
    const double phi = target > 0.0 ? scr_->storedMol() / target : kFullStoreFillRatio;
    const double fill = std::clamp((p_.dosing_fill_stop - phi) / (p_.dosing_fill_stop - p_.dosing_fill_start), 0.0, 1.0);
    out_.anr = p_.dosing_anr * fill;
    s.n_NH3 = out_.anr * s.n_NOx;
    s.adblue = 0.5 * s.n_NH3 * kM_urea / p_.adblue_urea_mass_fraction;
    s.Q_adblue = s.adblue * p_.adblue_heat_J_kg;
    // never cool the gas below ambient by evaporation (tiny flows)
    s.Q_adblue = std::min(s.Q_adblue, std::max(0.0, s.mcp * (s.T_scr_in - s.Tamb)));
    s.T_scr_in -= s.Q_adblue / s.mcp;
  }
}

// SCR: NH3 storage and NOx reduction (ScrStorage, Runge-Kutta 5(4)), then its thermal step.
void Aftertreatment::stepScr(StepState& s) {
  Brick& scr = *bricks_[kSCR];
  ScrInlet si;
  si.n_NO_mol_s = s.n_NOx - s.n_NO2;
  si.n_NO2_mol_s = s.n_NO2;
  si.n_NH3_mol_s = s.n_NH3;
  si.n_total_mol_s = s.n_tot;
  si.p_Pa = p_brick_[kSCR];
  for (int i = 0; i < scr.slices(); ++i) T_wall_[i] = scr.T(i);
  s.scr = scr_->step(s.dt, si, T_wall_.data(), heat_J_.data());
  for (int i = 0; i < scr.slices(); ++i) qr_[i] = heat_J_[i] / s.dt;
  s.Tg_in[kSCR] = s.T_scr_in;
  s.Tg_out[kSCR] = scr.stepThermal(s.dt, s.mdot, s.cp, s.T_scr_in, qr_.data(), s.Tamb, s.v, s.e[kSCR]);
  s.nox_in_mol = s.n_NOx * s.dt;
  s.nox_out_mol = std::max(0.0, s.nox_in_mol - s.scr.std_mol - 2.0 * s.scr.fast_mol - s.scr.no2_mol);
}

// ASC: NH3 slip oxidised per slice, then its thermal step.
void Aftertreatment::stepAsc(StepState& s) {
  Brick& asc = *bricks_[kASC];
  s.n_slip = s.scr.nh3_slip_mol / s.dt;
  s.n_slip_in = s.n_slip;
  for (int i = 0; i < asc.slices(); ++i) {
    qr_[i] = 0.0;
    if (s.n_tot <= 0.0 || s.n_slip <= 0.0) continue;
    const double T = asc.T(i);
    const double tau = asc.sliceVolume() / (s.n_tot * kRu * T / p_brick_[kASC]);
    const double X = -std::expm1(-arrhenius(p_.asc_k_ref_1_s, p_.asc_E_J_mol, p_.asc_T_ref_K, T) * tau);
    qr_[i] = kDH_NH3ox * s.n_slip * X;
    s.n_slip *= 1.0 - X;
  }
  s.Tg_in[kASC] = s.Tg_out[kSCR];
  s.Tg_out[kASC] = asc.stepThermal(s.dt, s.mdot, s.cp, s.Tg_in[kASC], qr_.data(), s.Tamb, s.v, s.e[kASC]);
  s.T_tailpipe = line_[kLineOutlet]->step(s.dt, s.mdot, s.cp, s.Tg_out[kASC], s.Tamb, s.v, s.e_line[kLineOutlet]);
}

// Pressure from the tailpipe (ambient) upstream: muffler, then each brick at its mean gas
// temperature; the brick pressures of the next step and the back-pressure.
void Aftertreatment::updateBackPressure(const AtsInputs& in, const StepState& s) {
  double p = in.ambient_p_Pa;
  {
    const double T = s.Tg_out[kASC];
    const double rho = p / (s.R * T);
    const double A = 0.25 * units::kPi * p_.pipe_diameter_m * p_.pipe_diameter_m;
    const double u = s.mdot / (rho * A);
    out_.muffler_dp_Pa = p_.muffler_k * 0.5 * rho * u * u;
    p += out_.muffler_dp_Pa;
  }
  for (int b = kASC; b >= kDOC; --b) {
    const double T = 0.5 * (s.Tg_in[b] + s.Tg_out[b]);
    const double rho = p / (s.R * T);
    const PressureDrop dp = bricks_[b]->pressureDrop(s.mdot / rho, T, rho, b == kDPF ? &dpf_ : nullptr,
                                                     p_.contraction_k);
    out_.brick_dp_Pa[b] = dp.total();
    p_brick_[b] = p + 0.5 * dp.total();
    p += dp.total();
  }
  if (!std::isfinite(p))
    throw ModelDivergence("aftertreatment", "back-pressure", "non-physical value");
  out_.back_pressure_Pa = p;
}

// Cumulative energy and nitrogen balances.
void Aftertreatment::accumulateBalances(const AtsInputs& in, const StepState& s) {
  const double dt = s.dt;
  const ScrStepResult& r = s.scr;
  for (int b = 0; b < kNumBricks; ++b) {
    energy_.can_loss_J += s.e[b].can_loss_J;
    energy_.reaction_heat_J += s.e[b].reaction_J;
    out_.brick_T_K[b] = bricks_[b]->meanT();
    out_.brick_out_T_K[b] = s.Tg_out[b];
  }
  for (int l = 0; l < kNumLineParts; ++l) energy_.line_loss_J += s.e_line[l].can_loss_J;
  energy_.reaction_heat_J -= s.Q_adblue * dt;
  energy_.enthalpy_in_J += s.mcp * (in.exhaust_T_K - kT_ref_K) * dt;
  energy_.enthalpy_out_J += s.mcp * (s.T_tailpipe - kT_ref_K) * dt;
  accumulateSoot(s);
  energy_.stored_change_J = energyStored() - E0_;

  n_.nh3_dosed_mol += s.n_NH3 * dt;
  n_.nh3_scr_reacted_mol += r.std_mol + 2.0 * r.fast_mol + (4.0 / 3.0) * r.no2_mol;
  n_.nh3_scr_oxidised_mol += r.ox_mol;
  n_.nh3_scr_slip_mol += r.nh3_slip_mol;
  n_.nh3_asc_oxidised_mol += (s.n_slip_in - s.n_slip) * dt;
  n_.nh3_tailpipe_mol += s.n_slip * dt;
  n_.nox_scr_in_mol += s.nox_in_mol;
  n_.nox_scr_out_mol += s.nox_out_mol;
  n_.nh3_stored_change_mol = scr_->storedMol() - stored0_;
}

// Cumulative soot counters and the NO2 reduced to NO on the soot.
void Aftertreatment::accumulateSoot(const StepState& s) {
  const SootStep& r = s.soot;
  soot_.engine_out_kg += r.captured_kg + r.slip_kg;
  soot_.captured_kg += r.captured_kg;
  soot_.slip_kg += r.slip_kg;
  soot_.burnt_kg += (r.carbon_co2_mol + r.carbon_co_mol) * kM_C;
  soot_.carbon_co2_mol += r.carbon_co2_mol;
  soot_.carbon_co_mol += r.carbon_co_mol;
  soot_.no2_to_no_mol += r.no2_consumed_mol;
  soot_.stored_change_kg = filter_->mass_kg() - soot0_kg_;
}

// Tailpipe flows, cumulative masses and the step's SCR conversion.
void Aftertreatment::updateOutputs(const StepState& s) {
  const double dt = s.dt;
  out_.outlet_T_K = s.T_tailpipe;
  out_.doc_inlet_T_K = s.Tg_in[kDOC];
  out_.scr_inlet_T_K = s.T_scr_in;
  out_.scr_inlet_no2_fraction = s.n_NOx > 0.0 ? s.n_NO2 / s.n_NOx : 0.0;
  out_.soot_mass_kg = filter_->mass_kg();
  out_.soot_load_g_L = filter_->load_g_L();
  out_.tailpipe_nox_kg_s = s.nox_out_mol / dt * kM_NO2;
  out_.tailpipe_nox_kg += s.nox_out_mol * kM_NO2;
  out_.engine_nox_kg += s.nox_in_mol * kM_NO2;
  out_.nh3_slip_kg_s = s.n_slip * kM_NH3;
  out_.nh3_slip_kg += s.n_slip * dt * kM_NH3;
  out_.adblue_kg_s = s.adblue;
  out_.adblue_kg += s.adblue * dt;
  out_.urea_kg += s.adblue * dt * p_.adblue_urea_mass_fraction;
  out_.nox_conversion = s.nox_in_mol > 0.0 ? 1.0 - s.nox_out_mol / s.nox_in_mol : 0.0;
  out_.nh3_stored_mol = scr_->storedMol();
}

// Filtered SCR conversion and the light-off time; advances the clock.
void Aftertreatment::updateLightOff(const AtsInputs& in, const StepState& s) {
  const double dt = s.dt;
  const double a = p_.lightoff_filter_s > 0.0 ? -std::expm1(-dt / p_.lightoff_filter_s) : 1.0;
  F_in_ += a * (in.nox_mass_flow_kg_s - F_in_);
  F_out_ += a * (out_.tailpipe_nox_kg_s - F_out_);
  const bool enough = F_in_ >= p_.lightoff_min_nox_kg_s && F_in_ > 0.0;
  out_.nox_conversion_filtered = enough ? 1.0 - F_out_ / F_in_ : 0.0;
  t_ += dt;
  out_.light_off = enough && out_.nox_conversion_filtered >= p_.lightoff_conversion &&
                   out_.brick_T_K[kSCR] >= p_.dosing_release_T_K;
  if (out_.light_off && out_.light_off_time_s < 0.0) out_.light_off_time_s = t_;
  T_amb_last_ = s.Tamb;
}

}  // namespace hbt::aftertreatment
