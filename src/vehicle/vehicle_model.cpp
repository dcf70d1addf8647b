// VehicleModel: construction, macro step (shift decision, substeps, driver + idle governor).
#include "vehicle/vehicle_model.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace hbt::vehicle {
namespace {

std::string resolve(const std::string& base, const std::string& path) {
  if (base.empty() || path.empty() || path[0] == '/') return path;
  return base + (base.back() == '/' ? "" : "/") + path;
}

}  // namespace

VehicleModel::VehicleModel(const VehicleParams& p, const std::string& base_dir) : p_(p) {
  p_.validate();
  const auto& d = p_.driveline;
  const auto& c = p_.chassis;
  road_ = RoadLoad(c);
  tc_ = TorqueConverter(resolve(base_dir, d.torque_converter_file), d.tc_reference_speed_rad_s);
  gear_loss_map_ = GearLossMap(resolve(base_dir, p_.gearbox.gear_loss_map_file));
  ret_ = RetarderLoss(resolve(base_dir, d.retarder_loss_file));
  gb_oil_ = OilThermalNode(p_.driveline_oil.gearbox);
  axle_oil_ = OilThermalNode(p_.driveline_oil.axle);
  shift_ = ShiftStrategy(p_.shift, d.gear_ratios, d.idle_speed_rad_s);
  const double m = p_.totalMass_kg();
  driver_ = Driver(p_.driver, m);
  F_brake_max_ = driver_.maxBrakeForce();
  const double r = c.tyre_radius_m;
  inertia_mass_kg_ = m + (c.tyres_front + c.tyres_rear) * c.wheel_inertia_kg_m2 / (r * r);
  axle_ratio_per_radius_1_m_ = d.axle_ratio / r;
  k_.assign(d.gear_ratios.size() + 1, 0.0);
  for (std::size_t g = 1; g <= d.gear_ratios.size(); ++g) k_[g] = d.gear_ratios[g - 1] * axle_ratio_per_radius_1_m_;
  engine_inertia_kg_m2_ = d.engine_inertia_kg_m2 + d.tc_pump_inertia_kg_m2;
  gearbox_input_inertia_kg_m2_ = d.gearbox_input_inertia_kg_m2;
  reset(0.0, 0, d.idle_speed_rad_s);
}

void VehicleModel::setGradeProfile(const std::vector<double>& s, const std::vector<double>& g) {
  grade_profile_ = Table1D(s, g, "grade profile", "distance_m");
}

void VehicleModel::reset(double v, int gear, double w_e, double distance_m) {
  const int n = static_cast<int>(p_.driveline.gear_ratios.size());
  if (gear < 0 || gear > n) throw InputError("(vehicle reset)", "gear", "out of range");
  if (!std::isfinite(v) || !std::isfinite(w_e)) throw InputError("(vehicle reset)", "speed", "not finite");
  out_ = VehicleOutputs{};
  v_ = std::max(v, 0.0);
  w_ = std::max(w_e, 0.0);
  s_ = distance_m;
  h_ = 0.0;
  t_since_shift_ = kNoShiftYet_s;
  T_in_est_ = T_ax_est_ = 0.0;
  brake_force_ = accel_pedal_ = idle_integral_ = crank_accel_ = 0.0;
  hold_ = start_request_ = locking_ = false;
  oil_set_ = false;
  last_dv_ = 0.0;
  s_target_ = s_;
  v_target_prev_ = v_;
  driver_.reset();
  if (gear == 0) {
    gear_state_ = {DriveMode::Neutral, 0};
  } else if (gear == 1 && v_ * k_[1] < p_.shift.lockup_min_turbine_speed_rad_s) {
    gear_state_ = {DriveMode::Converter, 1};
  } else {
    gear_state_ = {DriveMode::Locked, gear};
    w_ = k_[gear] * v_;
  }
  out_.energy.kinetic_initial_J = out_.energy.kinetic_J = kineticEnergy();
  out_.engine_speed_rad_s = w_;
  out_.speed_m_s = v_;
  out_.distance_m = s_;
  out_.gear = gear_state_.gear;
  out_.mode = gear_state_.mode;
}

