#include "gasdyn/tvd_solver.hpp"

#include <algorithm>
#include <cmath>

namespace hbt::gasdyn {

namespace {
// Upper bound of a finite density [kg/m^3] or pressure [Pa]: a cell above it has diverged.
constexpr double kHuge = 1e300;

inline double limiter(Limiter l, double th) {
  switch (l) {
    case Limiter::Minmod: return std::max(0.0, std::min(1.0, th));
    case Limiter::Superbee: return std::max({0.0, std::min(2.0 * th, 1.0), std::min(th, 2.0)});
    case Limiter::VanLeer:
    default: return (th + std::abs(th)) / (1.0 + std::abs(th));
  }
}
inline double sgn(double x) { return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0); }
inline double fixedAbs(double l, double delta) {
  const double a = std::abs(l);
  return a >= delta ? a : 0.5 * (l * l + delta * delta) / delta;
}
}  // namespace

TvdSolver::TvdSolver(const PerfectGas& gas, const PipeConfig& cfg, const PipeGeometry& geo)
    : gas_(gas), cfg_(cfg), geo_(geo), n_(geo.n) {
  for (auto* v : {&q1_, &q2_, &q3_, &rho_, &u_, &p_, &H_, &c_, &srho_, &fr_}) v->assign(n_, 0.0);
  for (auto* v : {&am1_, &am2_, &am3_, &ap1_, &ap2_, &ap3_, &z1_, &z2_, &z3_, &ut_, &ct_, &Ht_,
                  &ft1_, &ft2_, &ft3_})
    v->assign(n_ + 1, 0.0);
  inv_V_.resize(n_);
  fric_k_.resize(n_);
  for (int i = 0; i < n_; ++i) {
    inv_V_[i] = 1.0 / geo_.V_cell[i];
    fric_k_[i] = cfg_.friction_darcy / (2.0 * geo_.D_cell[i]) * geo_.A_cell[i];
  }
  for (int i = 0; i < n_; ++i) setState(i, 1.2, 0.0, 1e5);
}

void TvdSolver::setState(int i, double rho, double u, double p) {
  q1_[i] = rho;
  q2_[i] = rho * u;
  q3_[i] = p / (gas_.gamma - 1.0) + 0.5 * rho * u * u;
  primitives(i);
  max_speed_ = 0.0;
  for (int k = 0; k < n_; ++k) max_speed_ = std::max(max_speed_, std::abs(u_[k]) + c_[k]);
}

void TvdSolver::primitives(int i) {
  const double r = q1_[i], u = q2_[i] / r;
  const double p = (gas_.gamma - 1.0) * (q3_[i] - 0.5 * q2_[i] * u);
  rho_[i] = r;
  u_[i] = u;
  p_[i] = p;
  H_[i] = (q3_[i] + p) / r;
  c_[i] = std::sqrt(std::abs(gas_.gamma * p / r));
  srho_[i] = std::sqrt(std::abs(r));
  fr_[i] = -cfg_.friction_darcy / (2.0 * geo_.D_cell[i]) * q2_[i] * std::abs(u) * geo_.A_cell[i];
}

EndState TvdSolver::endState(End e) const {
  if (e == End::Left) return {rho_[0], u_[0], p_[0], geo_.A_face[0]};
  return {rho_[n_ - 1], -u_[n_ - 1], p_[n_ - 1], geo_.A_face[n_]};
}

