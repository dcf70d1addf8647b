// Linear lumped-parameter thermal network with N = 4 nodes and two boundaries, the LT coolant
// and the engine structure the machine is bolted to, solved exactly for heat inputs and
// boundary temperatures held constant over a step.
//
//   C dx/dt = q + g_c T_c + g_e T_e − G x   x [K] node temperatures, q [W] heat into the nodes,
//                                         C [J/K] capacities (diagonal), T_c [K] coolant,
//                                         T_e [K] engine (flywheel housing, crankshaft)
//   G = L + diag(g_c + g_e)              L = weighted graph Laplacian of the node-node
//                                         conductances G_ij [W/K], g_c, g_e [W/K] node-coolant
//                                         and node-engine conductances.
// G is symmetric positive definite when every node is connected to a boundary through the
// graph, so with D = C^(-1/2) the matrix M = D G D is symmetric with eigenvalues λ_k > 0 and
// orthonormal eigenvectors Q (Eigen::SelfAdjointEigenSolver, once, in the constructor). With
// the steady state x_ss = G⁻¹ (q + g_c T_c + g_e T_e) and z = Qᵀ D⁻¹ (x_0 − x_ss):
//   x(h)        = x_ss + D Q diag(e^(−λ_k h)) z
//   ∫_0^h x dt  = x_ss h + D Q diag((1 − e^(−λ_k h))/λ_k) z      (−expm1 for small λh)
// which is exact for any h (no stability limit, stiff modes included). Over the step the heat
// leaving to the coolant is Q_c = g_cᵀ(∫x dt − T_c h) and the heat coming in from the engine is
// Q_e = g_eᵀ(T_e h − ∫x dt); then Σq h + Q_e − Q_c − Σ C Δx = 0 up to rounding (all computed
// from the same exact solution, not one from the other). Fixed-size Eigen matrices: no
// allocation in step().
#pragma once
#include <Eigen/Dense>
#include <string>

namespace hbt::emachine {

class ThermalNetwork {
 public:
  static constexpr int N = 4;
  using Vec = Eigen::Matrix<double, N, 1>;
  using Mat = Eigen::Matrix<double, N, N>;

  ThermalNetwork() = default;
  /// C > 0; Gnode symmetric, >= 0 off the diagonal (its diagonal is ignored); g_coolant,
  /// g_engine >= 0. Throws InputError(source, "thermal/...") if a node is connected to neither
  /// boundary.
  ThermalNetwork(const Vec& C, const Mat& Gnode, const Vec& g_coolant, const Vec& g_engine,
                 const std::string& source = "thermal network");

  /// Advances x over h [s] with q [W], T_c and T_e [K] held; returns ∫x dt over the step in x_int.
  void step(double h, const Vec& q, double T_c, double T_e, Vec& x, Vec& x_int) const;
  /// G⁻¹ (q + g_c T_c + g_e T_e).
  Vec steadyState(const Vec& q, double T_c, double T_e) const {
    return Ginv_ * (q + g_ * T_c + ge_ * T_e);
  }
  const Mat& conductance() const { return G_; }
  const Vec& capacity() const { return C_; }
  const Vec& coolantConductance() const { return g_; }
  const Vec& engineConductance() const { return ge_; }
  const Vec& eigenvalues() const { return lambda_; }  // 1/s, ascending

 private:
  Vec C_ = Vec::Ones(), g_ = Vec::Zero(), ge_ = Vec::Zero(), D_ = Vec::Ones(), lambda_ = Vec::Ones();
  Mat G_ = Mat::Identity(), Ginv_ = Mat::Identity(), Q_ = Mat::Identity();
};

}  // namespace hbt::emachine
