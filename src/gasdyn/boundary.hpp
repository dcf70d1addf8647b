// Boundary: anything that drives pipe ends (closed end, open end, valve, turbine entry, ...).
// Each step the Network calls computeFluxes(t) on every boundary (it reads the end-cell states and
// sets the end-face fluxes, and adds the opposite flows to any Volume it feeds), then steps the
// pipes and volumes with those fluxes. One virtual call per boundary per step.
#pragma once
#include <limits>
#include <string>

#include "gasdyn/pipe.hpp"

namespace hbt::gasdyn {

/// A pipe end: the pipe and which of its ends.
struct PipeEnd {
  Pipe* pipe = nullptr;
  End end = End::Left;
  EndState state() const { return pipe->endState(end); }
  void setFlux(const EndFlux& f) const { pipe->setEndFlux(end, f); }
  double area() const { return end == End::Left ? pipe->geometry().A_face.front()
                                                 : pipe->geometry().A_face.back(); }
};
inline PipeEnd leftEnd(Pipe& p) { return {&p, End::Left}; }
inline PipeEnd rightEnd(Pipe& p) { return {&p, End::Right}; }

class Boundary {
 public:
  explicit Boundary(std::string name) : name_(std::move(name)) {}
  virtual ~Boundary() = default;
  Boundary(const Boundary&) = delete;
  Boundary& operator=(const Boundary&) = delete;
  const std::string& name() const { return name_; }
  /// Sets the end-face fluxes of the connected pipe ends for the step starting at time t [s].
  virtual void computeFluxes(double t) = 0;
  /// Called once after every step of length dt [s] (bookkeeping).
  virtual void afterStep(double dt) {}
  /// Largest stable step this boundary allows [s].
  virtual double maxDt() const { return std::numeric_limits<double>::infinity(); }

 protected:
  /// Claims a pipe end (throws InputError if another boundary already has it).
  PipeEnd claim(PipeEnd e) {
    e.pipe->attach(e.end, name_);
    return e;
  }

 private:
  std::string name_;
};

}  // namespace hbt::gasdyn
