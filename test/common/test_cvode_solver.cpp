// CvodeSolver: integrates a linear decay to CVODE's tolerance, its quadratures to their exact
// integrals (restarting from the values set), steps one internal step at a time to a stop time
// and locates a root of a root function at its exact crossing time, and names CVODE's flag and
// the owner when the integration fails.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/cvode_solver.hpp"
#include "common/errors.hpp"

namespace {

// dy/dt = -k y, k [1/s] in user data.
int decay(realtype, N_Vector y, N_Vector yd, void* ud) {
  const double k = *static_cast<const double*>(ud);
  N_VGetArrayPointer(yd)[0] = -k * N_VGetArrayPointer(y)[0];
  return 0;
}

// quadratures of the decay: q0 = ∫ y dt, q1 = ∫ y² dt
int decayIntegrals(realtype, N_Vector y, N_Vector qd, void*) {
  const double x = N_VGetArrayPointer(y)[0];
  N_VGetArrayPointer(qd)[0] = x;
  N_VGetArrayPointer(qd)[1] = x * x;
  return 0;
}

int failingRhs(realtype, N_Vector, N_Vector, void*) { return -1; }  // unrecoverable

std::string messageOf(hbt::CvodeSolver& s, double t_out) {
  try {
    s.advance(t_out, "test quantity");
  } catch (const hbt::ModelDivergence& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CvodeSolver, IntegratesAnExponentialDecay) {
  double k = 2.0;
  hbt::CvodeSolver s("decay", 1, &decay, &k, 1e-8, {1e-12}, 5000);
  for (int restart = 0; restart < 2; ++restart) {
    s.y()[0] = 1.0;
    s.reinit();
    s.setStopTime(0.5);
    EXPECT_GT(s.advance(0.5, "y"), 0);
    EXPECT_NEAR(s.y()[0], std::exp(-1.0), 1e-6);
  }
}

TEST(CvodeSolver, QuadraturesIntegrateExactlyAndRestartFromTheirSetValues) {
  // y = exp(-k t): ∫0^T y dt = (1 - e^{-kT})/k, ∫0^T y² dt = (1 - e^{-2kT})/(2k)
  double k = 2.0;
  const double T = 0.5;
  hbt::CvodeSolver s("decay", 1, &decay, &k, 1e-8, {1e-12}, 5000);
  s.addQuadratures(2, &decayIntegrals, {1e-12, 1e-12});
  for (const double q0 : {0.0, 3.0}) {  // a restart from set values: the integral adds to them
    s.y()[0] = 1.0;
    s.quadratures()[0] = q0;
    s.quadratures()[1] = 0.0;
    s.reinit();
    s.setStopTime(T);
    s.advance(T, "y");
    EXPECT_NEAR(s.quadratures()[0], q0 + (1.0 - std::exp(-k * T)) / k, 1e-7);
    EXPECT_NEAR(s.quadratures()[1], (1.0 - std::exp(-2.0 * k * T)) / (2.0 * k), 1e-7);
  }
  EXPECT_THROW(s.addQuadratures(1, &decayIntegrals, {1e-12}), hbt::ModelDivergence);  // once only
}

TEST(CvodeSolver, FailuresNameOwnerQuantityAndFlag) {
  double k = 2.0;
  hbt::CvodeSolver few("decay", 1, &decay, &k, 1e-10, {1e-14}, 2);
  few.y()[0] = 1.0;
  few.reinit();
  const std::string m = messageOf(few, 100.0);
  EXPECT_NE(m.find("decay: test quantity: CVODE failed: CV_TOO_MUCH_WORK"), std::string::npos) << m;

  hbt::CvodeSolver bad("bad rhs", 1, &failingRhs, nullptr, 1e-6, {1e-12}, 100);
  bad.y()[0] = 1.0;
  bad.reinit();
  const std::string b = messageOf(bad, 1.0);
  EXPECT_NE(b.find("bad rhs: test quantity: CVODE failed: CV_RHSFUNC_FAIL"), std::string::npos) << b;

  try {
    bad.setTolerances(-1.0);  // a negative relative tolerance: CVODE rejects it
    ADD_FAILURE() << "no exception";
  } catch (const hbt::ModelDivergence& e) {
    EXPECT_NE(std::string(e.what()).find("bad rhs: CVODE: CVodeSVtolerances failed: CV_ILL_INPUT"), std::string::npos)
        << e.what();
  }
}

TEST(CvodeSolver, RejectsAToleranceCountOtherThanTheEquations) {
  double k = 1.0;
  EXPECT_THROW(hbt::CvodeSolver("decay", 2, &decay, &k, 1e-6, {1e-12}, 100), hbt::ModelDivergence);
}

namespace {
// g = y - 1/2: crosses zero (falling) at t = ln 2 / k for y = exp(-k t)
int halfLevel(realtype, N_Vector y, realtype* g, void*) {
  g[0] = N_VGetArrayPointer(y)[0] - 0.5;
  return 0;
}
}  // namespace

TEST(CvodeSolver, StepsToTheStopTimeAndLocatesARoot) {
  double k = 2.0;
  hbt::CvodeSolver s("decay", 1, &decay, &k, 1e-10, {1e-14}, 5000);
  s.addRootFunctions(1, &halfLevel);
  s.y()[0] = 1.0;
  s.reinit();
  s.setStopTime(1.0);
  double t = 0.0, t_root = -1.0;
  int steps = 0, roots = 0;
  while (t < 1.0) {
    bool root = false;
    const double t_new = s.step(1.0, "y", &root);
    EXPECT_GT(t_new, t);  // one internal step forward, never past the stop time
    EXPECT_LE(t_new, 1.0);
    t = t_new;
    ++steps;
    if (root) {
      ++roots;
      t_root = t;
      EXPECT_EQ(s.rootsFound().at(0), -1);  // falling
      EXPECT_NEAR(s.y()[0], 0.5, 1e-9);
    }
  }
  EXPECT_EQ(t, 1.0);
  EXPECT_GT(steps, 2);
  EXPECT_EQ(roots, 1);
  EXPECT_NEAR(t_root, std::log(2.0) / k, 1e-9);
  EXPECT_NEAR(s.y()[0], std::exp(-k), 1e-8);
}
