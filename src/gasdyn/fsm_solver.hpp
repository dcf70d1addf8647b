// FSM: the "fast simulation method", a staggered finite-volume "1D cell" scheme (SPEC section 3).
//
// Unknowns: in cell centres c at integer time levels n, density rho [kg/m^3] and total energy per
// volume rho e0 [J/m^3] (e0 = cv T + u^2/2); at the ports p (cell faces) at half levels n+1/2, the
// mass flux m = rho u A [kg/s].
//   rho_c^{n+1}    = rho_c^n    + dt/V_c sum_ports (rho u A)^{n+1/2}                (mass)
//   (rho e0)_c^{n+1} = (rho e0)_c^n + dt/V_c sum_ports (rho u h0 A)^{n+1/2} + S_e      (energy)
//   (rho u A)_p^{n+1/2} = (rho u A)_p^{n-1/2} + dt/dL sum [(p + rho u^2) A] + S_m       (momentum)
// with h0 = cp T + u^2/2 [J/kg], port sums signed into the control volume, dL = dx.
// Discretisation details:
//  * h0 at a port is taken from the donor (upwind) cell by the sign of m (donor cell);
//  * port velocity u_p = m/(rho_mean A_p) (mean of the two cell densities), centre velocity
//    u_c = (u_l + u_r)/2 (also for the kinetic energy in p = (gamma-1)(rho e0 - rho u_c^2/2));
//  * the momentum flux rho u^2 A at a centre is u_c m_donor, with
//    m_donor the upwind port's m (donor cell); the pressure term is written A_p (p_{c-1} - p_c),
//    i.e. sum[pA] plus the area source S_m = p dA/dx folded in (exactly at rest: no spurious flow);
//  * S_m also holds wall friction -f_D/(2D) rho u|u| A dL, applied implicitly (linearised), and a
//    bulk viscosity q = rho (c2 du^2 + c1 c |du|) [Pa] added to p where the cell is compressed
//    (du < 0) so shocks are captured without ringing on coarse meshes;
//  * S_e = wall heat dt q_w/A_c, implicitly limited so T never overshoots T_wall.
//  * end ports carry the mass and enthalpy flows given by the boundary objects.
// Stable for dt <= CFL dx / max(|u| + c + 2 nu/dx) (nu/dx = c1 c + c2 |du| in compression; 0
// with one cell: its two ports are boundary faces, so q never acts). Conserves mass and total
// energy to round-off.
// One cell: a valid element (mass and energy of the cell, both port fluxes from the boundaries'
// characteristic face solutions); it carries no momentum equation of its own, the end faces see
// the cell velocity (mean of the two port velocities) through the Riemann invariants.
#pragma once
#include <vector>

#include "gasdyn/pipe_solver.hpp"

namespace hbt::gasdyn {

class FsmSolver final : public PipeSolver {
 public:
  FsmSolver(const PerfectGas& gas, const PipeConfig& cfg, const PipeGeometry& geo);
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
  void updatePrimitives(int i);
  double faceVelocity(int j) const;
  double wallHeat(int i, double dt, double r_new) const;
  CellFault findFault() const;

  PerfectGas gas_;
  const PipeConfig& cfg_;
  const PipeGeometry& geo_;
  int n_;
  // cells
  std::vector<double> rho_, E_, p_, u_, c_, h0_, mom_, pq_;
  // ports (n+1): mass flux [kg/s]; ports 0 and n are set by the boundaries
  std::vector<double> m_, uf_;  // uf_: port velocity m/(rho_mean A) [m/s]
  std::vector<double> u_init_;
  std::vector<double> inv_V_, inv_Af_, fric_;  // 1/V_c, 1/A_p, f_D/(2 D_p)
  double max_speed_ = 0.0;
};

}  // namespace hbt::gasdyn
