// DormandPrince: a linear decay and its integrals against the exact solution, the 5th order of
// the tableau (one step at h and h/2), a linear invariant kept to round-off across intervals whose
// right-hand side jumps, a stiff relaxation held stable by the step control, and the errors naming the
// owner and the quantity.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "common/dormand_prince.hpp"
#include "common/errors.hpp"

namespace {

using hbt::DormandPrince;

// dy/dt = -k y; integrals q0 = ∫ y dt, q1 = ∫ y² dt.
struct Decay {
  double k;
  void operator()(const double* y, double* yd, double* qd) const {
    yd[0] = -k * y[0];
    if (qd) {
      qd[0] = y[0];
      qd[1] = y[0] * y[0];
    }
  }
};

TEST(DormandPrince, ADecayAndItsIntegralsMatchTheExactSolution) {
  DormandPrince rk("test", 1, 2, 1e-10, {1e-14}, 10000);
  Decay f{2.0};
  double y = 1.0, q[2] = {0.0, 0.0};
  const long steps = rk.integrate(f, 3.0, &y, q, "y");
  EXPECT_NEAR(y, std::exp(-6.0), 1e-9 * std::exp(-6.0));
  EXPECT_NEAR(q[0], (1.0 - std::exp(-6.0)) / 2.0, 1e-9);
  EXPECT_NEAR(q[1], (1.0 - std::exp(-12.0)) / 4.0, 1e-9);
  EXPECT_GT(steps, 5);  // the tolerance, not the interval, sets the step
  std::printf("[rk] decay k = 2 over 3 s at rtol 1e-10: %ld steps, error %.2g relative\n", steps,
              y / std::exp(-6.0) - 1.0);
}

TEST(DormandPrince, OneStepIsFifthOrder) {
  // a loose tolerance accepts the whole interval as one step; local error ~ h^6
  auto error = [](double h) {
    DormandPrince rk("test", 1, 0, 1.0, {1.0}, 10);
    double y = 1.0;
    EXPECT_EQ(rk.integrate(Decay{1.0}, h, &y, nullptr, "y"), 1);
    return std::abs(y - std::exp(-h));
  };
  const double ratio = error(0.4) / error(0.2);
  EXPECT_GT(ratio, 0.8 * 64.0);
  EXPECT_LT(ratio, 1.2 * 64.0);
  std::printf("[rk] one-step error ratio h / (h/2): %.1f (h^6: 64)\n", ratio);
}

// A <-> B with a nonlinear exchange, B leaving at rate s B (counted by the integral q0) and A
// fed at a constant rate u: d(A + B + q0)/dt = u exactly.
struct Exchange {
  double u, kf, kr, s;
  void operator()(const double* y, double* yd, double* qd) const {
    const double r = kf * y[0] * y[0] - kr * y[1];
    yd[0] = u - r;
    yd[1] = r - s * y[1];
    if (qd) qd[0] = s * y[1];
  }
};

TEST(DormandPrince, ALinearInvariantHoldsToRoundOffAcrossJumpingInputs) {
  DormandPrince rk("test", 2, 1, 1e-6, {1e-12, 1e-12}, 10000);
  double y[2] = {0.2, 0.0}, fed = 0.0, left = 0.0;
  const double total0 = y[0] + y[1];
  for (int k = 0; k < 2000; ++k) {  // 200 s in 0.1 s intervals, every one with other rates
    const double u = 0.5 + 0.4 * std::sin(0.37 * k), T = 1.0 + 0.5 * std::cos(0.11 * k);
    double q = 0.0;
    rk.integrate(Exchange{u, 3.0 * T, 0.5, 0.2 * T}, 0.1, y, &q, "y");
    fed += u * 0.1;
    left += q;
  }
  const double residual = (y[0] + y[1] + left) - (total0 + fed);
  EXPECT_NEAR(residual, 0.0, 1e-13 * fed);
  std::printf("[rk] invariant over 2000 intervals: fed %.6g, residual %.2g\n", fed, residual);
}

// dy/dt = -k (y - 1): relaxation to 1, y = 1 - (1 - y0) e^(-k t).
struct Relax {
  double k;
  void operator()(const double* y, double* yd, double*) const { yd[0] = -k * (y[0] - 1.0); }
};

TEST(DormandPrince, AStiffRelaxationStaysStableAndAccurate) {
  // k h = 5 on each 0.01 s interval: outside the explicit stability region (about 3.3 on the
  // negative real axis), so the control must shrink the step; unstable steps would blow up
  DormandPrince rk("test", 1, 0, 1e-8, {1e-12}, 100000);
  double y = 0.0;
  long steps = 0;
  for (int k = 1; k <= 10; ++k) {
    steps += rk.integrate(Relax{500.0}, 0.01, &y, nullptr, "y");
    EXPECT_NEAR(y, 1.0 - std::exp(-5.0 * k), 1e-7) << "interval " << k;
  }
  EXPECT_GT(steps, 20);
  std::printf("[rk] stiff relaxation k = 500 1/s, ten 0.01 s intervals: %ld steps\n", steps);
}

TEST(DormandPrince, FailuresNameTheOwnerAndTheQuantity) {
  DormandPrince rk("my model", 1, 0, 1e-10, {1e-14}, 3);
  double y = 1.0;
  try {
    rk.integrate(Decay{1000.0}, 1.0, &y, nullptr, "coverage");
    FAIL() << "no error after max_steps";
  } catch (const hbt::ModelDivergence& e) {
    EXPECT_NE(std::string(e.what()).find("my model"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("coverage"), std::string::npos) << e.what();
  }
  DormandPrince rk2("my model", 1, 0, 1e-6, {1e-14}, 100);
  y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(rk2.integrate(Decay{1.0}, 1.0, &y, nullptr, "coverage"), hbt::ModelDivergence);
}

}  // namespace
