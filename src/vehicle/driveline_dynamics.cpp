// VehicleModel: right-hand sides, Heun substeps with Coulomb stop/hold, clutch impulses and
// energy booking (equations in vehicle_model.hpp).
#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "vehicle/vehicle_model.hpp"

namespace hbt::vehicle {

double VehicleModel::gearboxInputSpeed(double v, double w) const {
  switch (gear_state_.mode) {
    case DriveMode::Locked: return w;
    case DriveMode::Shifting: return w;  // input shaft still turns with the engine
    case DriveMode::Converter: return v * k_[1];
    default: return w;  // neutral: the free turbine turns with the pump
  }
}

VehicleModel::Rates VehicleModel::rates(double v, double w, const StepConst& c, int dir) const {
  Rates r;
  const double w_out = v * axle_ratio_per_radius_1_m_;
  const int g = gear_state_.gear;
  // Gear load loss at the input speed referred to the engaged (or on-coming) gear.
  const double w_in = gear_state_.mode == DriveMode::Shifting ? v * k_[g] : gearboxInputSpeed(v, w);
  // stopped: a braking engine torque acts as friction (never turns the crank backwards); a
  // driving one (the gas of an expanding cylinder of the crank-resolved 1D engine) as it is
  r.T_eng = c.engine_on || c.T_e > 0.0 ? c.T_e : -std::fabs(c.T_e) * smoothSign(w);
  r.T_em = c.T_em;
  // below idle the belt-driven set's torque falls linearly to zero at rest (its power with the
  // speed squared): no consumer draws more torque during a crank or a run-up than at idle
  const double wa = std::max(std::fabs(w), p_.driveline.idle_speed_rad_s);
  r.T_aux = c.P_aux * w / (wa * wa);
  // Gearbox drag: with a gear engaged, the drag part of the loss map at the gearbox input speed
  // (VECTO: the map applies at the gearbox input; in 1C that is the turbine, so the drag acts on
  // the turbine side; locked and shifting: the input shaft turns with the crank). In neutral
  // the forward clutch is open and the geartrain stands: only the pump-side spin loss
  // (oil pump + open-clutch drag + free turbine) acts at the pump speed. Both are spin losses:
  // × the cold-oil factor φ(T_oil) of the gearbox oil (exactly 1 at its reference temperature).
  if (gear_state_.mode == DriveMode::Neutral) {
    r.T_drag = c.drag_factor * p_.driveline.neutral_drag_torque_Nm * smoothSign(w);
  } else if (gear_state_.mode == DriveMode::Converter) {
    r.T_drag_in = c.drag_factor * gear_loss_map_.drag(w_in) * smoothSign(w_in);
  } else {
    r.T_drag = c.drag_factor * gear_loss_map_.drag(w) * smoothSign(w);
  }
  if (gear_state_.mode != DriveMode::Neutral) {
    r.T_gload = p_.gearbox.gear_load_loss_factor[g - 1] * gear_loss_map_.load(w_in, T_in_est_) * smoothSign(w_in);
    r.T_axl = (1.0 - p_.driveline.axle_efficiency) * std::fabs(T_ax_est_) * smoothSign(w_out);
  }
  r.T_ret = ret_.torque(w_out) * smoothSign(w_out);
  const double sv = v > 0.0 ? 1.0 : (v < 0.0 ? -1.0 : static_cast<double>(dir));
  r.F_roll = road_.rolling(c.grade, c.rr_factor) * sv;
  r.F_brake = c.F_brake * sv;
  r.F_aero = road_.aero(v, c.rho);
  r.F_grade = road_.gradeForce(c.grade);
  const double F_res = r.F_roll + r.F_aero + r.F_grade + r.F_brake + axle_ratio_per_radius_1_m_ * (r.T_ret + r.T_axl);
  const double T_crank = r.T_eng + r.T_em - r.T_aux - r.T_drag;
  switch (gear_state_.mode) {
    case DriveMode::Locked: {
      const double k = k_[g];
      r.dv = (k * (T_crank - r.T_gload) - F_res) / (inertia_mass_kg_ + (engine_inertia_kg_m2_ + gearbox_input_inertia_kg_m2_) * k * k);
      r.dw = k * r.dv;
      break;
    }
    case DriveMode::Shifting: {
      const double k = k_[g], J = engine_inertia_kg_m2_ + gearbox_input_inertia_kg_m2_;
      const double slip = w - k * v;
      double Tc = T_crank + J * shift_slip0_ / p_.shift.shift_duration_s;
      if (Tc * slip < 0.0 || slip * shift_slip0_ <= 0.0) Tc = 0.0;  // clutch cannot create energy
      r.T_clutch = Tc;
      r.dw = (T_crank - Tc) / J;
      r.dv = (k * (Tc - r.T_gload) - F_res) / inertia_mass_kg_;
      break;
    }
    case DriveMode::Converter: {
      r.T_pump = tc_.pumpTorque(w, w_in);
      r.T_turb = tc_.turbineTorque(w, w_in);
      if (locking_) {  // lock-up clutch slipping in parallel with the converter
        const double slip = w - w_in;
        double Tc = T_crank - r.T_pump + engine_inertia_kg_m2_ * shift_slip0_ / p_.shift.lockup_duration_s;
        if (Tc * slip < 0.0 || slip * shift_slip0_ <= 0.0) Tc = 0.0;
        r.T_clutch = Tc;
      }
      r.dw = (T_crank - r.T_pump - r.T_clutch) / engine_inertia_kg_m2_;
      r.dv = (k_[1] * (r.T_turb + r.T_clutch - r.T_gload - r.T_drag_in) - F_res) / (inertia_mass_kg_ + gearbox_input_inertia_kg_m2_ * k_[1] * k_[1]);
      break;
    }
    default:
      r.dw = T_crank / (engine_inertia_kg_m2_ + gearbox_input_inertia_kg_m2_);
      r.dv = -F_res / inertia_mass_kg_;
  }
  return r;
}

// At v = 0: is the bus held by rolling resistance + brake? Else *dir = direction of motion.
bool VehicleModel::held(const StepConst& c, int* dir) const {
  const Rates r0 = rates(0.0, w_, c, 0);  // Coulomb terms off
  double M = inertia_mass_kg_;
  if (gear_state_.mode == DriveMode::Locked) M += (engine_inertia_kg_m2_ + gearbox_input_inertia_kg_m2_) * k_[gear_state_.gear] * k_[gear_state_.gear];
  if (gear_state_.mode == DriveMode::Converter) M += gearbox_input_inertia_kg_m2_ * k_[1] * k_[1];
  const double F_other = r0.dv * M;
  const double R = road_.rolling(c.grade, c.rr_factor) + c.F_brake;
  if (std::fabs(F_other) <= R) return true;
  *dir = F_other > 0.0 ? 1 : -1;
  return false;
}

void VehicleModel::book(const Rates& r, double v0, double v2, double w0, double w2, double h) {
  VehicleEnergy& e = out_.energy;
  const double vm = 0.5 * (v0 + v2), wm = 0.5 * (w0 + w2);
  const double w_out = vm * axle_ratio_per_radius_1_m_;
  const double w_in = gear_state_.mode == DriveMode::Locked ? wm
                      : gear_state_.mode == DriveMode::Converter ? vm * k_[1]
                      : gear_state_.mode == DriveMode::Shifting ? vm * k_[gear_state_.gear] : 0.0;
  e.engine_J += r.T_eng * wm * h;
  e.em_J += r.T_em * wm * h;
  e.aux_J += r.T_aux * wm * h;
  e.gearbox_drag_J += (r.T_drag * wm + r.T_drag_in * w_in) * h;
  e.tc_loss_J += (r.T_pump * wm - r.T_turb * w_in) * h;
  e.gear_load_loss_J += r.T_gload * w_in * h;
  e.retarder_J += r.T_ret * w_out * h;
  e.axle_loss_J += r.T_axl * w_out * h;
  // Slipping clutch heat: gear change -> shift loss, lock-up clutch -> TC loss.
  const double clutch = gear_state_.gear > 0 ? r.T_clutch * (wm - vm * k_[gear_state_.gear]) * h : 0.0;
  (gear_state_.mode == DriveMode::Converter ? e.tc_loss_J : e.shift_loss_J) += clutch;
  e.rolling_J += r.F_roll * vm * h;
  e.aero_J += r.F_aero * vm * h;
  e.grade_J += r.F_grade * vm * h;
  e.brake_J += r.F_brake * vm * h;
  e.wheel_J += (inertia_mass_kg_ * (v2 - v0) / h + r.F_roll + r.F_aero + r.F_grade + r.F_brake) * vm * h;
  s_ += vm * h;
}

void VehicleModel::substep(double h, const StepConst& c, int depth) {
  if (h <= 0.0) return;
  const double v0 = v_, w0 = w_;
  int dir = v0 > 0.0 ? 1 : (v0 < 0.0 ? -1 : 0);
  const double sin_a = std::sin(std::atan(c.grade));
  auto avg = [](const Rates& a, const Rates& b) {
    Rates m;
    m.T_eng = 0.5 * (a.T_eng + b.T_eng); m.T_em = 0.5 * (a.T_em + b.T_em);
    m.T_aux = 0.5 * (a.T_aux + b.T_aux); m.T_drag = 0.5 * (a.T_drag + b.T_drag);
    m.T_drag_in = 0.5 * (a.T_drag_in + b.T_drag_in);
    m.T_pump = 0.5 * (a.T_pump + b.T_pump); m.T_turb = 0.5 * (a.T_turb + b.T_turb);
    m.T_gload = 0.5 * (a.T_gload + b.T_gload); m.T_ret = 0.5 * (a.T_ret + b.T_ret);
    m.T_axl = 0.5 * (a.T_axl + b.T_axl); m.F_roll = 0.5 * (a.F_roll + b.F_roll);
    m.F_aero = 0.5 * (a.F_aero + b.F_aero); m.F_grade = 0.5 * (a.F_grade + b.F_grade);
    m.F_brake = 0.5 * (a.F_brake + b.F_brake); m.T_clutch = 0.5 * (a.T_clutch + b.T_clutch);
    m.dw = 0.5 * (a.dw + b.dw); m.dv = 0.5 * (a.dv + b.dv);
    return m;
  };
  Rates used;
  if (v0 == 0.0 && held(c, &dir)) {
    // Vehicle held: only the crank (and free turbine) move; locked mode cannot turn.
    Rates r1 = rates(0.0, w0, c, 0);
    r1.dv = 0.0;
    r1.F_roll = r1.F_brake = 0.0;
    if (gear_state_.mode == DriveMode::Locked) r1.dw = 0.0;
    const double w1 = w0 + h * r1.dw;
    Rates r2 = rates(0.0, w1, c, 0);
    r2.dv = 0.0;
    r2.F_roll = r2.F_brake = 0.0;
    if (gear_state_.mode == DriveMode::Locked) r2.dw = 0.0;
    used = avg(r1, r2);
    w_ = w0 + h * used.dw;
    book(used, 0.0, 0.0, w0, w_, h);
  } else {
    const Rates r1 = rates(v0, w0, c, dir);
    const double v1 = v0 + h * r1.dv, w1 = w0 + h * r1.dw;
    if (v1 * dir < 0.0) {
      // Coulomb forces stop the bus within this substep: Euler exactly to v = 0, then hold.
      const double ts = -v0 / r1.dv;
      v_ = 0.0;
      w_ = w0 + ts * r1.dw;
      if (gear_state_.mode == DriveMode::Locked) w_ = 0.0;
      book(r1, v0, 0.0, w0, w_, ts);
      h_ += 0.5 * v0 * ts * sin_a;
      last_dv_ = r1.dv;
      if (depth < 3) substep(h - ts, c, depth + 1);
      return;
    }
    const Rates r2 = rates(v1, w1, c, v1 > 0.0 ? 1 : (v1 < 0.0 ? -1 : dir));
    used = avg(r1, r2);
    double v2 = v0 + h * used.dv, w2 = w0 + h * used.dw;
    if (v2 * dir < 0.0) {  // Heun overshoots the stop although Euler did not: take Euler
      used = r1;
      v2 = v1;
      w2 = w1;
    }
    v_ = v2;
    w_ = w2;
    book(used, v0, v2, w0, w2, h);
    h_ += 0.5 * (v0 + v2) * h * sin_a;
  }
  last_dv_ = used.dv;
  if (w_ < 0.0) {  // crank cannot turn backwards (engine stopped): clamp, book the difference
    const double ke0 = kineticEnergy();
    w_ = 0.0;
    if (gear_state_.mode == DriveMode::Locked) v_ = 0.0;
    out_.energy.correction_J += ke0 - kineticEnergy();
  }
  // Transmitted torques for the next loss evaluation.
  switch (gear_state_.mode) {
    case DriveMode::Locked:
      T_in_est_ = used.T_eng + used.T_em - used.T_aux - used.T_drag - (engine_inertia_kg_m2_ + gearbox_input_inertia_kg_m2_) * used.dw;
      T_ax_est_ = p_.driveline.gear_ratios[gear_state_.gear - 1] * (T_in_est_ - used.T_gload);
      break;
    case DriveMode::Shifting:
      T_in_est_ = used.T_clutch;
      T_ax_est_ = p_.driveline.gear_ratios[gear_state_.gear - 1] * (T_in_est_ - used.T_gload);
      break;
    case DriveMode::Converter:
      T_in_est_ = used.T_turb + used.T_clutch - gearbox_input_inertia_kg_m2_ * k_[1] * used.dv;
      T_ax_est_ = p_.driveline.gear_ratios[0] * (T_in_est_ - used.T_gload);
      break;
    default:
      T_in_est_ = T_ax_est_ = 0.0;
  }
  if (gear_state_.mode == DriveMode::Shifting || locking_) {
    shift_elapsed_ += h;
    const double ts = locking_ ? p_.shift.lockup_duration_s : p_.shift.shift_duration_s;
    const double slip = w_ - k_[gear_state_.gear] * v_;
    // Synchronised (slip crossed zero or is below two substeps of the sync rate) or timed out.
    const double band = 2.0 * h * std::fabs(shift_slip0_) / ts + 1e-3;
    if (slip * shift_slip0_ <= 0.0 || std::fabs(slip) < band || shift_elapsed_ > 3.0 * ts) {
      locking_ = false;
      transition({DriveMode::Locked, gear_state_.gear}, false);  // synchronised: the clutch locks
    }
  }
}

double VehicleModel::kineticEnergy() const {
  const double w_in = gearboxInputSpeed(v_, w_);
  return 0.5 * inertia_mass_kg_ * v_ * v_ + 0.5 * engine_inertia_kg_m2_ * w_ * w_ + 0.5 * gearbox_input_inertia_kg_m2_ * w_in * w_in;
}

void VehicleModel::transition(const GearState& to, bool allow_slip) {
  if (allow_slip && to.mode == DriveMode::Locked && to.gear == 1 &&
      gear_state_.mode == DriveMode::Converter && p_.shift.lockup_duration_s > 0.0) {
    if (locking_) return;  // lock-up already in progress
    const double slip0 = w_ - k_[1] * v_;
    if (std::fabs(slip0) > 1e-6) {
      locking_ = true;
      shift_slip0_ = slip0;
      shift_elapsed_ = 0.0;
      return;
    }
  }
  locking_ = false;
  if (allow_slip && to.mode == DriveMode::Locked && gear_state_.mode == DriveMode::Locked &&
      to.gear != gear_state_.gear && p_.shift.shift_duration_s > 0.0) {
    // Gear change with a slip phase: no impulse now, the clutch synchronises (rates()).
    const double slip0 = w_ - k_[to.gear] * v_;
    if (std::fabs(slip0) > 1e-6) {
      gear_state_ = {DriveMode::Shifting, to.gear};
      shift_slip0_ = slip0;
      shift_elapsed_ = 0.0;
      t_since_shift_ = 0.0;
      return;
    }
  }
  const double ke0 = kineticEnergy();
  const double w_in = gearboxInputSpeed(v_, w_);
  const bool heldAtRest = v_ == 0.0 && brake_force_ > 0.0;
  switch (to.mode) {
    case DriveMode::Neutral:
      w_ = (engine_inertia_kg_m2_ * w_ + gearbox_input_inertia_kg_m2_ * w_in) / (engine_inertia_kg_m2_ + gearbox_input_inertia_kg_m2_);
      break;
    case DriveMode::Converter: {
      // Engaging from neutral at standstill: the turbine is stopped by the forward clutch while
      // the bus stands (driver still on the brake): its momentum goes into the brake/tyres.
      const double k = k_[1];
      const bool standing = heldAtRest || (v_ == 0.0 && gear_state_.mode == DriveMode::Neutral);
      v_ = standing ? 0.0 : (inertia_mass_kg_ * v_ + gearbox_input_inertia_kg_m2_ * w_in * k) / (inertia_mass_kg_ + gearbox_input_inertia_kg_m2_ * k * k);
      break;
    }
    case DriveMode::Locked: {
      const double k = k_[to.gear];
      v_ = (inertia_mass_kg_ * v_ + (engine_inertia_kg_m2_ * w_ + gearbox_input_inertia_kg_m2_ * w_in) * k) / (inertia_mass_kg_ + (engine_inertia_kg_m2_ + gearbox_input_inertia_kg_m2_) * k * k);
      w_ = k * v_;
      break;
    }
    case DriveMode::Shifting:  // entered above without impulse
      break;
  }
  if (to.gear != gear_state_.gear && gear_state_.mode != DriveMode::Shifting) t_since_shift_ = 0.0;
  gear_state_ = to;
  T_in_est_ = T_ax_est_ = 0.0;
  out_.energy.shift_loss_J += ke0 - kineticEnergy();
}

}  // namespace hbt::vehicle
