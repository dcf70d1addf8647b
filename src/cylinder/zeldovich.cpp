#include "cylinder/zeldovich.hpp"

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <string>

#include "common/cvode_solver.hpp"

namespace hbt::cylinder {

struct ZeldovichAccess {
  static int rhs(realtype, N_Vector y, N_Vector yd, void* ud) {
    const auto* z = static_cast<const ZeldovichNO*>(ud);
    double dNO, dN;
    z->rates(NV_Ith_S(y, 0), NV_Ith_S(y, 1), dNO, dN);
    NV_Ith_S(yd, 0) = dNO;
    NV_Ith_S(yd, 1) = dN;
    return 0;
  }
  static int jac(realtype, N_Vector y, N_Vector, SUNMatrix J, void* ud, N_Vector, N_Vector,
                 N_Vector) {
    const auto* z = static_cast<const ZeldovichNO*>(ud);
    const double NO = NV_Ith_S(y, 0), N = NV_Ith_S(y, 1);
    const double* c = z->c_;
    const double d1NO = -z->k1r_ * N, d1N = -z->k1r_ * NO;
    const double d2NO = -z->k2r_ * c[kO], d2N = z->k2f_ * c[kO2];
    const double d3NO = -z->k3r_ * c[kH], d3N = z->k3f_ * c[kOH];
    SM_ELEMENT_D(J, 0, 0) = d1NO + d2NO + d3NO;
    SM_ELEMENT_D(J, 0, 1) = d1N + d2N + d3N;
    SM_ELEMENT_D(J, 1, 0) = d1NO - d2NO - d3NO;
    SM_ELEMENT_D(J, 1, 1) = d1N - d2N - d3N;
    return 0;
  }
};

// CVODE: relative tolerance 1e-6 until the first integrate() sets rtol_, absolute tolerances
// per unit concentration until setConditions() scales them, at most 20000 steps per interval.
ZeldovichNO::ZeldovichNO()
    : cvode_(std::make_unique<CvodeSolver>("ZeldovichNO", 2, &ZeldovichAccess::rhs, this, 1e-6,
                                           std::vector<double>{1e-12, 1e-16}, 20000,
                                           &ZeldovichAccess::jac)) {}

ZeldovichNO::~ZeldovichNO() = default;

void ZeldovichNO::setConditions(double T, double p, const double x[kNumSpecies]) {
  ctot_ = p / (kRu * T);
  for (int s = 0; s < kNumSpecies; ++s) c_[s] = x[s] * ctot_;
  // Equilibrium constants K = exp(−ΔG°/RT) of the three reactions (Δn = 0: K_c = K_p).
  const double gNO = gRT(kNO, T), gN = gRT(kN, T), gO = gRT(kO, T), gN2 = gRT(kN2, T);
  const double gO2 = gRT(kO2, T), gOH = gRT(kOH, T), gH = gRT(kH, T);
  const double K1 = std::exp(-(gNO + gN - gO - gN2));
  const double K2 = std::exp(-(gNO + gO - gN - gO2));
  const double K3 = std::exp(-(gNO + gH - gN - gOH));
  k1f_ = 7.6e7 * std::exp(-38000.0 / T);
  k2f_ = 6.4e3 * T * std::exp(-3150.0 / T);
  k3f_ = 4.1e7;
  k1r_ = k1f_ / K1;
  k2r_ = k2f_ / K2;
  k3r_ = k3f_ / K3;
  cNOe_ = c_[kNO];
  cvode_->atol()[0] = 1e-12 * ctot_;
  cvode_->atol()[1] = 1e-18 * ctot_;
}

void ZeldovichNO::rates(double NO, double N, double& dNO, double& dN) const {
  const double r1 = k1f_ * c_[kO] * c_[kN2] - k1r_ * NO * N;
  const double r2 = k2f_ * N * c_[kO2] - k2r_ * NO * c_[kO];
  const double r3 = k3f_ * N * c_[kOH] - k3r_ * NO * c_[kH];
  dNO = r1 + r2 + r3;
  dN = r1 - r2 - r3;
}

double ZeldovichNO::quasiSteadyN(double NO) const {
  // d[N]/dt = 0 is linear in [N]:  N (k1r NO + k2f O2 + k3f OH) = k1f O N2 + NO (k2r O + k3r H)
  const double num = k1f_ * c_[kO] * c_[kN2] + NO * (k2r_ * c_[kO] + k3r_ * c_[kH]);
  const double den = k1r_ * NO + k2f_ * c_[kO2] + k3f_ * c_[kOH];
  return den > 0.0 ? num / den : 0.0;
}

void ZeldovichNO::integrate(double dt, double& c_NO, double& c_N, bool start_N_qss) {
  if (start_N_qss) c_N = quasiSteadyN(c_NO);
  double* y = cvode_->y();
  y[0] = c_NO;
  y[1] = c_N;
  cvode_->reinit();
  cvode_->setTolerances(rtol_);
  cvode_->setStopTime(dt);
  cvode_->setInitialStep(start_N_qss ? dt * init_frac_ : 0.0);
  steps_ += cvode_->advance(dt, "NO concentration");
  c_NO = y[0];
  c_N = y[1];
}

}  // namespace hbt::cylinder