void TvdSolver::faceWaves() {
  const int n = n_;
  const double gm1 = gas_.gamma - 1.0, dx = geo_.dx, eps = cfg_.entropy_fix;
  const double* Ac = geo_.A_cell.data();
  const double *q1 = q1_.data(), *q2 = q2_.data(), *q3 = q3_.data();
  const double *u = u_.data(), *p = p_.data(), *H = H_.data(), *sr = srho_.data(), *fr = fr_.data();
  for (int j = 1; j < n; ++j) {
    const int i = j - 1;
    const double w = 1.0 / (sr[i] + sr[j]);
    const double ut = (sr[i] * u[i] + sr[j] * u[j]) * w;
    const double Ht = (sr[i] * H[i] + sr[j] * H[j]) * w;
    const double c2 = std::max(gm1 * (Ht - 0.5 * ut * ut), 1e-12);
    const double ct = std::sqrt(c2), rc = 1.0 / ct, ic2 = gm1 * rc * rc, i2c = 0.5 * rc;
    const double hu = Ht - ut * ut;
    // wave strengths of the jump in q
    const double d1 = q1[j] - q1[i], d2 = q2[j] - q2[i], d3 = q3[j] - q3[i];
    const double a2 = ic2 * (d1 * hu + ut * d2 - d3);
    const double a1 = (d1 * (ut + ct) - d2 - ct * a2) * i2c;
    const double a3 = d1 - a1 - a2;
    // area / friction part of the fluctuation and its characteristic projection
    const double Aa = 0.5 * (Ac[i] + Ac[j]), dA = Ac[j] - Ac[i];
    const double frm = 0.5 * (fr[i] + fr[j]) * dx;
    const double g1 = 0.5 * (q2[i] + q2[j]) * dA;
    const double g2 = 0.5 * (q2[i] * u[i] + q2[j] * u[j]) * dA - frm;
    const double g3 = 0.5 * (q2[i] * H[i] + q2[j] * H[j]) * dA;
    const double b2 = ic2 * (g1 * hu + ut * g2 - g3);
    const double b1 = (g1 * (ut + ct) - g2 - ct * b2) * i2c;
    const double b3 = g1 - b1 - b2;
    const double l1 = ut - ct, l2 = ut, l3 = ut + ct;
    const double delta = eps * ct;
    const double s1 = 0.5 * Aa * (l1 - fixedAbs(l1, delta)) * a1 + 0.5 * (1.0 - sgn(l1)) * b1;
    const double s2 = 0.5 * Aa * (l2 - std::abs(l2)) * a2 + 0.5 * (1.0 - sgn(l2)) * b2;
    const double s3 = 0.5 * Aa * (l3 - fixedAbs(l3, delta)) * a3 + 0.5 * (1.0 - sgn(l3)) * b3;
    const double m1 = s1 + s2 + s3;
    const double m2 = s1 * l1 + s2 * l2 + s3 * l3;
    const double m3 = s1 * (Ht - ut * ct) + s2 * 0.5 * ut * ut + s3 * (Ht + ut * ct);
    // exact fluctuation (conservative complement)
    const double Fi1 = Ac[i] * q2[i], Fj1 = Ac[j] * q2[j];
    const double Fi2 = Ac[i] * (q2[i] * u[i] + p[i]), Fj2 = Ac[j] * (q2[j] * u[j] + p[j]);
    const double Fi3 = Ac[i] * q2[i] * H[i], Fj3 = Ac[j] * q2[j] * H[j];
    am1_[j] = m1;
    am2_[j] = m2;
    am3_[j] = m3;
    ap1_[j] = (Fj1 - Fi1) - m1;
    ap2_[j] = (Fj2 - Fi2 - 0.5 * (p[i] + p[j]) * dA - frm) - m2;
    ap3_[j] = (Fj3 - Fi3) - m3;
    z1_[j] = Aa * l1 * a1 + b1;
    z2_[j] = Aa * l2 * a2 + b2;
    z3_[j] = Aa * l3 * a3 + b3;
    ut_[j] = ut;
    ct_[j] = ct;
    Ht_[j] = Ht;
  }
  // boundary faces: wave strengths copied from the neighbour face for the limiter ratio
  z1_[0] = z1_[1], z2_[0] = z2_[1], z3_[0] = z3_[1];
  z1_[n] = z1_[n - 1], z2_[n] = z2_[n - 1], z3_[n] = z3_[n - 1];
}

void TvdSolver::correctionFluxes(double dt) {
  const int n = n_;
  const double nu = dt / geo_.dx;
  const Limiter lim = cfg_.limiter;
  auto coef = [&](const double* z, int j, double l) {
    const double zj = z[j];
    if (zj == 0.0 || l == 0.0) return 0.0;
    const double th = z[l > 0.0 ? j - 1 : j + 1] / zj;
    return 0.5 * sgn(l) * (1.0 - nu * std::abs(l)) * limiter(lim, th) * zj;
  };
  for (int j = 1; j < n; ++j) {
    const double ut = ut_[j], ct = ct_[j], Ht = Ht_[j];
    const double l1 = ut - ct, l3 = ut + ct;
    const double s1 = coef(z1_.data(), j, l1);
    const double s2 = coef(z2_.data(), j, ut);
    const double s3 = coef(z3_.data(), j, l3);
    ft1_[j] = s1 + s2 + s3;
    ft2_[j] = s1 * l1 + s2 * ut + s3 * l3;
    ft3_[j] = s1 * (Ht - ut * ct) + s2 * 0.5 * ut * ut + s3 * (Ht + ut * ct);
  }
  ft1_[0] = ft2_[0] = ft3_[0] = 0.0;
  ft1_[n] = ft2_[n] = ft3_[n] = 0.0;
}

