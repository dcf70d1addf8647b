#include "emachine/thermal_network.hpp"

#include <cmath>

#include "common/errors.hpp"

namespace hbt::emachine {

ThermalNetwork::ThermalNetwork(const Vec& C, const Mat& Gnode, const Vec& g, const Vec& ge,
                               const std::string& source)
    : C_(C), g_(g), ge_(ge) {
  for (int i = 0; i < N; ++i) {
    if (!(C(i) > 0.0) || !std::isfinite(C(i)))
      throw InputError(source, "thermal/C", "heat capacities must be positive and finite");
    if (!(g(i) >= 0.0) || !std::isfinite(g(i)))
      throw InputError(source, "thermal/G_housing_coolant_W_K", "coolant conductance must be >= 0");
    if (!(ge(i) >= 0.0) || !std::isfinite(ge(i)))
      throw InputError(source, "thermal/G_housing_engine_W_K", "engine conductances must be >= 0");
  }
  G_.setZero();
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      if (i == j) continue;
      const double gij = 0.5 * (Gnode(i, j) + Gnode(j, i));
      if (!(gij >= 0.0) || !std::isfinite(gij))
        throw InputError(source, "thermal/G", "conductances must be >= 0 and finite");
      G_(i, j) = -gij;
      G_(i, i) += gij;
    }
  for (int i = 0; i < N; ++i) G_(i, i) += g_(i) + ge_(i);
  for (int i = 0; i < N; ++i) D_(i) = 1.0 / std::sqrt(C_(i));
  const Mat M = D_.asDiagonal() * G_ * D_.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Mat> es(M);
  if (es.info() != Eigen::Success)
    throw InputError(source, "thermal/G", "eigen-decomposition of the network failed");
  lambda_ = es.eigenvalues();
  Q_ = es.eigenvectors();
  if (!(lambda_(0) > 1e-12 * lambda_(N - 1)))
    throw InputError(source, "thermal/G_housing_coolant_W_K",
                     "a node has no conduction path to the coolant or the engine (singular network)");
  Ginv_ = G_.inverse();
}

void ThermalNetwork::step(double h, const Vec& q, double T_c, double T_e, Vec& x, Vec& x_int) const {
  const Vec xss = steadyState(q, T_c, T_e);
  const Vec z = Q_.transpose() * ((x - xss).array() / D_.array()).matrix();
  Vec e, ie;
  for (int k = 0; k < N; ++k) {
    const double lh = lambda_(k) * h;
    e(k) = std::exp(-lh);
    ie(k) = -std::expm1(-lh) / lambda_(k);
  }
  const Vec a = Q_ * (e.array() * z.array()).matrix();
  const Vec b = Q_ * (ie.array() * z.array()).matrix();
  x = xss + (D_.array() * a.array()).matrix();
  x_int = xss * h + (D_.array() * b.array()).matrix();
}

}  // namespace hbt::emachine
