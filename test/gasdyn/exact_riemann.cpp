#include "exact_riemann.hpp"

#include <cmath>
#include <stdexcept>

namespace hbt::gasdyn::test {

ExactRiemann::ExactRiemann(double gamma, Prim left, Prim right) : g_(gamma), L_(left), R_(right) {
  cL_ = std::sqrt(g_ * L_.p / L_.rho);
  cR_ = std::sqrt(g_ * R_.p / R_.rho);
  if (2.0 / (g_ - 1.0) * (cL_ + cR_) <= R_.u - L_.u) throw std::runtime_error("vacuum generated");
  // two-rarefaction initial guess
  const double z = (g_ - 1.0) / (2.0 * g_);
  double p = std::pow((cL_ + cR_ - 0.5 * (g_ - 1.0) * (R_.u - L_.u)) /
                          (cL_ / std::pow(L_.p, z) + cR_ / std::pow(R_.p, z)), 1.0 / z);
  for (int it = 0; it < 100; ++it) {
    double dl, dr;
    const double fl = f(p, L_, cL_, dl), fr = f(p, R_, cR_, dr);
    double pn = p - (fl + fr + R_.u - L_.u) / (dl + dr);
    if (pn < 1e-12 * p) pn = 1e-12 * p;
    const double change = 2.0 * std::abs(pn - p) / (pn + p);
    p = pn;
    if (change < 1e-15) break;
  }
  double dl, dr;
  ps_ = p;
  us_ = 0.5 * (L_.u + R_.u) + 0.5 * (f(p, R_, cR_, dr) - f(p, L_, cL_, dl));
}

double ExactRiemann::f(double p, const Prim& k, double c, double& df) const {
  if (p > k.p) {  // shock
    const double A = 2.0 / ((g_ + 1.0) * k.rho), B = (g_ - 1.0) / (g_ + 1.0) * k.p;
    const double q = std::sqrt(A / (p + B));
    df = q * (1.0 - 0.5 * (p - k.p) / (B + p));
    return (p - k.p) * q;
  }
  const double pr = p / k.p;  // rarefaction
  df = 1.0 / (k.rho * c) * std::pow(pr, -(g_ + 1.0) / (2.0 * g_));
  return 2.0 * c / (g_ - 1.0) * (std::pow(pr, (g_ - 1.0) / (2.0 * g_)) - 1.0);
}

Prim ExactRiemann::sample(double s) const {
  const double g = g_, gm = (g - 1.0) / (g + 1.0);
  if (s <= us_) {  // left of the contact
    if (ps_ > L_.p) {
      const double sl = L_.u - cL_ * std::sqrt((g + 1.0) / (2.0 * g) * ps_ / L_.p + (g - 1.0) / (2.0 * g));
      if (s <= sl) return L_;
      return {L_.rho * (ps_ / L_.p + gm) / (gm * ps_ / L_.p + 1.0), us_, ps_};
    }
    const double csl = cL_ * std::pow(ps_ / L_.p, (g - 1.0) / (2.0 * g));
    if (s <= L_.u - cL_) return L_;
    if (s >= us_ - csl) return {L_.rho * std::pow(ps_ / L_.p, 1.0 / g), us_, ps_};
    const double c = 2.0 / (g + 1.0) * (cL_ + 0.5 * (g - 1.0) * (L_.u - s));
    const double u = 2.0 / (g + 1.0) * (cL_ + 0.5 * (g - 1.0) * L_.u + s);
    const double rho = L_.rho * std::pow(c / cL_, 2.0 / (g - 1.0));
    return {rho, u, L_.p * std::pow(c / cL_, 2.0 * g / (g - 1.0))};
  }
  if (ps_ > R_.p) {
    const double sr = R_.u + cR_ * std::sqrt((g + 1.0) / (2.0 * g) * ps_ / R_.p + (g - 1.0) / (2.0 * g));
    if (s >= sr) return R_;
    return {R_.rho * (ps_ / R_.p + gm) / (gm * ps_ / R_.p + 1.0), us_, ps_};
  }
  const double csr = cR_ * std::pow(ps_ / R_.p, (g - 1.0) / (2.0 * g));
  if (s >= R_.u + cR_) return R_;
  if (s <= us_ + csr) return {R_.rho * std::pow(ps_ / R_.p, 1.0 / g), us_, ps_};
  const double c = 2.0 / (g + 1.0) * (cR_ - 0.5 * (g - 1.0) * (R_.u - s));
  const double u = 2.0 / (g + 1.0) * (-cR_ + 0.5 * (g - 1.0) * R_.u + s);
  const double rho = R_.rho * std::pow(c / cR_, 2.0 / (g - 1.0));
  return {rho, u, R_.p * std::pow(c / cR_, 2.0 * g / (g - 1.0))};
}

}  // namespace hbt::gasdyn::test