void VehicleModel::setOilTemperatures(double gearbox_K, double axle_K) {
  if (!(gearbox_K > 0.0) || !(axle_K > 0.0))
    throw InputError("(vehicle oil temperatures)", "driveline_oil", "must be > 0 K");
  gb_oil_.reset(gearbox_K);
  axle_oil_.reset(axle_K);
  oil_set_ = true;
  out_.gearbox_oil_T_K = gearbox_K;
  out_.axle_oil_T_K = axle_K;
  out_.gearbox_drag_factor = oilDragFactor(p_.driveline_oil.gearbox, gearbox_K);
}

double VehicleModel::gearboxOilHeat_J() const {
  const VehicleEnergy& e = out_.energy;
  return e.gearbox_drag_J + e.gear_load_loss_J + e.tc_loss_J + e.shift_loss_J + e.retarder_J;
}

void VehicleModel::stepOilNodes(double dt, double gb_J0, double axle_J0, double T_amb) {
  const double q_gb = gearboxOilHeat_J() - gb_J0, q_ax = out_.energy.axle_loss_J - axle_J0;
  gb_oil_.step(dt, q_gb, T_amb);
  axle_oil_.step(dt, q_ax, T_amb);
  out_.gearbox_oil_heat_W = q_gb / dt;
  out_.axle_oil_heat_W = q_ax / dt;
  out_.gearbox_cooler_W = gb_oil_.lastCoolerPower_W();
  out_.gearbox_oil_T_K = gb_oil_.temperature_K();
  out_.axle_oil_T_K = axle_oil_.temperature_K();
}

double VehicleModel::auxPower(const VehicleInputs& in) const {
  const auto& a = p_.aux;
  return a.steering_pump_W + a.air_compressor_W + a.alternator_W + aux_payback_W_ +
         (in.has_fan_power ? in.fan_power_W : a.fan_default_W) + hvacCrankPower(in);
}

double VehicleModel::hvacCrankPower(const VehicleInputs& in) const {
  const auto& a = p_.aux;
  return in.hvac_compressor_W + (a.electricViaDcdc() ? 0.0 : in.hvac_electric_W / a.alternator_efficiency);
}

void VehicleModel::bookAuxConsumers(double dE_aux_J, double P_aux_W, const VehicleInputs& in) {
  if (std::fabs(P_aux_W) < 1e-9) return;  // no aux power: no aux work this step either
  const auto& a = p_.aux;
  const double per_W = dE_aux_J / P_aux_W;  // the step's aux work per watt of aux power [s]
  VehicleEnergy& e = out_.energy;
  e.fan_J += per_W * (in.has_fan_power ? in.fan_power_W : a.fan_default_W);
  const double P_def = a.steering_pump_W + a.air_compressor_W;
  const double f = P_def > 0.0 ? 1.0 + aux_payback_W_ / P_def : 1.0;  // stop-start payback share
  e.steering_J += per_W * a.steering_pump_W * f;
  e.pneumatic_J += per_W * a.air_compressor_W * f;
  if (aux_payback_W_ > 0.0) e.aux_deferred_J = std::max(0.0, e.aux_deferred_J - per_W * aux_payback_W_);
  e.electric_J += per_W * a.alternator_W;
  e.hvac_J += per_W * hvacCrankPower(in);
}