CellFault TvdSolver::step(double dt, const EndFlux& left, const EndFlux& right) {
  const int n = n_;
  const double* Ac = geo_.A_cell.data();
  const double* Af = geo_.A_face.data();
  const double dx = geo_.dx;
  faceWaves();
  correctionFluxes(dt);
  // boundary fluctuations (x-direction fluxes F_b; half-cell area and friction sources)
  {
    const int i = 0;
    const double Sm = p_[i] * (Ac[i] - Af[0]) + 0.5 * fr_[i] * dx;
    ap1_[0] = Ac[i] * q2_[i] - left.mdot_in;
    ap2_[0] = Ac[i] * (q2_[i] * u_[i] + p_[i]) - left.momentum - Sm;
    ap3_[0] = Ac[i] * q2_[i] * H_[i] - left.energy_in;
  }
  {
    const int i = n - 1;
    const double Sm = p_[i] * (Af[n] - Ac[i]) + 0.5 * fr_[i] * dx;
    am1_[n] = -right.mdot_in - Ac[i] * q2_[i];
    am2_[n] = right.momentum - Ac[i] * (q2_[i] * u_[i] + p_[i]) - Sm;
    am3_[n] = -right.energy_in - Ac[i] * q2_[i] * H_[i];
  }
  const double* iV = inv_V_.data();
  const double* fk = fric_k_.data();
  const bool heat = cfg_.heat != WallHeat::None;
  const double gm1 = gas_.gamma - 1.0, cv = gas_.cv(), Rg = gas_.R, Tw = cfg_.T_wall;
  double vmax = 0.0;
  bool ok = true;
  for (int i = 0; i < n; ++i) {
    const double inv = dt * iV[i];
    const double r = q1_[i] - inv * (ap1_[i] + am1_[i + 1] + ft1_[i + 1] - ft1_[i]);
    const double mu = q2_[i] - inv * (ap2_[i] + am2_[i + 1] + ft2_[i + 1] - ft2_[i]);
    double Et = q3_[i] - inv * (ap3_[i] + am3_[i + 1] + ft3_[i + 1] - ft3_[i]);
    const double ir = 1.0 / r, u = mu * ir;
    if (heat) {
      const double T = p_[i] / (rho_[i] * Rg);
      const double h = cfg_.heat == WallHeat::GivenCoefficient
                           ? cfg_.h_wall
                           : 0.125 * cfg_.friction_darcy * rho_[i] * std::abs(u_[i]) * gas_.cp();
      const double kk = dt * h * 4.0 / geo_.D_cell[i] / (r * cv);
      Et += r * cv * (Tw - T) * kk / (1.0 + kk);
    }
    const double p = gm1 * (Et - 0.5 * mu * u);
    q1_[i] = r;
    q2_[i] = mu;
    q3_[i] = Et;
    rho_[i] = r;
    u_[i] = u;
    p_[i] = p;
    H_[i] = (Et + p) * ir;
    const double c = std::sqrt(std::abs(gas_.gamma * p * ir));
    c_[i] = c;
    srho_[i] = std::sqrt(std::abs(r));
    fr_[i] = -fk[i] * mu * std::abs(u);
    vmax = std::max(vmax, std::abs(u) + c);
    ok &= (r > 0.0) & (p > 0.0) & (r < kHuge) & (p < kHuge);
  }
  max_speed_ = vmax;
  return ok && std::isfinite(vmax) ? CellFault{} : findFault();
}

CellFault TvdSolver::findFault() const {
  for (int i = 0; i < n_; ++i) {
    if (!(rho_[i] > 0.0 && rho_[i] < kHuge)) return {i, "density", rho_[i]};
    if (!(p_[i] > 0.0 && p_[i] < kHuge)) return {i, "pressure", p_[i]};
    if (!std::isfinite(u_[i])) return {i, "velocity", u_[i]};
  }
  return {0, "wave speed", max_speed_};
}

double TvdSolver::mass() const {
  double s = 0.0;
  for (int i = 0; i < n_; ++i) s += q1_[i] * geo_.V_cell[i];
  return s;
}

double TvdSolver::energy() const {
  double s = 0.0;
  for (int i = 0; i < n_; ++i) s += q3_[i] * geo_.V_cell[i];
  return s;
}

}  // namespace hbt::gasdyn
