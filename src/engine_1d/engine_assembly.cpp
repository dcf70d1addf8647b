#include "engine_1d/engine_assembly.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.hpp"

namespace hbt::engine_1d {
namespace {
using gasdyn::End;
using units::kRad_per_deg;

std::string num(int k) { return std::to_string(k + 1); }

void requireFinite(double v, const std::string& where, const char* what) {
  if (!std::isfinite(v)) throw ModelDivergence(where, what, "non-finite value");
}
}  // namespace

EngineAssembly::FlowMaps EngineAssembly::FlowMaps::build(const turbo::Turbocharger& tc) {
  FlowMaps m;
  m.compressor = std::make_shared<CompressorFlowMap>(tc.compressor);
  m.turbine[0] = std::make_shared<TurbineFlowMap>(tc.turbine.entry(0), &tc.turbine.wastegate());
  m.turbine[1] = std::make_shared<TurbineFlowMap>(tc.turbine.entry(1), nullptr);
  return m;
}

EngineAssembly::EngineAssembly(const Engine1DParams& p, const turbo::Turbocharger& tc,
                               const FlowMaps& maps, const Initial& init)
    : P_(p),
      tc_(tc),
      shaft_(tc.shaft),
      intake_(PerfectGas{p.turbo.compressor_options.gamma, p.turbo.air_gas_constant}),
      exhaust_(PerfectGas{p.turbo.exhaust_gamma, p.turbo.exhaust_gas_constant}),
      comp_map_(maps.compressor),
      turb_map_(maps.turbine) {
  cp_in_ = intake_.gas().cp();
  cp_ex_ = exhaust_.gas().cp();
  build(init);
}

gasdyn::Pipe& EngineAssembly::pipe(gasdyn::Network& n, const std::string& name,
                                   const PipeSpec& s, double friction, bool hot) {
  gasdyn::PipeConfig c;
  c.name = name;
  c.length = s.length_m;
  const bool tvd = P_.engine.solver == "tvd";
  c.cells = tvd ? std::max(2, static_cast<int>(std::lround(s.cells * P_.engine.tvd_mesh_factor)))
                : (s.fsm_cells > 0 ? s.fsm_cells : s.cells);
  c.diameter_left = c.diameter_right = s.diameter_m;
  c.friction_darcy = friction;
  c.solver = tvd ? gasdyn::SolverKind::TVD : gasdyn::SolverKind::FSM;
  if (hot) {
    c.heat = gasdyn::WallHeat::ReynoldsAnalogy;
    c.T_wall = P_.engine.exhaust_wall_T_K;
  }
  return n.addPipe(c);
}

void EngineAssembly::build(const Initial& in) {
  const Engine1DConfig& E = P_.engine;
  cylinder::CylinderParams cp = P_.cylinder;
  // The assembly sub-steps the cylinders (coupledStep) at <= substep_deg_; the cylinder's own
  // limit is set above that so it never splits a sub-step again (round-off at exact multiples).
  substep_deg_ = E.cylinder_substep_deg > 0.0 ? E.cylinder_substep_deg : cp.max_substep_deg;
  substep_open_deg_ = std::max(substep_deg_, E.cylinder_substep_open_deg);
  cp.max_substep_deg = 2.0 * substep_open_deg_;
  if (E.nox_interval_deg > 0.0) cp.nox_interval_deg = E.nox_interval_deg;
  const int n = E.cylinders;  // validated with firing_order and exhaust_bank (validate())
  cyl_.resize(n);
  for (int j = 0; j < n; ++j) {
    const int c = static_cast<int>(E.firing_order[j]) - 1;
    cyl_[c].phase_deg = E.firingIntervalDeg() * j;
  }
  for (int k = 0; k < n; ++k) {
    CylinderSlot& s = cyl_[k];
    s.bank = E.exhaustEntry(k);
    s.cyl = std::make_unique<cylinder::Cylinder>(cp, "cyl" + num(k));
    s.cyl->setCoolantTemperature(in.coolant_K);
    s.cyl->setFuelPerCycle(in.fuel_per_cycle_kg);
    // cylinder k is at local angle -phase when the engine crank (cylinder 1 firing TDC) is 0
    const double th = cylinder::wrapCycleDeg(-s.phase_deg);
    const bool exhaust_side = th > cp.evo_deg || th < cp.evc_deg - 720.0;
    s.cyl->initialize(th, exhaust_side ? in.p3 : in.p_im, exhaust_side ? in.T3 : in.T_im + 30.0,
                      0.05);
  }
  shaft_.setOmega(in.turbo_rad_s);
  T_amb_ = in.T_amb;
  intake_.setImplicitVolumes(E.implicit_volumes);
  exhaust_.setImplicitVolumes(E.implicit_volumes);
  intake_.setImplicitOneCellPipes(E.implicit_one_cell_pipes);
  exhaust_.setImplicitOneCellPipes(E.implicit_one_cell_pipes);
  intake_.setSubcycledPipes(E.subcycle_coupling_cfl);
  exhaust_.setSubcycledPipes(E.subcycle_coupling_cfl);

  // --- intake network ---
  filter_ = &intake_.addReservoir("air_filter_box", in.p_amb, in.T_amb);
  plenum_ = &intake_.addVolume("intake_plenum", E.intake_plenum_m3, in.p_im, in.T_im);
  comp_pipe_ = &pipe(intake_, "compressor_outlet", E.compressor_outlet, E.intake_friction_darcy, false);
  cac_pipe_ = &pipe(intake_, "charge_air_duct", E.charge_air_duct, E.intake_friction_darcy, false);
  comp_ = &intake_.add<gasdyn::CompressorOutlet>("compressor", *filter_, gasdyn::leftEnd(*comp_pipe_),
                                                 comp_map_);
  cac_ = &intake_.add<ChargeAirCoolerLink>("intercooler", gasdyn::rightEnd(*comp_pipe_),
                                           gasdyn::leftEnd(*cac_pipe_), tc_.intercooler);
  cac_->setCoolingAirTemperature(in.T_amb);
  intake_.connect(*cac_pipe_, End::Right, *plenum_);
  for (int k = 0; k < n; ++k) {
    CylinderSlot& s = cyl_[k];
    s.run_in = &pipe(intake_, "intake_runner_" + num(k), E.intake_runner, E.intake_friction_darcy, false);
    intake_.connect(*s.run_in, End::Left, *plenum_);
    s.res_in = &intake_.addReservoir("cyl" + num(k) + "_intake_side", in.p_im, in.T_im);
    auto area = std::make_shared<CrankValveArea>(*s.cyl, E.intake_valve, cp.ivo_deg, cp.ivc_deg, false);
    s.area_in = area.get();
    intake_.add<CylinderValve>("intake_valves_" + num(k), *s.res_in, gasdyn::rightEnd(*s.run_in), area);
  }
  // --- exhaust network ---
  turb_out_ = &exhaust_.addVolume("turbine_outlet", E.turbine_outlet_m3, in.p_amb * 1.1, in.T3 - 100.0);
  back_ = &exhaust_.addReservoir("aftertreatment_inlet", in.p_amb * 1.05, in.T3 - 100.0);
  for (int b = 0; b < 2; ++b) {
    junction_[b] = &exhaust_.addVolume("exhaust_collector_" + num(b), E.exhaust_junction_m3, in.p3, in.T3);
    turb_pipe_[b] = &pipe(exhaust_, "turbine_inlet_" + num(b), E.turbine_inlet, E.exhaust_friction_darcy, true);
    exhaust_.connect(*turb_pipe_[b], End::Left, *junction_[b]);
    turb_[b] = &exhaust_.add<gasdyn::TurbineEntry>("turbine_entry_" + num(b), gasdyn::rightEnd(*turb_pipe_[b]),
                                                  *turb_out_, turb_map_[b]);
  }
  for (int k = 0; k < n; ++k) {
    CylinderSlot& s = cyl_[k];
    s.run_ex = &pipe(exhaust_, "exhaust_runner_" + num(k), E.exhaust_runner, E.exhaust_friction_darcy, true);
    s.res_ex = &exhaust_.addReservoir("cyl" + num(k) + "_exhaust_side", in.p3, in.T3);
    auto area = std::make_shared<CrankValveArea>(*s.cyl, E.exhaust_valve, cp.evo_deg, cp.evc_deg, true);
    s.area_ex = area.get();
    exhaust_.add<CylinderValve>("exhaust_valves_" + num(k), *s.res_ex, gasdyn::leftEnd(*s.run_ex), area);
    exhaust_.connect(*s.run_ex, End::Right, *junction_[s.bank]);
  }
  down_pipe_ = &pipe(exhaust_, "downpipe", E.downpipe, E.exhaust_friction_darcy, true);
  exhaust_.connect(*down_pipe_, End::Left, *turb_out_);
  back_end_ = &exhaust_.connect(*down_pipe_, End::Right, *back_);

  for (auto& p : intake_.pipes()) p->setUniform(p.get() == comp_pipe_ ? in.p_im * 1.05 : in.p_im,
                                                p.get() == comp_pipe_ ? in.T_im + 60.0 : in.T_im);
  for (auto& p : exhaust_.pipes())
    p->setUniform(p.get() == down_pipe_ ? in.p_amb * 1.08 : in.p3,
                  p.get() == down_pipe_ ? in.T3 - 100.0 : in.T3);
  window_.reset();
  window_.setMaxSpan(E.cycle_window_max_s);
}

void EngineAssembly::setFuelPerCycle(double m) {
  for (auto& s : cyl_) s.cyl->setFuelPerCycle(m);
}
void EngineAssembly::setCoolantTemperature(double T) {
  for (auto& s : cyl_) s.cyl->setCoolantTemperature(T);
}
void EngineAssembly::setOilTemperature(double T) {
  for (auto& s : cyl_) s.cyl->setOilTemperature(T);
}
void EngineAssembly::setCombustion(bool on) {
  for (auto& s : cyl_) s.cyl->setCombustion(on);
}
void EngineAssembly::setAmbient(double p_amb, double T_amb) {
  // Air filter: dp = K mdot^2 T/p, K from (dp_ref, mdot_ref) at 298.15 K, 100 kPa; flow = cycle mean.
  const Engine1DConfig& E = P_.engine;
  const double K = E.air_filter_dp_ref_Pa * 1e5 /
                   (E.air_filter_ref_flow_kg_s * E.air_filter_ref_flow_kg_s * 298.15);
  CycleMeans m;
  cycleMeans(m);
  const double mdot = windowFull() ? m[kAir] : comp_->massFlow();
  const double dp = std::min(K * mdot * mdot * T_amb / p_amb, 0.3 * p_amb);
  filter_->setReservoirState(p_amb - dp, T_amb);
  cac_->setCoolingAirTemperature(T_amb);
  T_amb_ = T_amb;
}
void EngineAssembly::setBackPressure(double p, double T) { back_->setReservoirState(p, T); }
void EngineAssembly::setWastegateOpening(double a) { turb_map_[0]->setWastegateOpening(a); }

double EngineAssembly::compressorMassFlow() const { return comp_->massFlow(); }

double EngineAssembly::displacement_m3() const {
  return cylinders() * cylinder::SliderCrank(P_.cylinder.geometry).displacement();
}

double EngineAssembly::peakPressureLastCycles() const {
  double p = 0.0;
  for (const auto& s : cyl_) p = std::max(p, s.cyl->lastCycle().pmax_Pa);
  return p;
}

double EngineAssembly::exhaustBurnedFraction() const {
  CycleMeans m;
  cycleMeans(m);
  return m[kCylOut] > 0.0 ? m[kBurnedOut] / m[kCylOut] : 0.0;
}

void EngineAssembly::advance(double interval, double omega) {
  interval_ = Interval{};
  if (!(interval > 0.0)) return;
  if (!(omega >= 0.0) || !std::isfinite(omega))
    throw ModelDivergence("engine_1d", "crank speed", "must be finite and >= 0");
  interval_.duration_s = interval;
  fric_torque_ = 0.0;
  for (const auto& s : cyl_) fric_torque_ += s.cyl->frictionTorque_Nm(omega);
  if (omega > 0.0) standing_s_ = 0.0;
  if (holdsRest(omega)) {
    holdRest(interval);
    return;
  }
  double remaining = interval;
  while (remaining > 0.0) {
    const double dtmax = stableDt(omega);
    if (!(dtmax > 1e-9)) {
      std::string who;
      stableDt(omega, &who);
      throw ModelDivergence(who, "time step",
                            "stable step " + std::to_string(dtmax) + " s collapsed");
    }
    const double n = std::max(1.0, std::ceil(remaining / dtmax * (1.0 - 1e-12)));
    const double dt = n <= 1.0 ? remaining : remaining / n;
    coupledStep(dt, omega);
    remaining = n <= 1.0 ? 0.0 : remaining - dt;
  }
  if (omega == 0.0) standing_s_ += interval;
  CycleMeans m;
  cycleMeans(m);
  for (int b = 0; b < 2; ++b) {
    const double out = m[kBankOut0 + b];
    if (out > 0.0) xb_bank_[b] = m[kBankBurned0 + b] / out;
  }
}

bool EngineAssembly::holdsRest(double omega) {
  const Engine1DConfig& E = P_.engine;
  if (omega > 0.0 || !(E.rest_hold_after_s > 0.0)) return held_ = false;
  if (held_) {
    if (std::fabs(filter_->p() - held_filter_p_) <= kHoldPressureTol_Pa &&
        std::fabs(back_->p() - held_back_p_) <= kHoldPressureTol_Pa)
      return true;
    held_ = false;  // a boundary moved: the gas flows again and relaxes anew
    standing_s_ = 0.0;
    return false;
  }
  if (standing_s_ < E.rest_hold_after_s) return false;
  CycleMeans m;
  cycleMeans(m);
  if (!(std::fabs(m[kAir]) < E.rest_hold_flow_kg_s && std::fabs(m[kExhOut]) < E.rest_hold_flow_kg_s))
    return false;
  held_filter_p_ = filter_->p();
  held_back_p_ = back_->p();
  return held_ = true;
}

// The held gas over the interval: no gas is stepped; the turbocharger coasts on its bearing
// friction alone (no flow: no turbine or compressor power); the window gets the standing state
// (zero flows, fuel, wall heat and NOx; the gas torque at the standing angle; the friction torque).
void EngineAssembly::holdRest(double interval) {
  shaft_.step(interval, 0.0, 0.0);
  std::array<double, kNumChannels> x{};
  x[kIndTorque] = gasTorque_Nm();
  x[kFricTorque] = fric_torque_;
  gasStateChannels(x);
  window_.add(interval, 0.0, x);
  t_ += interval;
}

double EngineAssembly::gasTorque_Nm() const {
  double T = 0.0;
  for (const CylinderSlot& s : cyl_) {
    const cylinder::Cylinder& c = *s.cyl;
    T += c.pressure_Pa() * c.crank().dVdtheta(units::degToRad(c.crankAngle_deg()));
  }
  return T;
}

double EngineAssembly::stableDt(double omega, std::string* limiter) const {
  // the crank-angle cap: none at rest (omega = 0)
  const double dt_ang = omega > 0.0 ? units::degToRad(P_.engine.coupling_max_deg) / omega
                                    : std::numeric_limits<double>::infinity();
  if (!limiter) return std::min({intake_.stableDt(), exhaust_.stableDt(), dt_ang, cylinderDt(omega)});
  std::string a, b;
  const double di = intake_.stableDt(&a), de = exhaust_.stableDt(&b), dc = cylinderDt(omega);
  const double dt = std::min({di, de, dt_ang, dc});
  *limiter = dt == di ? a : dt == de ? b : dt == dt_ang ? "crank-angle cap" : "cylinder valves";
  return dt;
}

double EngineAssembly::cylinderDt(double omega) const {
  // Each cylinder is seen by its valves as a reservoir frozen over the coupled step (explicit
  // coupling): like a gasdyn volume, its filling/emptying mode dp/dt ~ -(c^2/V) sum A_eff/c p
  // is stable for dt <= V/(c sum A_eff). A_eff: the larger of the two directions' effective
  // valve areas; c from the exhaust gas constants (gamma 1.33: c within ~3 % of the mixture's).
  // A slow crank (a cycle longer than cycle_window_max_s: spin-down, cranking, at rest) holds a
  // valve open for many steps at a nearly balanced pressure: there the cylinder / 1-cell
  // runner pair has an odd-even mode at cfl 1 that a passing valve event never lets grow but
  // that grows at rest (measured: the crank standing at 349 deg with the exhaust valve open,
  // T_cyl 380 -> 7000 K within 1.5 s); the slow-crank limit coupling_cylinder_cfl_slow damps it.
  const double cfl = omega < P_.engine.slowCrank_rad_s() ? P_.engine.coupling_cylinder_cfl_slow
                                                         : P_.engine.coupling_cylinder_cfl;
  if (!(cfl > 0.0)) return std::numeric_limits<double>::infinity();
  const PerfectGas& g = exhaust_.gas();
  double dt = std::numeric_limits<double>::infinity();
  for (const CylinderSlot& s : cyl_) {
    double fi, ri, fe, re;
    const double th = s.cyl->crankAngle_deg();
    s.area_in->areasAt(th, fi, ri);
    s.area_ex->areasAt(th, fe, re);
    const double A = std::max(fi, ri) + std::max(fe, re);
    if (A <= 0.0) continue;
    const double c = std::sqrt(g.gamma * g.R * s.cyl->temperature_K());
    dt = std::min(dt, cfl * s.cyl->volume_m3() / (c * A));
  }
  return dt;
}

void EngineAssembly::coupledStep(double dt, double omega) {
  stepNetworks(dt, omega);
  std::array<double, kNumChannels> x{};
  StepSums sums;
  const double dth = omega * dt / kRad_per_deg;
  const int nsub_closed = std::max(1, static_cast<int>(std::ceil(dth / substep_deg_ - 1e-9)));
  const int nsub_open = std::max(1, static_cast<int>(std::ceil(dth / substep_open_deg_ - 1e-9)));
  for (CylinderSlot& s : cyl_) {
    advanceCylinder(s, dt, omega, nsub_closed, nsub_open, x);
    accumulateCylinder(s, sums);
  }
  stepTurboShaft(dt);
  accumulateTotals(sums, dt, omega);
  recordStep(sums, dt, omega, x);
  t_ += dt;
  ++steps_;
}

// Valve boundaries at the cylinders' states (areas led by half a step if configured), the
// turbocharger speed, then both pipe networks over dt.
void EngineAssembly::stepNetworks(double dt, double omega) {
  for (CylinderSlot& s : cyl_) {
    const double p = s.cyl->pressure_Pa(), T = s.cyl->temperature_K();
    s.res_in->setReservoirState(p, T);
    s.res_ex->setReservoirState(p, T);
  }
  const double lead = P_.engine.valve_area_midstep ? 0.5 * omega * dt / kRad_per_deg : 0.0;
  for (CylinderSlot& s : cyl_) {
    s.area_in->setLead(lead);
    s.area_ex->setLead(lead);
  }
  const double wtc = shaft_.omega();
  comp_->setSpeed(wtc);
  turb_[0]->setSpeed(wtc);
  turb_[1]->setSpeed(wtc);
  intake_.step(dt);  // dt <= both networks' stable steps (advance() checked them)
  exhaust_.step(dt);
}

// Intake valve: mass flow [kg/s] (> 0 into the cylinder) and its PortFlow. Inflow at the
// runner's stagnation temperature carries the buffered back-flow's burned gas first; back-flow
// leaves at the cylinder's enthalpy and fills the buffer.
double EngineAssembly::intakePortFlow(CylinderSlot& s, double dt, cylinder::PortFlow& pf) {
  const cylinder::Cylinder& c = *s.cyl;
  const gasdyn::EndFlux& fi = s.run_in->endFlux(End::Right);
  const double mi = -fi.mdot_in;
  if (mi > 0.0) {
    const double T0 = -fi.energy_in / (mi * cp_in_), dm = mi * dt;
    double xb = 0.0;
    if (s.back_m > 0.0) {
      const double take = std::min(s.back_m, dm);
      xb = s.back_xb * take / dm;
      s.back_m -= take;
    }
    pf = {mi, mi * c.enthalpyOf(T0, xb), xb};
  } else if (mi < 0.0) {
    const double dm = -mi * dt, xbc = c.burnedFraction();
    s.back_xb = (s.back_m * s.back_xb + dm * xbc) / (s.back_m + dm);
    s.back_m += dm;
    pf = {mi, mi * c.specificEnthalpy_J_kg(), 0.0};
  }
  return mi;
}

// Exhaust valve: mass flow [kg/s] (> 0 into the cylinder) and its PortFlow. Back-flow carries
// its bank's burned fraction; outflow is counted in the step's channels x.
double EngineAssembly::exhaustPortFlow(const CylinderSlot& s, cylinder::PortFlow& pf,
                                       std::array<double, kNumChannels>& x) const {
  const cylinder::Cylinder& c = *s.cyl;
  const gasdyn::EndFlux& fe = s.run_ex->endFlux(End::Left);
  const double me = -fe.mdot_in;
  const int bank = s.bank;
  if (me > 0.0) {
    const double T0 = -fe.energy_in / (me * cp_ex_), xb = xb_bank_[bank];
    pf = {me, me * c.enthalpyOf(T0, xb), xb};
  } else if (me < 0.0) {
    const double xbc = c.burnedFraction();
    pf = {me, me * c.specificEnthalpy_J_kg(), 0.0};
    x[kCylOut] -= me;
    x[kBurnedOut] -= me * xbc;
    x[kBankOut0 + bank] -= me;
    x[kBankBurned0 + bank] -= me * xbc;
  }
  return me;
}

// One cylinder over the coupled step: its port flows, then sub-steps of <= cylinder_substep_deg
// with the port mass flows of this coupled step; outflows leave at the cylinder's current
// specific enthalpy of each sub-step.
void EngineAssembly::advanceCylinder(CylinderSlot& s, double dt, double omega, int nsub_closed,
                                     int nsub_open, std::array<double, kNumChannels>& x) {
  cylinder::Cylinder& c = *s.cyl;
  cylinder::PortFlows pf;
  const double mi = intakePortFlow(s, dt, pf.intake);
  const double me = exhaustPortFlow(s, pf.exhaust, x);
  const double ivc = P_.cylinder.ivc_deg, evo = P_.cylinder.evo_deg;
  const double th = c.crankAngle_deg();
  const int nsub = th >= ivc && th < evo ? nsub_closed : nsub_open;
  const double dts = dt / nsub;
  for (int j = 0; j < nsub; ++j) {
    if (j > 0 && mi < 0.0) pf.intake.Hdot_W = mi * c.specificEnthalpy_J_kg();
    if (j > 0 && me < 0.0) pf.exhaust.Hdot_W = me * c.specificEnthalpy_J_kg();
    totals_.intake_enthalpy_J += pf.intake.Hdot_W * dts;
    totals_.exhaust_enthalpy_J -= pf.exhaust.Hdot_W * dts;
    c.advance(dts, omega, pf);
  }
}

// The cylinder's indicated work, wall heat, NOx (at each cycle end) and fuel injected over the
// step, added to the step's sums.
void EngineAssembly::accumulateCylinder(CylinderSlot& s, StepSums& sums) {
  const cylinder::Cylinder& c = *s.cyl;
  const int cycles = c.cyclesCompleted();
  double dW, dQ;
  if (cycles != s.prev_cycles) {
    const cylinder::CycleResults& r = c.lastCycle();
    dW = r.work_net_J - s.prev_work + c.workThisCycle_J();
    dQ = r.heat_wall_J - s.prev_wall + c.wallHeatThisCycle_J();
    sums.nox_kg += r.nox_no2eq_kg;
    s.prev_cycles = cycles;
  } else {
    dW = c.workThisCycle_J() - s.prev_work;
    dQ = c.wallHeatThisCycle_J() - s.prev_wall;
  }
  s.prev_work = c.workThisCycle_J();
  s.prev_wall = c.wallHeatThisCycle_J();
  double inj = 0.0;
  for (int i = 0; i < 3; ++i) inj += c.pulseInjected_kg(i);  // the cylinder's injection pulses
  if (inj < s.prev_inj) s.prev_inj = 0.0;
  sums.fuel_kg += inj - s.prev_inj;
  s.prev_inj = inj;
  sums.work_J += dW;
  sums.wall_J += dQ;
}

// Turbocharger shaft over dt with the turbines' and the compressor's power.
void EngineAssembly::stepTurboShaft(double dt) {
  const double Pt = turb_[0]->power() + turb_[1]->power(), Pc = comp_->power();
  requireFinite(Pt, "turbine", "power");
  requireFinite(Pc, "compressor", "power");
  shaft_.step(dt, Pt, Pc);
  if (!std::isfinite(shaft_.omega()) || shaft_.omega() > 5e4)
    throw ModelDivergence("turbocharger shaft", "speed",
                          "omega = " + std::to_string(shaft_.omega()) + " rad/s");
}

void EngineAssembly::accumulateTotals(const StepSums& sums, double dt, double omega) {
  const double lhv = P_.cylinder.fuel.lhv_J_kg;
  totals_.fuel_kg += sums.fuel_kg;
  totals_.fuel_energy_J += sums.fuel_kg * lhv;
  totals_.indicated_work_J += sums.work_J;
  totals_.friction_work_J += fric_torque_ * omega * dt;
  interval_.indicated_J += sums.work_J;
  interval_.friction_J += fric_torque_ * omega * dt;
  totals_.wall_heat_J += sums.wall_J;
  totals_.nox_kg += sums.nox_kg;
}

// The step's channels into the cycle window.
void EngineAssembly::recordStep(const StepSums& sums, double dt, double omega,
                                std::array<double, kNumChannels>& x) {
  x[kIndTorque] = omega > 0.0 ? sums.work_J / (omega * dt) : gasTorque_Nm();
  x[kFricTorque] = fric_torque_;
  x[kAir] = comp_->massFlow();
  x[kExhOut] = -back_end_->massFlowIn();
  x[kExhEnth] = -down_pipe_->endFlux(End::Right).energy_in;
  gasStateChannels(x);
  // fuel injected, wall heat and NOx of this step as rates over the step (the window splits a
  // step over its bins by crank angle; impulses at the step end would phase-lock with the bins)
  x[kFuel] = sums.fuel_kg / dt;
  x[kWallHeat] = sums.wall_J / dt;
  x[kNox] = sums.nox_kg / dt;
  window_.add(dt, omega * dt / kRad_per_deg, x);
}

void EngineAssembly::gasStateChannels(std::array<double, kNumChannels>& x) const {
  x[kBoost] = plenum_->p();
  x[kImT] = plenum_->T();
  const int n0 = turb_pipe_[0]->cells() - 1, n1 = turb_pipe_[1]->cells() - 1;
  x[kP3] = 0.5 * (turb_pipe_[0]->p(n0) + turb_pipe_[1]->p(n1));
  x[kT3] = 0.5 * (turb_pipe_[0]->T(n0) + turb_pipe_[1]->T(n1));
}

}  // namespace hbt::engine_1d
