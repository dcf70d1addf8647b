// TVD: second-order, Roe-linearised, flux-limited scheme of the Corberan-Gascon family, written in
// the wave-propagation (fluctuation) form with characteristic upwinding of the source terms.
//
// Quasi-1D Euler equations, per unit length (A = A(x) [m^2]):
//   d/dt [rho A, rho u A, rho E A] + d/dx [rho u A, (rho u^2 + p) A, rho u H A]
//        = [0, p dA/dx - f_D/(2D) rho u|u| A, q_w]
// with E = cv T + u^2/2, H = E + p/rho [J/kg]. Cell unknowns are q = (rho, rho u, rho E) per volume.
// At each interior face between cells i, i+1 (Roe averages u~, H~, c~; eigenvalues u~-c~, u~, u~+c~,
// right eigenvectors r_k):
//   Phi = F_{i+1} - F_i - S~ dx  (flux difference minus the source over the interval, S~ with the
//         arithmetic mean pressure so that a gas at rest in a variable-area pipe stays at rest);
//   Phi = A~ sum_k lambda_k alpha_k r_k + G,  alpha = R^-1 (q_{i+1} - q_i) (Roe property), and
//   G = mean(f) dA - S~ dx (area and friction parts), beta = R^-1 G;
//   A^-dQ = sum_k [A~ lambda_k^- alpha_k + (1 - sgn lambda_k)/2 beta_k] r_k   (to cell i)
//   A^+dQ = Phi - A^-dQ                                                       (to cell i+1)
// i.e. the flux part is Roe upwinded (Harten entropy fix on the acoustic waves) and the source part
// is projected on the characteristics and sent upwind (Bermudez-Vazquez upwinding).
// Second order in space and time (Lax-Wendroff-TVD): correction flux
//   F~ = 1/2 sum_k sgn(lambda_k) (1 - dt/dx |lambda_k|) phi(theta_k) Z_k r_k,
//   Z_k = A~ lambda_k alpha_k + beta_k,  theta_k = Z_k(upwind face)/Z_k,  phi = minmod/van Leer/superbee
// (the limiter acts on the characteristic wave strengths). Update:
//   V_i (q_i^{n+1} - q_i^n) = -dt [A^+dQ_{i-1/2} + A^-dQ_{i+1/2} + F~_{i+1/2} - F~_{i-1/2}].
// End faces: the boundary flux F_b enters as A^+dQ = F_0 - F_b - S_half dx (first order there).
// Wall heat q_w is applied after the step by implicit relaxation towards T_wall.
// Stable for dt <= CFL dx / max(|u| + c), CFL <= 1. Conserves mass and energy to round-off.
#pragma once
#include <vector>

#include "gasdyn/pipe_solver.hpp"

namespace hbt::gasdyn {

class TvdSolver final : public PipeSolver {
 public:
  TvdSolver(const PerfectGas& gas, const PipeConfig& cfg, const PipeGeometry& geo);
  void setState(int i, double rho, double u, double p) override;
  double rho(int i) const override { return rho_[i]; }
  double u(int i) const override { return u_[i]; }
  double p(int i) const override { return p_[i]; }
  EndState endState(End e) const override;
  CellFault step(double dt, const EndFlux& left, const EndFlux& right) override;
  double maxWaveSpeed() const override { return max_speed_; }
  double mass() const override;
  double energy() const override;

 private:
  void faceWaves();
  void correctionFluxes(double dt);
  CellFault findFault() const;
  void primitives(int i);

  PerfectGas gas_;
  const PipeConfig& cfg_;
  const PipeGeometry& geo_;
  int n_;
  // cells: conserved per volume, primitives, helpers
  std::vector<double> q1_, q2_, q3_;
  std::vector<double> rho_, u_, p_, H_, c_, srho_, fr_;
  // faces (n+1): fluctuations, f-wave strengths, Roe speeds, correction flux
  std::vector<double> am1_, am2_, am3_, ap1_, ap2_, ap3_;
  std::vector<double> z1_, z2_, z3_, ut_, ct_, Ht_;
  std::vector<double> ft1_, ft2_, ft3_;
  std::vector<double> inv_V_, fric_k_;  // 1/V_i, f_D A/(2 D) per cell
  double max_speed_ = 0.0;
};

}  // namespace hbt::gasdyn
