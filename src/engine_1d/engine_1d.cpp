#include "engine_1d/engine_1d.hpp"

#include <time.h>

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/friction_heat.hpp"
#include "common/units.hpp"

namespace hbt::engine_1d {
namespace {
constexpr double kStoppedRadS = units::rpmToRadps(200.0);  // lowest speed of a reset()
// Below this the crank stands (omega = 0): the vehicle's friction stops it exponentially, so its
// speed decays through denormals, where omega dt underflows and W/(omega dt) is 0/0 [rad/s]
constexpr double kStandingRadS = 1e-6;

double threadCpu() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

void check(double v, const char* name) {
  if (!std::isfinite(v)) throw ModelDivergence("engine_1d outputs", name, "non-finite value");
}
}  // namespace

Engine1D::Engine1D(const Engine1DParams& p, const std::string& root) : P_(p) {
  P_.validate();
  tc_ = std::make_unique<turbo::Turbocharger>(turbo::buildTurbocharger(P_.turbo, root));
  // The reference map engine serves as the bench map (limits, feed-forward fuel, validation);
  // its NOx map is derived FROM this engine (src/engine_1d/tools/make_nox_map.py), so it is not
  // loaded here: the 1D engine runs (and regenerates the map) without it.
  engine_map::MapEngineParams ref_params = P_.reference;
  ref_params.nox_map_file.clear();
  ref_ = std::make_unique<engine_map::MapEngine>(ref_params, root);
  maps_ = EngineAssembly::FlowMaps::build(*tc_);
  cylinder::Cylinder probe(P_.cylinder, "probe");
  ctl_ = std::make_unique<EngineControllers>(P_.engine, probe.thermo().afrStoich(),
                                             P_.cylinder.fuel_ref_kg);
  reset(units::rpmToRadps(1200.0), 0.0);
}

Engine1D::~Engine1D() = default;

void Engine1D::reset(double w, double torque, double T_amb, double p_amb, double coolant) {
  w = std::max(w, kStoppedRadS);
  const double tfl = ref_->fullLoadTorque(w), tmot = ref_->motoringTorque(w);
  const double treq = EngineControllers::limitedRequest(torque, tfl, tmot);
  const double load = std::clamp(treq / tfl, 0.0, 1.0);
  const double rpm = units::radpsToRpm(w);
  EngineAssembly::Initial in;
  in.p_amb = p_amb;
  in.T_amb = T_amb;
  in.coolant_K = coolant;
  in.p_im = ctl_->boostTarget(w, load, p_amb);
  in.T_im = T_amb + 10.0 + 25.0 * load;
  in.p3 = in.p_im * (1.0 + 0.15 * load) + 5000.0;
  in.T3 = 550.0 + 350.0 * load;
  in.turbo_rad_s = units::rpmToRadps(P_.engine.initial_turbo_speed_rpm) *
                   std::clamp(0.35 + 0.65 * load, 0.2, 1.0) * std::sqrt(std::min(rpm / 1400.0, 1.6));
  const double cps = P_.engine.cylinders * w / (4.0 * units::kPi);  // cylinder-cycles per second
  in.fuel_per_cycle_kg = treq > tmot ? ref_->steadyFuel(w, treq) / cps : 0.0;
  asm_.reset();
  asm_ = std::make_unique<EngineAssembly>(P_, *tc_, maps_, in);
  ctl_->reset(0.5, treq);
  cmd_ = ControlCommand();
  cmd_.fuel_per_cycle_kg = in.fuel_per_cycle_kg;
  cmd_.wastegate_opening = 0.5;
  asm_->setWastegateOpening(0.5);
  out_ = Engine1DOutputs();
  out_.brake_torque_Nm = treq;
  out_.boost_pressure_Pa = in.p_im;
  out_.air_mass_flow_kg_s = 0.0;
  back_p_ = p_amb + 2000.0;
  asm_->setBackPressure(back_p_, in.T3 - 100.0);
  asm_->setAmbient(p_amb, T_amb);
}

const Engine1DOutputs& Engine1D::step(double dt, const Engine1DInputs& in) {
  const double cpu0 = threadCpu();
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw ModelDivergence("engine_1d inputs", "dt", "macro step must be finite and > 0");
  for (double v : {in.speed_rad_s, in.torque_request_Nm, in.ambient_T_K, in.ambient_p_Pa,
                   in.back_pressure_Pa, in.coolant_T_K, in.oil_T_K})
    if (!std::isfinite(v)) throw ModelDivergence("engine_1d inputs", "input", "non-finite input");
  if (!(in.ambient_T_K > 150.0 && in.ambient_p_Pa > 3e4))
    throw ModelDivergence("engine_1d inputs", "ambient", "ambient state out of range");
  // the driveline never turns it backwards; below kStandingRadS it stands
  const double w = in.speed_rad_s >= kStandingRadS ? in.speed_rad_s : 0.0;
  out_.max_torque_Nm = ref_->fullLoadTorque(w);
  out_.min_torque_Nm = ref_->motoringTorque(w);
  EngineAssembly& A = *asm_;
  CycleMeans m;
  A.cycleMeans(m);
  // boundary conditions
  A.setAmbient(in.ambient_p_Pa, in.ambient_T_K);
  A.setCoolantTemperature(in.coolant_T_K);
  A.setOilTemperature(in.oil_T_K);
  const double T_exh = out_.exhaust_T_K > 0.0 ? out_.exhaust_T_K : 600.0;
  if (in.back_pressure_Pa > 0.0) {
    back_p_ = in.back_pressure_Pa;
  } else {
    const Engine1DConfig& E = P_.engine;
    const double K = E.back_dp_ref_Pa * E.back_ref_p_Pa /
                     (E.back_ref_flow_kg_s * E.back_ref_flow_kg_s * E.back_ref_T_K);
    const double mdot = std::max(m[kExhOut], 0.0);
    back_p_ = in.ambient_p_Pa + std::min(K * mdot * mdot * T_exh / std::max(back_p_, in.ambient_p_Pa),
                                         0.5 * in.ambient_p_Pa);
  }
  A.setBackPressure(back_p_, T_exh);
  // controllers
  ControlInputs ci;
  ci.omega = w;
  ci.torque_request = in.torque_request_Nm;
  ci.full_load = out_.max_torque_Nm;
  ci.motoring = out_.min_torque_Nm;
  ci.brake_torque = A.windowFull() ? m[kIndTorque] - m[kFricTorque] : out_.brake_torque_Nm;
  ci.boost = A.windowFull() ? m[kBoost] : A.intakeManifoldPressure();
  ci.ambient_p = in.ambient_p_Pa;
  ci.air_flow = A.windowFull() ? m[kAir] : A.compressorMassFlow();
  ci.fuel_enabled = in.fuel_enabled;
  const double treq = EngineControllers::limitedRequest(in.torque_request_Nm, ci.full_load, ci.motoring);
  ci.feedforward_fuel_kg_s = ref_->steadyFuel(w, treq);
  cmd_ = ctl_->update(dt, ci);
  A.setFuelPerCycle(cmd_.fuel_per_cycle_kg);
  A.setWastegateOpening(cmd_.wastegate_opening);
  // gas dynamics and cylinders
  A.advance(dt, w);
  computeOutputs(dt, w, in);
  computeCrankTorque(w);
  // Brake work of the published (cycle-mean) torque over this macro step, split by sign as the
  // map engine does, so the vehicle-side energy balance sees the same numbers.
  const double work_J = out_.brake_torque_Nm * w * dt;
  out_.brake_work_J += work_J;
  (work_J > 0.0 ? out_.positive_work_J : out_.motoring_work_J) += work_J;
  out_.cpu_time_s = threadCpu() - cpu0;
  out_.cpu_time_total_s += out_.cpu_time_s;
  return out_;
}

// The torque on the crank over this macro step, T_c = (W_ind - W_f)/(omega dt): the exact mean
// over the step's crank angle (compression pulses resolved: the load of a crank that is cranked;
// the cycle mean would smear them over 720 deg and book another energy than the crank
// exchanged). At omega = 0: the gas torque at the standing crank angle less the friction
// (Coulomb: the crank turns only if the gas pushes harder than the friction holds).
void Engine1D::computeCrankTorque(double w) {
  const EngineAssembly& A = *asm_;
  const EngineAssembly::Interval& iv = A.lastInterval();
  const double angle = w * iv.duration_s;
  const double T_ind = angle > 0.0 ? iv.indicated_J / angle : A.gasTorque_Nm();
  const double T_f = angle > 0.0 ? iv.friction_J / angle : A.frictionTorque();
  out_.crank_torque_Nm = T_ind - T_f;
  check(out_.crank_torque_Nm, "crank torque");
}

void Engine1D::computeOutputs(double dt, double w, const Engine1DInputs& in) {
  const EngineAssembly& A = *asm_;
  CycleMeans m;
  A.cycleMeans(m);
  Engine1DOutputs& o = out_;
  o.indicated_torque_Nm = m[kIndTorque];
  o.friction_torque_Nm = m[kFricTorque];
  o.brake_torque_Nm = m[kIndTorque] - m[kFricTorque];
  o.fuel_mass_flow_kg_s = m[kFuel];
  o.fuel_mass_kg = A.totals().fuel_kg;
  o.fuel_per_cycle_kg = cmd_.fuel_per_cycle_kg;
  o.boost_pressure_Pa = m[kBoost];
  o.boost_target_Pa = cmd_.boost_target_Pa;
  o.intake_manifold_T_K = m[kImT];
  o.turbo_speed_rad_s = A.turboSpeed();
  o.wastegate_opening = A.wastegateOpening();
  o.air_mass_flow_kg_s = m[kAir];
  const cylinder::GasThermo& th = A.cylinder(0).thermo();
  o.lambda = m[kFuel] > 0.0 ? m[kAir] / (th.afrStoich() * m[kFuel]) : 0.0;
  o.exhaust_mass_flow_kg_s = m[kExhOut];
  const double cp_ex = P_.turbo.exhaust_gamma * P_.turbo.exhaust_gas_constant /
                       (P_.turbo.exhaust_gamma - 1.0);
  if (m[kExhOut] > 1e-6) o.exhaust_T_K = m[kExhEnth] / (m[kExhOut] * cp_ex);
  const double xb = std::clamp(A.exhaustBurnedFraction(), 0.0, 1.0);
  auto y = [&](cylinder::Species s) {
    return (1.0 - xb) * th.massFraction(cylinder::kAir, s) + xb * th.massFraction(cylinder::kBurned, s);
  };
  o.exhaust.y_O2 = y(cylinder::kO2);
  o.exhaust.y_N2 = y(cylinder::kN2);
  o.exhaust.y_CO2 = y(cylinder::kCO2);
  o.exhaust.y_H2O = y(cylinder::kH2O);
  o.exhaust.y_Ar = y(cylinder::kAr);
  o.exhaust.y_NOx = m[kExhOut] > 1e-6 ? std::min(m[kNox] / m[kExhOut], 0.1) : 0.0;
  o.back_pressure_Pa = back_p_;
  o.nox_mass_flow_kg_s = m[kNox];
  o.nox_mass_kg = A.totals().nox_kg;
  o.friction_W = m[kFricTorque] * w;
  const EngineHeatSplit heat = splitEngineHeat(m[kWallHeat], o.friction_W, P_.engine.friction_heat_to_oil_fraction);
  o.coolant_heat_W = heat.metal_W;
  o.coolant_heat_J += o.coolant_heat_W * dt;
  o.oil_heat_W = heat.oil_W;
  o.oil_heat_J += o.oil_heat_W * dt;
  o.peak_cylinder_pressure_Pa = A.peakPressureLastCycles();
  o.turbine_inlet_p_Pa = m[kP3];
  o.turbine_inlet_T_K = m[kT3];
  o.fuel_cut = cmd_.fuel_cut;
  o.smoke_limited = cmd_.smoke_limited;
  o.sim_time_s += dt;
  o.gas_steps = A.steps();
  (void)in;
  check(o.brake_torque_Nm, "brake_torque_Nm");
  check(o.fuel_mass_flow_kg_s, "fuel_mass_flow_kg_s");
  check(o.boost_pressure_Pa, "boost_pressure_Pa");
  check(o.turbo_speed_rad_s, "turbo_speed_rad_s");
  check(o.lambda, "lambda");
  check(o.air_mass_flow_kg_s, "air_mass_flow_kg_s");
  check(o.exhaust_mass_flow_kg_s, "exhaust_mass_flow_kg_s");
  check(o.exhaust_T_K, "exhaust_T_K");
  check(o.nox_mass_flow_kg_s, "nox_mass_flow_kg_s");
  check(o.coolant_heat_W, "coolant_heat_W");
  check(o.oil_heat_W, "oil_heat_W");
  check(o.turbine_inlet_p_Pa, "turbine_inlet_p_Pa");
  check(o.turbine_inlet_T_K, "turbine_inlet_T_K");
}

}  // namespace hbt::engine_1d
