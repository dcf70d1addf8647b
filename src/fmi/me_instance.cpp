#include "fmi/me_instance.hpp"

#include <nvector/nvector_serial.h>

#include <algorithm>

#include "common/errors.hpp"
#include "fmi/fmu_error.hpp"

namespace hbt::fmi {

namespace {
constexpr int kMaxEventIterations = 1000;  // a discrete-state iteration that has not settled by then loops

std::shared_ptr<const LoadedFmu> requireMe(std::shared_ptr<const LoadedFmu> fmu) {
  if (fmu->interfaceType() != InterfaceType::kModelExchange) {
    throw FmuError(fmu->file(), "loaded as CoSimulation, not ModelExchange");
  }
  return fmu;
}
}  // namespace

MeInstance::MeInstance(std::shared_ptr<const LoadedFmu> fmu, const std::string& instance_name,
                       LogSink sink, double rtol, double atol, long max_steps)
    : Fmi2Instance(requireMe(std::move(fmu)), instance_name, std::move(sink)),
      nx_(fmu_->modelDescription().numberOfContinuousStates()),
      nz_(fmu_->modelDescription().numberOfEventIndicators()) {
  // an FMU without continuous states still has its events: one dummy state dx/dt = 0
  const int neq = std::max(nx_, 1);
  solver_ = std::make_unique<CvodeSolver>("FMU " + fmu_->file() + " instance '" + name_ + "'", neq,
                                          &MeInstance::rhs, this, rtol,
                                          std::vector<double>(static_cast<std::size_t>(neq), atol), max_steps);
  if (nz_ > 0) solver_->addRootFunctions(nz_, &MeInstance::indicators);
}

MeInstance::~MeInstance() = default;

bool MeInstance::setTimeAndStates(double t_s, const double* x) {
  fmi2Status s = f_.setTime(c_, t_s);
  if (s > fmi2Warning) {
    callback_status_ = s, callback_call_ = "fmi2SetTime";
    return false;
  }
  if (nx_ == 0) return true;
  s = f_.setContinuousStates(c_, x, static_cast<std::size_t>(nx_));
  if (s > fmi2Warning) {
    callback_status_ = s, callback_call_ = "fmi2SetContinuousStates";
    return false;
  }
  return true;
}

int MeInstance::rhs(double tau, N_Vector y, N_Vector ydot, void* self_ptr) {
  auto* self = static_cast<MeInstance*>(self_ptr);
  double* dx = N_VGetArrayPointer(ydot);
  if (self->nx_ == 0) {
    dx[0] = 0.0;
    return 0;
  }
  if (!self->setTimeAndStates(self->t0_s_ + tau, N_VGetArrayPointer(y))) return -1;
  const fmi2Status s = self->f_.getDerivatives(self->c_, dx, static_cast<std::size_t>(self->nx_));
  if (s > fmi2Warning) {
    self->callback_status_ = s, self->callback_call_ = "fmi2GetDerivatives";
    return -1;
  }
  return 0;
}

int MeInstance::indicators(double tau, N_Vector y, double* g, void* self_ptr) {
  auto* self = static_cast<MeInstance*>(self_ptr);
  if (!self->setTimeAndStates(self->t0_s_ + tau, N_VGetArrayPointer(y))) return -1;
  const fmi2Status s = self->f_.getEventIndicators(self->c_, g, static_cast<std::size_t>(self->nz_));
  if (s > fmi2Warning) {
    self->callback_status_ = s, self->callback_call_ = "fmi2GetEventIndicators";
    return -1;
  }
  return 0;
}

void MeInstance::reportCallbackFailure() {
  if (callback_status_ > fmi2Warning) check(callback_status_, callback_call_.c_str());
}

void MeInstance::exitInitializationMode() {
  Fmi2Instance::exitInitializationMode();  // the FMU is now in event mode
  eventIteration();
  check(f_.enterContinuousTimeMode(c_), "fmi2EnterContinuousTimeMode");
}

void MeInstance::eventIteration() {
  info_.newDiscreteStatesNeeded = fmi2True;
  for (int k = 0; info_.newDiscreteStatesNeeded; ++k) {
    if (k == kMaxEventIterations) {
      fail("fmi2NewDiscreteStates", "the event iteration did not settle in " +
                                        std::to_string(kMaxEventIterations) + " iterations");
    }
    check(f_.newDiscreteStates(c_, &info_), "fmi2NewDiscreteStates");
    if (info_.terminateSimulation) {
      fail("fmi2NewDiscreteStates", "the FMU ends the simulation (terminateSimulation)");
    }
  }
}

void MeInstance::restartSolver() {
  if (nx_ > 0) {
    check(f_.getContinuousStates(c_, solver_->y(), static_cast<std::size_t>(nx_)), "fmi2GetContinuousStates");
  } else {
    solver_->y()[0] = 0.0;
  }
  t0_s_ = time_s_;
  solver_->reinit();
}

void MeInstance::handleEvent() {
  check(f_.enterEventMode(c_), "fmi2EnterEventMode");
  eventIteration();
  check(f_.enterContinuousTimeMode(c_), "fmi2EnterContinuousTimeMode");
  restartSolver();
}

void MeInstance::integrateTo(double t_stop_s, bool time_event_at_stop) {
  const double tau_stop = t_stop_s - t0_s_;
  solver_->setStopTime(tau_stop);
  for (;;) {
    bool root = false;
    double tau = 0.0;
    try {
      tau = solver_->step(tau_stop, "continuous states", &root);
    } catch (const ModelDivergence&) {
      reportCallbackFailure();  // the FMU's failure, if it was one
      throw;
    }
    const bool reached = tau >= tau_stop;
    time_s_ = reached ? t_stop_s : t0_s_ + tau;
    if (!setTimeAndStates(time_s_, solver_->y())) reportCallbackFailure();
    fmi2Boolean enter_event = fmi2False, terminate = fmi2False;
    check(f_.completedIntegratorStep(c_, fmi2True, &enter_event, &terminate), "fmi2CompletedIntegratorStep");
    if (terminate) fail("fmi2CompletedIntegratorStep", "the FMU ends the simulation (terminateSimulation)");
    const bool time_event = reached && time_event_at_stop;
    time_events_ += time_event;
    state_events_ += root;
    step_events_ += enter_event != fmi2False;
    if (time_event || root || enter_event) {
      handleEvent();
      return;
    }
    if (reached) return;
  }
}

void MeInstance::doStep(double h_s) {
  checkStep("Model Exchange step", h_s);
  const double t_end_s = time_s_ + h_s;
  restartSolver();  // the inputs may have changed since the last step
  while (time_s_ < t_end_s) {
    const bool time_event = info_.nextEventTimeDefined && info_.nextEventTime <= t_end_s;
    if (time_event && info_.nextEventTime <= time_s_) {  // due now: handle it before integrating
      const double due_s = info_.nextEventTime;
      ++time_events_;
      handleEvent();
      if (info_.nextEventTimeDefined && info_.nextEventTime <= due_s) {
        fail("fmi2NewDiscreteStates", "nextEventTime " + std::to_string(info_.nextEventTime) +
                                          " s does not advance");
      }
      continue;
    }
    integrateTo(time_event ? info_.nextEventTime : t_end_s, time_event);
  }
}

std::vector<double> MeInstance::states() const {
  std::vector<double> x(static_cast<std::size_t>(nx_));
  if (nx_ > 0 && f_.getContinuousStates(c_, x.data(), x.size()) > fmi2Warning) {
    fail("fmi2GetContinuousStates", "failed");
  }
  return x;
}

}  // namespace hbt::fmi