const VehicleOutputs& VehicleModel::step(double dt, const VehicleInputs& in) {
  const double vals[] = {in.target_speed_m_s, in.target_accel_m_s2, in.road_grade,
                         in.engine_torque_Nm, in.engine_max_torque_Nm, in.engine_min_torque_Nm,
                         in.em_torque_Nm, in.em_max_torque_Nm, in.friction_brake_force_N,
                         in.fan_power_W, in.ambient_T_K, in.accel_pedal_cmd, in.brake_pedal_cmd,
                         in.hvac_compressor_W, in.hvac_electric_W};
  for (double x : vals)
    if (!std::isfinite(x)) throw ModelDivergence("vehicle", "inputs", "non-finite input");
  if (!(dt > 0.0)) throw ModelDivergence("vehicle", "dt", "must be > 0");

  const double grade = grade_profile_.empty() ? in.road_grade : grade_profile_(s_);
  if (!oil_set_) setOilTemperatures(in.ambient_T_K, in.ambient_T_K);  // cold start at ambient
  const double gb_J0 = gearboxOilHeat_J(), axle_J0 = out_.energy.axle_loss_J;
  if (!in.driver_enabled) {
    brake_force_ = std::clamp(in.brake_pedal_cmd, 0.0, 1.0) * F_brake_max_;
    accel_pedal_ = std::clamp(in.accel_pedal_cmd, 0.0, 1.0);
    start_request_ = accel_pedal_ > 0.0;
    hold_ = v_ == 0.0 && brake_force_ > 0.0 && accel_pedal_ == 0.0;
  }

  // 1. Shift / lock-up decision at the start of the step.
  GearState target = gear_state_;
  if (in.neutral_request) {
    target = {DriveMode::Neutral, 0};
  } else {
    ShiftInputs si;
    si.engine_speed_rad_s = w_;
    si.gearbox_input_speed_rad_s = gearboxInputSpeed(v_, w_);
    si.output_speed_rad_s = v_ * axle_ratio_per_radius_1_m_;
    si.accel_pedal = accel_pedal_;
    si.time_since_shift_s = t_since_shift_;
    si.stopped_and_held = v_ == 0.0 && hold_;
    si.start_request = start_request_;
    target = shift_.decide(gear_state_, si);
    // A stopped (or cranking) engine cannot drive the converter: stay in neutral until it runs.
    if (!in.engine_on && gear_state_.mode == DriveMode::Neutral) target = gear_state_;
  }
  const int gear_before = gear_state_.gear;
  if (target != gear_state_) transition(target);
  out_.gear_changed = gear_state_.gear != gear_before;

  // 2. Integrate the macro step with the inputs held. Stop-start debt of the steering pump and
  // compressor: owed while the engine stands, repaid at up to their own power once it runs.
  const double P_def = p_.aux.steering_pump_W + p_.aux.air_compressor_W;
  aux_payback_W_ = in.engine_on ? std::min(P_def, out_.energy.aux_deferred_J / dt) : 0.0;
  StepConst c;
  c.T_e = in.engine_torque_Nm;
  c.T_em = in.em_torque_Nm;
  c.P_aux = auxPower(in);
  c.F_brake = in.brake_override ? std::max(0.0, in.friction_brake_force_N) : brake_force_;
  c.engine_on = in.engine_on;
  out_.applied_brake_force_N = c.F_brake;
  c.grade = grade;
  c.rho = road_.airDensity(in.ambient_T_K);
  c.rr_factor = road_.rollingTemperatureFactor(in.ambient_T_K);
  c.drag_factor = oilDragFactor(p_.driveline_oil.gearbox, gb_oil_.temperature_K());
  out_.tyre_rr_factor = c.rr_factor;
  out_.gearbox_drag_factor = c.drag_factor;
  const double v_start = v_, aux_start_J = out_.energy.aux_J, w_start = w_;
  const int n = std::max(1, static_cast<int>(std::ceil(dt / p_.numerics.max_substep_s - 1e-9)));
  for (int i = 0; i < n; ++i) substep(dt / n, c);
  crank_accel_ = (w_ - w_start) / dt;  // torque-driven, after this step's clutch impulse
  if (!std::isfinite(v_) || !std::isfinite(w_))
    throw ModelDivergence("vehicle", "state", "speed became non-finite");
  t_since_shift_ += dt;
  const double def_start_J = out_.energy.steering_J + out_.energy.pneumatic_J;
  bookAuxConsumers(out_.energy.aux_J - aux_start_J, c.P_aux, in);
  if (!in.engine_on)  // what the standing pump and compressor did not get this step is owed
    out_.energy.aux_deferred_J += std::max(
        0.0, P_def * dt - (out_.energy.steering_J + out_.energy.pneumatic_J - def_start_J));
  stepOilNodes(dt, gb_J0, axle_J0, in.ambient_T_K);

  // 3. Driver and idle governor at t + dt: pedals, brake force and torque request.
  evaluateDriver(dt, in);

  out_.speed_m_s = v_;
  out_.accel_m_s2 = (v_ - v_start) / dt;
  out_.distance_m = s_;
  out_.altitude_m = h_;
  out_.grade = grade_profile_.empty() ? in.road_grade : grade_profile_(s_);
  out_.engine_speed_rad_s = w_;
  out_.gear = gear_state_.gear;
  out_.mode = gear_state_.mode;
  out_.tc_locked = gear_state_.mode == DriveMode::Locked || gear_state_.mode == DriveMode::Shifting;
  const double w_in = gearboxInputSpeed(v_, w_);
  out_.gearbox_input_speed_rad_s = gear_state_.mode == DriveMode::Neutral ? 0.0 : w_in;
  if (gear_state_.mode == DriveMode::Converter) {
    out_.tc_speed_ratio = tc_.speedRatio(w_, w_in);
    out_.tc_pump_torque_Nm = tc_.pumpTorque(w_, w_in);
    out_.tc_turbine_torque_Nm = tc_.turbineTorque(w_, w_in);
  } else {
    out_.tc_speed_ratio = out_.tc_locked ? 1.0 : 0.0;
    out_.tc_pump_torque_Nm = out_.tc_turbine_torque_Nm = 0.0;
  }
  out_.aux_power_W = c.P_aux;
  out_.dcdc_input_power_W = p_.aux.electric_dcdc_W / p_.aux.dcdc_efficiency +
                            (p_.aux.electricViaDcdc() ? in.hvac_electric_W / p_.aux.dcdc_efficiency : 0.0);
  out_.energy.dcdc_J += out_.dcdc_input_power_W * dt;
  out_.energy.kinetic_J = kineticEnergy();
  return out_;
}

