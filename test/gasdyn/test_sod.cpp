// Sod shock tube for both pipe solvers against the exact Riemann solution: L1 density error at
// 100/200/400 cells, its decrease under refinement and the observed convergence rate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "exact_riemann.hpp"
#include "gasdyn/cases.hpp"

using namespace hbt::gasdyn;
using hbt::gasdyn::test::ExactRiemann;
using hbt::gasdyn::test::Prim;

namespace {

constexpr double kT = 0.6e-3;

ExactRiemann sodExact() { return ExactRiemann(1.4, {1.0, 0.0, 1e5}, {0.125, 0.0, 1e4}); }

struct Errors {
  double rho, u, p;
};

// L1 norms over the tube [1 m x unit]: sum |q_i - q_exact(x_i)| dx
Errors l1(const Profile& r) {
  const ExactRiemann ex = sodExact();
  const double dx = 1.0 / r.x.size();
  Errors e{0, 0, 0};
  for (std::size_t i = 0; i < r.x.size(); ++i) {
    const Prim q = ex.sample((r.x[i] - 0.5) / kT);
    e.rho += std::abs(r.rho[i] - q.rho) * dx;
    e.u += std::abs(r.u[i] - q.u) * dx;
    e.p += std::abs(r.p[i] - q.p) * dx;
  }
  return e;
}

}  // namespace

TEST(ExactRiemann, SodStarStateMatchesToro) {
  // Toro table 4.2 test 1 scaled: p* = 0.30313 p_L, u* = 0.92745 sqrt(p_L/rho_L)
  const ExactRiemann ex = sodExact();
  EXPECT_NEAR(ex.pStar(), 0.30313e5, 2.0);
  EXPECT_NEAR(ex.uStar(), 0.92745 * std::sqrt(1e5), 0.02);
  // contact: left/right star densities 0.42632 / 0.26557
  EXPECT_NEAR(ex.sample(ex.uStar() - 1.0).rho, 0.42632, 1e-4);
  EXPECT_NEAR(ex.sample(ex.uStar() + 1.0).rho, 0.26557, 1e-4);
}

class SodConvergence : public ::testing::TestWithParam<SolverKind> {};

TEST_P(SodConvergence, L1DensityErrorConverges) {
  const SolverKind s = GetParam();
  double e[3];
  const int n[3] = {100, 200, 400};
  for (int k = 0; k < 3; ++k) {
    const Profile r = runSod(s, n[k], kT);
    const Errors er = l1(r);
    e[k] = er.rho;
    std::printf("[sod %s] cells %4d  L1(rho) %.5e kg/m^2  L1(u) %.4e  L1(p) %.4e\n",
                solverName(s), n[k], er.rho, er.u, er.p);
    for (std::size_t i = 0; i < r.x.size(); ++i) {
      ASSERT_GT(r.rho[i], 0.0);
      ASSERT_GT(r.p[i], 0.0);
    }
  }
  const double rate1 = std::log2(e[0] / e[1]), rate2 = std::log2(e[1] / e[2]);
  std::printf("[sod %s] observed rates %.3f %.3f\n", solverName(s), rate1, rate2);
  EXPECT_LT(e[1], e[0]);
  EXPECT_LT(e[2], e[1]);
  EXPECT_GT(rate1, 0.5);
  EXPECT_GT(rate2, 0.5);
  EXPECT_LT(e[0], 0.02);  // 2% of the density jump spread over the tube, at 100 cells
}

INSTANTIATE_TEST_SUITE_P(Solvers, SodConvergence, ::testing::Values(SolverKind::FSM, SolverKind::TVD),
                         [](const auto& i) { return std::string(solverName(i.param)); });

TEST(Sod, TvdMoreAccurateThanFsmAtEqualCells) {
  const double ef = l1(runSod(SolverKind::FSM, 200, kT)).rho;
  const double et = l1(runSod(SolverKind::TVD, 200, kT)).rho;
  std::printf("[sod] 200 cells: L1 fsm %.4e, tvd %.4e\n", ef, et);
  EXPECT_LT(et, ef);
}

TEST(Sod, ShockPositionAndPlateau) {
  // the post-shock plateau between contact (0.676 m) and shock (0.832 m) at 0.6 ms must be within 2% of the exact state
  const ExactRiemann ex = sodExact();
  for (SolverKind s : {SolverKind::FSM, SolverKind::TVD}) {
    const Profile r = runSod(s, 400, kT);
    for (std::size_t i = 0; i < r.x.size(); ++i) {
      const double xi = r.x[i];
      if (xi < 0.72 || xi > 0.80) continue;
      const Prim q = ex.sample((xi - 0.5) / kT);
      EXPECT_NEAR(r.p[i], q.p, 0.02 * q.p) << solverName(s) << " x=" << xi;
      EXPECT_NEAR(r.u[i], q.u, 0.02 * q.u) << solverName(s) << " x=" << xi;
    }
  }
}
