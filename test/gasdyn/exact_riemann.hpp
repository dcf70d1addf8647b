// Exact solution of the Riemann problem of the 1D Euler equations for a perfect gas (Toro,
// "Riemann Solvers and Numerical Methods for Fluid Dynamics", ch. 4): Newton iteration on the
// star pressure, then sampling at x/t. Independent reference for the shock-tube tests.
#pragma once

namespace hbt::gasdyn::test {

struct Prim {
  double rho, u, p;
};

class ExactRiemann {
 public:
  ExactRiemann(double gamma, Prim left, Prim right);
  double pStar() const { return ps_; }
  double uStar() const { return us_; }
  /// Solution at the similarity coordinate s = (x - x0)/t [m/s].
  Prim sample(double s) const;

 private:
  double f(double p, const Prim& k, double c, double& df) const;
  double g_;
  Prim L_, R_;
  double cL_, cR_, ps_, us_;
};

}  // namespace hbt::gasdyn::test
