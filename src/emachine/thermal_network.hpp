// Linear lumped-parameter thermal network with N = 4 nodes and one coolant boundary, solved
// exactly for heat inputs and coolant temperature held constant over a step.
//
//   C dx/dt = q + g T_c − G x            x [K] node temperatures, q [W] heat into the nodes,
//                                         C [J/K] capacities (diagonal), T_c [K] coolant,
//   G = L + diag(g)                      L = weighted graph Laplacian of the node-node
//                                         conductances G_ij [W/K], g [W/K] node-coolant
//                                         conductances (here only the housing has one).
// G is symmetric positive definite when every node is connected to the coolant through the
// graph, so with D = C^(-1/2) the matrix M = D G D is symmetric with eigenvalues λ_k > 0 and
// orthonormal eigenvectors Q (Eigen::SelfAdjointEigenSolver, once, in the constructor). With
// the steady state x_ss = G⁻¹ (q + g T_c) and z = Qᵀ D⁻¹ (x_0 − x_ss):
//   x(h)        = x_ss + D Q diag(e^(−λ_k h)) z
//   ∫_0^h x dt  = x_ss h + D Q diag((1 − e^(−λ_k h))/λ_k) z      (−expm1 for small λh)
// which is exact for any h (no stability limit, stiff modes included). The heat leaving to the
// coolant over the step is gᵀ(∫x dt − T_c h); then Σq h − Q_coolant − Σ C Δx = 0 up to rounding
// (both computed from the same exact solution, not one from the other). Fixed-size Eigen
// matrices: no allocation in step().
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
  /// C > 0; Gnode symmetric, >= 0 off the diagonal (its diagonal is ignored); g >= 0. Throws
  /// InputError(source, "thermal/...") if the network has a node not connected to the coolant.
  ThermalNetwork(const Vec& C, const Mat& Gnode, const Vec& g, const std::string& source = "thermal network");

  /// Advances x over h [s] with q [W] and T_c [K] held; returns ∫x dt over the step in x_int.
  void step(double h, const Vec& q, double T_c, Vec& x, Vec& x_int) const;
  /// G⁻¹ (q + g T_c).
  Vec steadyState(const Vec& q, double T_c) const { return Ginv_ * (q + g_ * T_c); }
  const Mat& conductance() const { return G_; }
  const Vec& capacity() const { return C_; }
  const Vec& coolantConductance() const { return g_; }
  const Vec& eigenvalues() const { return lambda_; }  // 1/s, ascending

 private:
  Vec C_ = Vec::Ones(), g_ = Vec::Zero(), D_ = Vec::Ones(), lambda_ = Vec::Ones();
  Mat G_ = Mat::Identity(), Ginv_ = Mat::Identity(), Q_ = Mat::Identity();
};

}  // namespace hbt::emachine
