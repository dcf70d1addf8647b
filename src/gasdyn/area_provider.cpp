#include "gasdyn/area_provider.hpp"

#include <cmath>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::gasdyn {

ConstantArea::ConstantArea(double a, double cdf, double cdr) : area_(a), cd_f_(cdf), cd_r_(cdr) {
  if (!(a >= 0.0)) throw InputError("orifice", "geometric_area", "must be >= 0 m^2");
  if (!(cdf >= 0.0 && cdf <= 1.0)) throw InputError("orifice", "cd_forward", "must be in [0, 1]");
  if (!(cdr >= 0.0 && cdr <= 1.0)) throw InputError("orifice", "cd_reverse", "must be in [0, 1]");
}

double ConstantArea::effectiveArea(FlowDirection dir, double) const {
  return area_ * (dir == FlowDirection::Forward ? cd_f_ : cd_r_);
}

LiftProfileArea::LiftProfileArea(Table1D lift, Table1D cdf, Table1D cdr, double d, int n)
    : lift_(std::move(lift)), cd_f_(std::move(cdf)), cd_r_(std::move(cdr)), d_(d), n_(n) {
  if (lift_.empty()) throw InputError("valve", "lift", "empty lift profile");
  if (cd_f_.empty() || cd_r_.empty()) throw InputError("valve", "cd", "empty Cd table");
  if (!(d > 0.0)) throw InputError("valve", "diameter", "must be > 0 m");
  if (n < 1) throw InputError("valve", "n_valves", "must be >= 1");
}

void LiftProfileArea::setCrank(double theta0_deg, double t0_s, double rpm) {
  theta0_ = theta0_deg, t0_ = t0_s, rpm_ = rpm;
}

double LiftProfileArea::crankAngle(double t) const {
  const double th = theta0_ + 6.0 * rpm_ * (t - t0_);
  const double w = std::fmod(th, 720.0);
  return w < 0.0 ? w + 720.0 : w;
}

double LiftProfileArea::lift(double t) const {
  const double l = lift_(crankAngle(t));
  return l > 0.0 ? l : 0.0;
}

double LiftProfileArea::effectiveArea(FlowDirection dir, double t) const {
  const double l = lift(t);
  if (l <= 0.0) return 0.0;
  const double cd = (dir == FlowDirection::Forward ? cd_f_ : cd_r_)(l / d_);
  return n_ * units::kPi * d_ * l * (cd > 0.0 ? cd : 0.0);
}

}  // namespace hbt::gasdyn
