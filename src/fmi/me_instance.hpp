// One instance of an FMI 2.0 Model Exchange FMU (FMI 2.0 chapter 3) integrated by SUNDIALS
// CVODE (BDF, hbt::CvodeSolver) over each macro step [t, t + h], as section 3.2 of the standard
// (its state machine and its importer's pseudo-code) lays out the loop:
//   - between events the continuous states x (FMU's units) follow dx/dt = f(t, x, u) with the
//     inputs u held; CVODE calls fmi2SetTime, fmi2SetContinuousStates, fmi2GetDerivatives;
//   - time events: the integration stops exactly at the FMU's nextEventTime;
//   - state events: CVODE locates the sign changes of the event indicators
//     (fmi2GetEventIndicators) as roots;
//   - step events: fmi2CompletedIntegratorStep after every accepted CVODE step asks for one;
//   - at an event: fmi2EnterEventMode, fmi2NewDiscreteStates until no new discrete states are
//     needed, fmi2EnterContinuousTimeMode, the states read back and CVODE restarted there.
// CVODE also restarts at the start of each macro step (the inputs may have jumped). An FMU
// asking for terminateSimulation, or an event iteration that does not settle, is an error
// naming the FMU and the time; every FMU failure inside CVODE's callbacks is reported after
// CVODE returns (nothing unwinds through its C frames). Deterministic.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "common/cvode_solver.hpp"
#include "fmi/fmi2_instance.hpp"

namespace hbt::fmi {

class MeInstance : public Fmi2Instance {
 public:
  /// fmu loaded as ModelExchange; rtol [-] and atol [state units] CVODE's tolerances,
  /// max_steps its internal steps per segment between events.
  MeInstance(std::shared_ptr<const LoadedFmu> fmu, const std::string& instance_name, LogSink sink,
             double rtol, double atol, long max_steps);
  ~MeInstance() override;

  /// Leaves initialisation, runs the event iteration, enters continuous-time mode.
  void exitInitializationMode() override;
  /// Integrates from time() to time() + h_s [s] > 0, handling every event on the way.
  void doStep(double h_s);

  /// The continuous states at time() (FMU's units), in the FMU's order.
  std::vector<double> states() const;
  /// Events handled so far, by kind.
  long timeEvents() const { return time_events_; }
  long stateEvents() const { return state_events_; }
  long stepEvents() const { return step_events_; }

 private:
  static int rhs(double tau, N_Vector y, N_Vector ydot, void* self);
  static int indicators(double tau, N_Vector y, double* g, void* self);
  bool setTimeAndStates(double t_s, const double* x);  // false: a failed call was recorded
  void integrateTo(double t_stop_s, bool time_event_at_stop);
  void eventIteration();
  void handleEvent();
  void restartSolver();
  void reportCallbackFailure();

  int nx_ = 0, nz_ = 0;
  fmi2EventInfo info_{};
  std::unique_ptr<CvodeSolver> solver_;
  double t0_s_ = 0.0;  // the solver's time origin: CVODE time tau = t - t0
  long time_events_ = 0, state_events_ = 0, step_events_ = 0;
  fmi2Status callback_status_ = fmi2OK;  // the first failure inside a CVODE callback
  std::string callback_call_;
};

}  // namespace hbt::fmi
