#include "common/cvode_solver.hpp"

#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cstdlib>

#include "common/errors.hpp"

namespace hbt {
namespace {
// CVODE's name of a return flag ("CV_TOO_MUCH_WORK"), with the number.
std::string flagName(int flag) {
  char* name = CVodeGetReturnFlagName(flag);  // malloc'd by SUNDIALS
  std::string s = name ? name : "unknown flag";
  std::free(name);
  return s + " (flag " + std::to_string(flag) + ")";
}
}  // namespace

CvodeSolver::CvodeSolver(const std::string& owner, int neq, CVRhsFn rhs, void* user_data,
                         double rtol, const std::vector<double>& atol, long max_steps,
                         CVLsJacFn jac)
    : owner_(owner), neq_(neq), rtol_(rtol) {
  if (neq <= 0 || static_cast<int>(atol.size()) != neq)
    throw ModelDivergence(owner_, "CVODE", "need neq > 0 and one absolute tolerance per equation");
  if (SUNContext_Create(nullptr, &ctx_) != 0)
    throw ModelDivergence(owner_, "CVODE", "SUNContext_Create failed");
  y_ = N_VNew_Serial(neq, ctx_);
  atol_ = N_VNew_Serial(neq, ctx_);
  mem_ = CVodeCreate(CV_BDF, ctx_);
  A_ = SUNDenseMatrix(neq, neq, ctx_);
  LS_ = y_ && A_ ? SUNLinSol_Dense(y_, A_, ctx_) : nullptr;
  if (!y_ || !atol_ || !mem_ || !A_ || !LS_) {
    const char* what = !y_ || !atol_ ? "N_VNew_Serial" : !mem_ ? "CVodeCreate" : !A_ ? "SUNDenseMatrix"
                                                                                     : "SUNLinSol_Dense";
    release();
    throw ModelDivergence(owner_, "CVODE", std::string(what) + " failed (allocation of solver memory)");
  }
  double* y0 = N_VGetArrayPointer(y_);
  double* a = N_VGetArrayPointer(atol_);
  for (int i = 0; i < neq; ++i) {
    y0[i] = 0.0;
    a[i] = atol[i];
  }
  try {
    check(CVodeInit(mem_, rhs, 0.0, y_), "CVodeInit");
    check(CVodeSVtolerances(mem_, rtol, atol_), "CVodeSVtolerances");
    check(CVodeSetLinearSolver(mem_, LS_, A_), "CVodeSetLinearSolver");
    if (jac) check(CVodeSetJacFn(mem_, jac), "CVodeSetJacFn");
    check(CVodeSetUserData(mem_, user_data), "CVodeSetUserData");
    check(CVodeSetMaxNumSteps(mem_, max_steps), "CVodeSetMaxNumSteps");
  } catch (...) {
    release();
    throw;
  }
}

CvodeSolver::~CvodeSolver() { release(); }

void CvodeSolver::release() {
  if (mem_) CVodeFree(&mem_);
  if (LS_) SUNLinSolFree(LS_);
  if (A_) SUNMatDestroy(A_);
  if (y_) N_VDestroy(y_);
  if (atol_) N_VDestroy(atol_);
  if (q_) N_VDestroy(q_);
  if (atolQ_) N_VDestroy(atolQ_);
  if (ctx_) SUNContext_Free(&ctx_);
  mem_ = nullptr;
  LS_ = nullptr;
  A_ = nullptr;
  y_ = atol_ = q_ = atolQ_ = nullptr;
}

double* CvodeSolver::y() { return N_VGetArrayPointer(y_); }
double* CvodeSolver::atol() { return N_VGetArrayPointer(atol_); }

void CvodeSolver::check(int flag, const char* call) const {
  if (flag != CV_SUCCESS) throw ModelDivergence(owner_, "CVODE", std::string(call) + " failed: " + flagName(flag));
}

void CvodeSolver::reinit() {
  check(CVodeReInit(mem_, 0.0, y_), "CVodeReInit");
  if (q_) check(CVodeQuadReInit(mem_, q_), "CVodeQuadReInit");
}

void CvodeSolver::addQuadratures(int nq, CVQuadRhsFn rhsQ, const std::vector<double>& atolQ) {
  if (q_ || nq <= 0 || static_cast<int>(atolQ.size()) != nq)
    throw ModelDivergence(owner_, "CVODE", "quadratures: added once, nq > 0, one absolute tolerance each");
  q_ = N_VNew_Serial(nq, ctx_);
  atolQ_ = N_VNew_Serial(nq, ctx_);
  if (!q_ || !atolQ_) throw ModelDivergence(owner_, "CVODE", "N_VNew_Serial failed (quadratures)");
  double* q0 = N_VGetArrayPointer(q_);
  double* a = N_VGetArrayPointer(atolQ_);
  for (int i = 0; i < nq; ++i) {
    q0[i] = 0.0;
    a[i] = atolQ[i];
  }
  check(CVodeQuadInit(mem_, rhsQ, q_), "CVodeQuadInit");
  check(CVodeQuadSVtolerances(mem_, rtol_, atolQ_), "CVodeQuadSVtolerances");
  check(CVodeSetQuadErrCon(mem_, SUNTRUE), "CVodeSetQuadErrCon");
}

void CvodeSolver::addRootFunctions(int nroots, CVRootFn g) {
  if (!roots_found_.empty() || nroots <= 0)
    throw ModelDivergence(owner_, "CVODE", "root functions: added once, nroots > 0");
  check(CVodeRootInit(mem_, nroots, g), "CVodeRootInit");
  roots_found_.assign(static_cast<std::size_t>(nroots), 0);
}

double CvodeSolver::step(double t_out, const char* quantity, bool* root) {
  realtype t = 0.0;
  const int flag = CVode(mem_, t_out, y_, &t, CV_ONE_STEP);
  if (flag < 0) throw ModelDivergence(owner_, quantity, "CVODE failed: " + flagName(flag));
  *root = flag == CV_ROOT_RETURN;
  return t;
}

const std::vector<int>& CvodeSolver::rootsFound() {
  if (!roots_found_.empty()) check(CVodeGetRootInfo(mem_, roots_found_.data()), "CVodeGetRootInfo");
  return roots_found_;
}

double* CvodeSolver::quadratures() { return q_ ? N_VGetArrayPointer(q_) : nullptr; }
void CvodeSolver::setStopTime(double t_stop) { check(CVodeSetStopTime(mem_, t_stop), "CVodeSetStopTime"); }
void CvodeSolver::setTolerances(double rtol) {
  rtol_ = rtol;
  check(CVodeSVtolerances(mem_, rtol, atol_), "CVodeSVtolerances");
  if (q_) check(CVodeQuadSVtolerances(mem_, rtol, atolQ_), "CVodeQuadSVtolerances");
}
void CvodeSolver::setInitialStep(double h0) { check(CVodeSetInitStep(mem_, h0), "CVodeSetInitStep"); }

long CvodeSolver::advance(double t_out, const char* quantity) {
  realtype t = 0.0;
  const int flag = CVode(mem_, t_out, y_, &t, CV_NORMAL);
  if (flag < 0) throw ModelDivergence(owner_, quantity, "CVODE failed: " + flagName(flag));
  if (q_) check(CVodeGetQuad(mem_, &t, q_), "CVodeGetQuad");
  long nst = 0;
  CVodeGetNumSteps(mem_, &nst);
  return nst;
}

}  // namespace hbt
