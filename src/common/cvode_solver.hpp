// One SUNDIALS CVODE integrator (BDF, dense direct linear solver) with everything it owns: the
// SUNContext, the state and absolute-tolerance vectors, the dense matrix and linear solver and
// the CVODE memory, freed in reverse order by the destructor. A failure of any SUNDIALS call
// throws hbt::ModelDivergence naming the owner, the call and CVODE's flag name.
//
// Quadratures (optional): integrals q(t) = ∫ g(t, y) dt that the state's right-hand side does
// not depend on (cumulative amounts, heats). CVODES integrates them with the state's steps but
// outside the Newton iteration, so the dense Jacobian and its LU cover the state alone; they
// are part of the local error test (CVodeSetQuadErrCon) with their own absolute tolerances.
#pragma once
#include <cvodes/cvodes.h>
#include <cvodes/cvodes_ls.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>
#include <sundials/sundials_nvector.h>

#include <string>
#include <vector>

namespace hbt {

class CvodeSolver {
 public:
  /// Creates the solver for neq equations ydot = rhs(t, y, user_data), state 0 at t = 0:
  /// relative tolerance rtol, absolute tolerances atol (one per equation, in y's units), at most
  /// max_steps internal steps per call of advance(), an analytic Jacobian if jac is given (else
  /// CVODE's difference quotients). owner names the model in error messages.
  CvodeSolver(const std::string& owner, int neq, CVRhsFn rhs, void* user_data, double rtol,
              const std::vector<double>& atol, long max_steps, CVLsJacFn jac = nullptr);
  ~CvodeSolver();
  CvodeSolver(const CvodeSolver&) = delete;
  CvodeSolver& operator=(const CvodeSolver&) = delete;

  int size() const { return neq_; }
  /// The state: set it before reinit(), read it after advance().
  double* y();
  /// The absolute tolerances; takes effect at the next setTolerances().
  double* atol();
  /// Restarts the integration at t = 0 from the state y().
  void reinit();
  /// The integration stops exactly at t_stop [s] (no step beyond it).
  void setStopTime(double t_stop);
  /// Relative tolerance rtol with the absolute tolerances atol().
  void setTolerances(double rtol);
  /// First internal step [s] (0: CVODE's estimate).
  void setInitialStep(double h0);
  /// Integrates from t = 0 to t_out [s] (the state in y(), the quadratures in quadratures());
  /// returns the internal steps taken. A failure throws naming `quantity`. No allocation unless
  /// it throws.
  long advance(double t_out, const char* quantity);

  /// Root functions (optional): CVODE locates the zero crossings of g_i(t, y), i < nroots,
  /// during step(). Call once, after construction.
  void addRootFunctions(int nroots, CVRootFn g);
  /// One internal step towards t_out [s], never past the stop time (CV_ONE_STEP mode): the
  /// state in y() at the returned time [s]. *root: a root function crossed zero (its direction
  /// in rootsFound()); the returned time is the crossing. A failure throws naming `quantity`.
  double step(double t_out, const char* quantity, bool* root);
  /// After step() returned a root: per root function 0 (none), +1 (rising) or -1 (falling).
  const std::vector<int>& rootsFound();

  /// Adds nq quadratures dq/dt = rhsQ(t, y, user_data) with absolute tolerances atolQ (one
  /// per quadrature, in q's units) and the state's relative tolerance; q = 0 at t = 0. Call once,
  /// after construction.
  void addQuadratures(int nq, CVQuadRhsFn rhsQ, const std::vector<double>& atolQ);
  /// The quadratures: set them before reinit() (their values at t = 0), read them after advance().
  double* quadratures();

 private:
  void check(int flag, const char* call) const;
  void release();  // frees whatever was created, in reverse order

  std::string owner_;
  int neq_ = 0;
  SUNContext ctx_ = nullptr;
  double rtol_ = 0.0;
  N_Vector y_ = nullptr, atol_ = nullptr, q_ = nullptr, atolQ_ = nullptr;
  SUNMatrix A_ = nullptr;
  SUNLinearSolver LS_ = nullptr;
  void* mem_ = nullptr;
  std::vector<int> roots_found_;
};

}  // namespace hbt
