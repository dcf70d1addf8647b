#include "gasdyn/fsm_solver.hpp"

#include <algorithm>
#include <cmath>

namespace hbt::gasdyn {

namespace {
// Upper bound of a finite density [kg/m^3] or pressure [Pa]: a cell above it has diverged.
constexpr double kHuge = 1e300;
}

FsmSolver::FsmSolver(const PerfectGas& gas, const PipeConfig& cfg, const PipeGeometry& geo)
    : gas_(gas), cfg_(cfg), geo_(geo), n_(geo.n) {
  for (auto* v : {&rho_, &E_, &p_, &u_, &c_, &h0_, &mom_, &pq_, &u_init_}) v->assign(n_, 0.0);
  m_.assign(n_ + 1, 0.0);
  uf_.assign(n_ + 1, 0.0);
  inv_V_.resize(n_);
  for (int i = 0; i < n_; ++i) inv_V_[i] = 1.0 / geo_.V_cell[i];
  inv_Af_.resize(n_ + 1);
  fric_.resize(n_ + 1);
  for (int j = 0; j <= n_; ++j) {
    inv_Af_[j] = 1.0 / geo_.A_face[j];
    fric_[j] = cfg_.friction_darcy / (2.0 * geo_.D_face[j]);
  }
  for (int i = 0; i < n_; ++i) setState(i, 1.2, 0.0, 1e5);
}

void FsmSolver::setState(int i, double rho, double u, double p) {
  rho_[i] = rho;
  u_init_[i] = u;
  E_[i] = p / (gas_.gamma - 1.0) + 0.5 * rho * u * u;
  // ports next to the cell: mean of the neighbouring cell momenta (ends: the cell's own)
  for (int j = i; j <= i + 1; ++j) {
    const int l = std::max(j - 1, 0), r = std::min(j, n_ - 1);
    m_[j] = 0.5 * (rho_[l] * u_init_[l] + rho_[r] * u_init_[r]) * geo_.A_face[j];
  }
  for (int j = std::max(i - 1, 0); j <= std::min(i + 2, n_); ++j) uf_[j] = faceVelocity(j);
  for (int k = std::max(i - 1, 0); k <= std::min(i + 1, n_ - 1); ++k) updatePrimitives(k);
  max_speed_ = 0.0;
  for (int k = 0; k < n_; ++k) max_speed_ = std::max(max_speed_, std::abs(u_[k]) + c_[k]);
}

void FsmSolver::updatePrimitives(int i) {
  const double r = rho_[i];
  const double u = 0.5 * (uf_[i] + uf_[i + 1]);
  const double p = (gas_.gamma - 1.0) * (E_[i] - 0.5 * r * u * u);
  u_[i] = u;
  p_[i] = p;
  h0_[i] = (E_[i] + p) / r;
  c_[i] = std::sqrt(std::max(gas_.gamma * p / r, 0.0));
}

double FsmSolver::faceVelocity(int j) const {
  const int l = j > 0 ? j - 1 : 0, r = j < n_ ? j : n_ - 1;
  return 2.0 * m_[j] / ((rho_[l] + rho_[r]) * geo_.A_face[j]);
}

EndState FsmSolver::endState(End e) const {
  if (e == End::Left) return {rho_[0], u_[0], p_[0], geo_.A_face[0]};
  return {rho_[n_ - 1], -u_[n_ - 1], p_[n_ - 1], geo_.A_face[n_]};
}

CellFault FsmSolver::step(double dt, const EndFlux& left, const EndFlux& right) {
  const int n = n_;
  const double* Af = geo_.A_face.data();
  const double* iV = inv_V_.data();
  const double* iAf = inv_Af_.data();
  double* rho = rho_.data();
  double* E = E_.data();
  double* p = p_.data();
  double* u = u_.data();
  double* c = c_.data();
  double* h0 = h0_.data();
  double* mom = mom_.data();
  double* pq = pq_.data();
  double* m = m_.data();
  double* uf = uf_.data();  // port velocities at level n (kept from the previous step)
  const double gm1 = gas_.gamma - 1.0, gam = gas_.gamma;
  const double c1 = cfg_.fsm_visc_linear, c2 = cfg_.fsm_visc_quadratic;

  // 1. centre momentum flux (donor cell) and pressure + bulk viscosity, at level n
  for (int i = 0; i < n; ++i) {
    const double uc = u[i];
    mom[i] = uc * (uc >= 0.0 ? m[i] : m[i + 1]);
    const double du = uf[i + 1] - uf[i];
    const double q = du < 0.0 ? rho[i] * (c2 * du * du - c1 * c[i] * du) : 0.0;
    pq[i] = p[i] + q;
  }
  // 2. interior ports: momentum to n+1/2, wall friction implicit (linearised in |u|)
  const double k = dt / geo_.dx;
  if (cfg_.friction_darcy > 0.0) {
    const double* fr = fric_.data();
    for (int j = 1; j < n; ++j) {
      const double ms = m[j] + k * ((mom[j - 1] - mom[j]) + Af[j] * (pq[j - 1] - pq[j]));
      m[j] = ms / (1.0 + dt * fr[j] * std::abs(uf[j]));
    }
  } else {
    for (int j = 1; j < n; ++j) m[j] += k * ((mom[j - 1] - mom[j]) + Af[j] * (pq[j - 1] - pq[j]));
  }
  // 3. end ports from the boundaries
  m[0] = left.mdot_in;
  m[n] = -right.mdot_in;
  // 4. cells: mass and energy to n+1 (donor-cell h0)
  const bool heat = cfg_.heat != WallHeat::None;
  bool ok = true;
  double Hl = left.energy_in;
  for (int i = 0; i < n; ++i) {
    const double mr = m[i + 1];
    const double Hr = (i == n - 1) ? -right.energy_in : mr * (mr >= 0.0 ? h0[i] : h0[i + 1]);
    const double inv = dt * iV[i];
    const double r = rho[i] + inv * (m[i] - mr);
    double Ei = E[i] + inv * (Hl - Hr);
    Hl = Hr;
    if (heat) Ei += wallHeat(i, dt, r);
    rho[i] = r;
    E[i] = Ei;
    ok &= (r > 0.0) & (r < kHuge);
  }
  // 5. port velocities at n+1 (mean density), then the cell primitives
  uf[0] = m[0] * iAf[0] / rho[0];
  for (int j = 1; j < n; ++j) uf[j] = 2.0 * m[j] * iAf[j] / (rho[j - 1] + rho[j]);
  uf[n] = m[n] * iAf[n] / rho[n - 1];
  double vmax = 0.0;
  // the bulk viscosity acts through the interior ports only: a 1-cell pipe has none, so its
  // signal speed is |u| + c (no diffusion limit)
  const double vis_on = n > 1 ? 1.0 : 0.0;
  for (int i = 0; i < n; ++i) {
    const double r = rho[i], ir = 1.0 / r, ui = 0.5 * (uf[i] + uf[i + 1]);
    const double pi = gm1 * (E[i] - 0.5 * r * ui * ui);
    u[i] = ui;
    p[i] = pi;
    h0[i] = (E[i] + pi) * ir;
    const double ci = std::sqrt(std::abs(gam * pi * ir));
    c[i] = ci;
    // signal speed incl. the bulk-viscosity diffusion limit dt <= dx/(2 nu/dx)
    const double du = uf[i + 1] - uf[i];
    const double visc = du < 0.0 ? vis_on * 2.0 * (c1 * ci - c2 * du) : 0.0;
    vmax = std::max(vmax, std::abs(ui) + ci + visc);
    ok &= (pi > 0.0) & (pi < kHuge);
  }
  max_speed_ = vmax;
  return ok && std::isfinite(vmax) ? CellFault{} : findFault();
}

double FsmSolver::wallHeat(int i, double dt, double r_new) const {
  // implicit relaxation of T towards T_wall: dE = rho cv (Tw - T) k/(1+k), k = dt h 4/(D rho cv)
  const double cv = gas_.cv();
  const double T = p_[i] / (rho_[i] * gas_.R);
  const double h = cfg_.heat == WallHeat::GivenCoefficient
                       ? cfg_.h_wall
                       : 0.125 * cfg_.friction_darcy * rho_[i] * std::abs(u_[i]) * gas_.cp();
  const double kk = dt * h * 4.0 / geo_.D_cell[i] / (r_new * cv);
  return r_new * cv * (cfg_.T_wall - T) * kk / (1.0 + kk);
}

CellFault FsmSolver::findFault() const {
  for (int i = 0; i < n_; ++i) {
    if (!(rho_[i] > 0.0 && rho_[i] < kHuge)) return {i, "density", rho_[i]};
    if (!(p_[i] > 0.0 && p_[i] < kHuge)) return {i, "pressure", p_[i]};
    if (!std::isfinite(u_[i])) return {i, "velocity", u_[i]};
  }
  return {0, "wave speed", max_speed_};
}

double FsmSolver::mass() const {
  double s = 0.0;
  for (int i = 0; i < n_; ++i) s += rho_[i] * geo_.V_cell[i];
  return s;
}

double FsmSolver::energy() const {
  double s = 0.0;
  for (int i = 0; i < n_; ++i) s += E_[i] * geo_.V_cell[i];
  return s;
}

}  // namespace hbt::gasdyn