void VehicleModel::evaluateDriver(double dt, const VehicleInputs& in) {
  const auto& d = p_.driveline;
  const double grade = grade_profile_.empty() ? in.road_grade : grade_profile_(s_);
  StepConst c{0.0, in.em_torque_Nm, auxPower(in), 0.0, grade, road_.airDensity(in.ambient_T_K), true,
              road_.rollingTemperatureFactor(in.ambient_T_K),
              oilDragFactor(p_.driveline_oil.gearbox, gb_oil_.temperature_K())};
  const Rates r = rates(v_, w_, c, 1);  // present loss torques (T_e = 0)
  const double T_min = in.engine_min_torque_Nm;
  // The demand is the whole crank torque (engine + e-machine): the driver's full pedal asks both
  // maxima; the split is the EMS's (hybrid) or all the engine's (baseline: em = 0).
  const double T_max_total = in.engine_max_torque_Nm + std::max(0.0, in.em_max_torque_Nm);
  double T_max = std::max(T_max_total, T_min);
  const double T_loss_crank = r.T_aux + r.T_drag;
  const double F_drag_out = axle_ratio_per_radius_1_m_ * (r.T_ret + r.T_axl);
  double M_eff = inertia_mass_kg_, F_min = 0.0, F_max = 0.0;
  const bool locked = gear_state_.mode == DriveMode::Locked || gear_state_.mode == DriveMode::Shifting;
  const int g = locked ? gear_state_.gear : 1;
  const double k = k_[g];
  const double mu = locked ? 1.0 : tc_.torqueRatio(tc_.speedRatio(w_, v_ * k_[1]));
  const double limit = d.gear_max_input_torque_Nm[g - 1];
  if (limit > 0.0) T_max = std::min(T_max, std::max(T_min, limit / mu));
  if (locked) M_eff += (engine_inertia_kg_m2_ + gearbox_input_inertia_kg_m2_) * k * k;
  else M_eff += gearbox_input_inertia_kg_m2_ * k * k;
  // Torque at zero accelerator (pedal 0 = this, pedal 1 = T_max). Locked: the motoring torque
  // (overrun). Converter (and neutral, about to engage 1C): the idle governor keeps the engine
  // at idle against aux + pump torque, so the least force the driveline gives is the creep
  // force of the converter at idle, not the motoring torque multiplied by mu (the engine cannot
  // be pulled below idle through an open converter).
  double T_floor = T_min;
  const double T_side = r.T_gload + r.T_drag_in;  // input-shaft losses
  F_max = k * (mu * (T_max - T_loss_crank) - T_side) - F_drag_out;
  if (locked) {
    F_min = k * (mu * (T_min - T_loss_crank) - T_side) - F_drag_out;
  } else {
    const double w_i = d.idle_speed_rad_s, w_t = v_ * k_[1];
    const double T_idle = c.P_aux / w_i + r.T_drag + tc_.pumpTorque(w_i, w_t);
    if (gear_state_.mode == DriveMode::Converter) T_floor = std::clamp(T_idle, T_min, T_max);
    F_min = k * (tc_.turbineTorque(w_i, w_t) - T_side) - F_drag_out;
    F_max = std::max(F_max, F_min);
  }
  const double F_road = road_.rolling(grade, c.rr_factor) + road_.aero(v_, c.rho) + road_.gradeForce(grade);
  const double F_ff = M_eff * in.target_accel_m_s2 + F_road;
  const double F_stop = -M_eff * p_.driver.stop_decel_m_s2 + F_road;

  double accel = 0.0;
  // Distance reference: trapezoidal integral of the targets (exact for a target linear in t).
  s_target_ += 0.5 * (v_target_prev_ + in.target_speed_m_s) * dt;
  v_target_prev_ = in.target_speed_m_s;
  if (in.driver_enabled) {
    const DriverCommand cmd = driver_.update(dt, v_, in.target_speed_m_s, F_ff, F_min, F_max,
                                             F_stop, s_target_ - s_);
    accel = cmd.accel_pedal;
    brake_force_ = cmd.brake_force_N;
    hold_ = cmd.hold;
    start_request_ = !driver_.stopRequested(in.target_speed_m_s);
    out_.brake_pedal = cmd.brake_pedal;
  } else {
    driver_.reset();
    s_target_ = s_;  // open loop: the reference restarts from the bus position
    accel = std::clamp(in.accel_pedal_cmd, 0.0, 1.0);
    brake_force_ = std::clamp(in.brake_pedal_cmd, 0.0, 1.0) * F_brake_max_;
    out_.brake_pedal = std::clamp(in.brake_pedal_cmd, 0.0, 1.0);
  }
  accel_pedal_ = accel;
  const double T_driver = T_floor + accel * (T_max - T_floor);

  // Idle governor: PID on (ω_idle - ω_e), D on the crank acceleration of the last step, with the
  // present load as feed-forward; acts as a floor under the driver's demand. Its integral only
  // corrects the engine's torque error: it integrates while the governor is the active demand
  // AND the crank speed is free (neutral, 1C); locked or shifting, the wheels impose the speed
  // and the integral is held. Gains for both engines' response (config/vehicle.yaml).
  const double e = d.idle_speed_rad_s - w_;
  const double T_load = r.T_aux + r.T_drag + (gear_state_.mode == DriveMode::Converter ? r.T_pump : 0.0);
  const auto& dp = p_.driver;
  const double T_pd = T_load + dp.idle_kp_Nm_s * e - dp.idle_kd_Nm_s2 * crank_accel_;
  double T_gov = T_pd + dp.idle_ki_Nm * idle_integral_;
  if (!in.engine_on) T_gov = T_driver;  // stopped/cranking: no governor, integrator frozen
  const bool governs = gear_state_.mode == DriveMode::Neutral || gear_state_.mode == DriveMode::Converter;
  if (T_gov > T_driver && governs && dp.idle_ki_Nm > 0.0) {
    idle_integral_ = std::clamp(idle_integral_ + e * dt, -200.0 / dp.idle_ki_Nm, 400.0 / dp.idle_ki_Nm);
    T_gov = T_pd + dp.idle_ki_Nm * idle_integral_;
  }
  double demand = std::clamp(std::max(T_driver, T_gov), T_min, std::max(T_max_total, T_min));
  // TCU torque intervention in the inertia phase of an upshift: the engine gives up the torque
  // that the clutch would otherwise add by slowing the engine (smooth output torque).
  if (gear_state_.mode == DriveMode::Shifting && shift_slip0_ > 0.0 && p_.shift.shift_torque_intervention)
    demand = std::max(T_min, demand - (engine_inertia_kg_m2_ + gearbox_input_inertia_kg_m2_) * shift_slip0_ / p_.shift.shift_duration_s);
  out_.crank_torque_demand_Nm = demand;
  out_.engine_torque_request_Nm = demand - in.em_torque_Nm;
  out_.accel_pedal = accel;
  out_.brake_force_N = brake_force_;
  out_.stop_hold = hold_;
  out_.start_request = start_request_;
  out_.crank_to_wheel_ratio = gear_state_.mode == DriveMode::Locked
      ? p_.driveline.gear_ratios[gear_state_.gear - 1] * p_.driveline.axle_ratio : 0.0;
}

}  // namespace hbt::vehicle
