// Network: owns pipes, volumes (plenums, junctions, reservoirs) and boundaries and advances them
// together.
//
// Time stepping: one common step for the whole network. advance(interval) splits the interval in
// equal steps dt <= min(pipe CFL steps, volume steps V/(c sum A), boundary limits), re-evaluated
// every step; each step: every boundary computes its end-face fluxes from the states at t (and the
// matching volume flows), every finite volume closes its pipe-end ports (explicit, or linearised
// implicit in its pressure: setImplicitVolumes, volume.hpp; implicit ports do not limit the step),
// then every pipe and volume advances by dt with those fluxes. Mass and energy therefore move
// between elements exactly (conserved to round-off).
// Robustness: pipes/volumes throw hbt::ModelDivergence naming the element, cell and quantity on a
// non-physical state; a step below dt_floor (default 1e-9 s) throws naming the limiting element.
// No allocation inside advance() (all storage is sized at construction).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "gasdyn/boundaries.hpp"
#include "gasdyn/pipe.hpp"
#include "gasdyn/volume.hpp"

namespace hbt::gasdyn {

class Network {
 public:
  explicit Network(PerfectGas gas = {});
  const PerfectGas& gas() const { return gas_; }

  Pipe& addPipe(PipeConfig cfg);  // name must be unique
  Volume& addVolume(std::string name, double volume_m3, double p, double T);
  Volume& addReservoir(std::string name, double p, double T);
  /// Open ends to finite volumes linearised-implicit in the volume pressure (volume.hpp); applies
  /// to volumes added before and after the call. Default: explicit.
  void setImplicitVolumes(bool on);
  /// With implicit volumes: every one-cell FSM pipe with one end on a finite volume and an
  /// explicit boundary at the other end gets an implicit cell (volume.hpp "Implicit one-cell
  /// pipes"); applied when the network is first stepped. Default: off.
  void setImplicitOneCellPipes(bool on) { implicit_cells_ = on, validated_ = false; }
  /// Every pipe of >= 2 FSM cells takes its own CFL sub-steps within the network step, its end
  /// fluxes held (Pipe::setSubcycled; coupling_cfl > 0, 0: off); applied when the network is
  /// first stepped.
  void setSubcycledPipes(double coupling_cfl) { subcycle_cfl_ = coupling_cfl, validated_ = false; }
  /// Adds any boundary (constructed in place); returns it.
  template <class B, class... Args>
  B& add(Args&&... args) {
    auto b = std::make_unique<B>(std::forward<Args>(args)...);
    B& r = *b;
    boundaries_.push_back(std::move(b));
    return r;
  }
  ClosedEnd& close(Pipe& p, End e);
  OpenEnd& connect(Pipe& p, End e, Volume& v);

  Pipe& pipe(const std::string& name);
  Volume& volume(const std::string& name);
  const std::vector<std::unique_ptr<Pipe>>& pipes() const { return pipes_; }
  const std::vector<std::unique_ptr<Volume>>& volumes() const { return volumes_; }

  /// Advances all elements by `interval` [s] (many internal steps).
  void advance(double interval);
  /// Exactly one step of dt [s] (the caller has checked dt <= stableDt(); no re-evaluation).
  void step(double dt);
  double stableDt(std::string* limiter = nullptr) const;  // [s]
  double time() const { return t_; }
  long steps() const { return steps_; }
  double lastDt() const { return last_dt_; }
  void setDtFloor(double dt_floor_s) { dt_floor_ = dt_floor_s; }

  /// Mass [kg] and total energy [J] in pipes and finite volumes (reservoirs excluded).
  double totalMass() const;
  double totalEnergy() const;
  /// Net mass [kg] / energy [J] that entered all reservoirs since the start.
  double reservoirMassIn() const;
  double reservoirEnergyIn() const;

 private:
  void validate();
  void markImplicitCells() const;  // implicit cells, sub-cycling: flags on the pipes
  void stepOnce(double dt);  // fluxes at t_, then all elements advance by dt (t_ not updated)
  PerfectGas gas_;
  std::vector<std::unique_ptr<Pipe>> pipes_;
  std::vector<std::unique_ptr<Volume>> volumes_;
  std::vector<std::unique_ptr<Boundary>> boundaries_;
  double t_ = 0.0, last_dt_ = 0.0, dt_floor_ = 1e-9;
  long steps_ = 0;
  bool validated_ = false, implicit_volumes_ = false, implicit_cells_ = false;
  double subcycle_cfl_ = 0.0;
};

}  // namespace hbt::gasdyn
