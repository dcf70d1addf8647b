#include "gasdyn/network.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/errors.hpp"

namespace hbt::gasdyn {

Network::Network(PerfectGas gas) : gas_(gas) {
  if (!(gas.gamma > 1.0)) throw InputError("network", "gamma", "must be > 1");
  if (!(gas.R > 0.0)) throw InputError("network", "R", "must be > 0");
}

Pipe& Network::addPipe(PipeConfig cfg) {
  for (const auto& p : pipes_)
    if (p->name() == cfg.name) throw InputError("network", "pipe " + cfg.name, "duplicate name");
  pipes_.push_back(std::make_unique<Pipe>(gas_, std::move(cfg)));
  validated_ = false;
  return *pipes_.back();
}

Volume& Network::addVolume(std::string name, double volume_m3, double p, double T) {
  volumes_.push_back(std::make_unique<Volume>(gas_, std::move(name), volume_m3, p, T));
  volumes_.back()->setImplicit(implicit_volumes_);
  return *volumes_.back();
}

Volume& Network::addReservoir(std::string name, double p, double T) {
  volumes_.push_back(std::make_unique<Volume>(Volume::reservoir(gas_, std::move(name), p, T)));
  return *volumes_.back();
}

void Network::setImplicitVolumes(bool on) {
  implicit_volumes_ = on;
  validated_ = false;
  for (auto& v : volumes_) v->setImplicit(on);
}

ClosedEnd& Network::close(Pipe& p, End e) {
  return add<ClosedEnd>(p.name() + (e == End::Left ? ".left" : ".right") + ".closed",
                        PipeEnd{&p, e});
}

OpenEnd& Network::connect(Pipe& p, End e, Volume& v) {
  return add<OpenEnd>(p.name() + (e == End::Left ? ".left" : ".right") + "->" + v.name(),
                      PipeEnd{&p, e}, v);
}

Pipe& Network::pipe(const std::string& name) {
  for (auto& p : pipes_)
    if (p->name() == name) return *p;
  throw InputError("network", "pipe " + name, "no such pipe");
}

Volume& Network::volume(const std::string& name) {
  for (auto& v : volumes_)
    if (v->name() == name) return *v;
  throw InputError("network", "volume " + name, "no such volume");
}

void Network::validate() {
  for (const auto& p : pipes_) {
    if (!p->attached(End::Left))
      throw InputError("network", "pipe " + p->name(), "left end has no boundary");
    if (!p->attached(End::Right))
      throw InputError("network", "pipe " + p->name(), "right end has no boundary");
  }
  markImplicitCells();
  validated_ = true;
}

// One-cell FSM pipes with exactly one end on an implicit volume port (the other end's flux then
// comes from an explicit boundary before the volume closes its ports).
void Network::markImplicitCells() const {
  for (auto& p : pipes_) {
    int ports = 0;
    for (const auto& v : volumes_)
      if (v->implicit()) ports += v->portsOf(*p);
    const bool fsm = p->config().solver == SolverKind::FSM;
    p->setImplicitCell(implicit_cells_ && ports == 1 && p->cells() == 1 && fsm);
    p->setSubcycled(fsm && p->cells() >= 2 ? subcycle_cfl_ : 0.0);
  }
}

double Network::stableDt(std::string* limiter) const {
  if (!validated_) markImplicitCells();  // the step as it will be taken, also before the first
  double dt = std::numeric_limits<double>::infinity();
  const std::string* who = nullptr;
  for (const auto& p : pipes_) {
    const double d = p->maxDt();
    if (d < dt) dt = d, who = &p->name();
  }
  for (const auto& v : volumes_) {
    const double d = v->maxDt();
    if (d < dt) dt = d, who = &v->name();
  }
  for (const auto& b : boundaries_) {
    const double d = b->maxDt();
    if (d < dt) dt = d, who = &b->name();
  }
  if (limiter && who) *limiter = *who;
  return dt;
}

void Network::advance(double interval) {
  if (!validated_) validate();
  if (!(interval >= 0.0)) throw InputError("network", "interval", "must be >= 0 s");
  const double t_end = t_ + interval;
  while (t_ < t_end) {
    const double dtmax = stableDt();
    if (!(dtmax >= dt_floor_)) {
      std::string who;
      stableDt(&who);
      throw ModelDivergence(who, "time step",
                            "stable step " + std::to_string(dtmax) + " s below the floor " +
                                std::to_string(dt_floor_) + " s at t = " + std::to_string(t_));
    }
    const double remaining = t_end - t_;
    const double nsteps = std::max(1.0, std::ceil(remaining / dtmax * (1.0 - 1e-12)));
    const double dt = remaining / nsteps;
    stepOnce(dt);
    t_ = nsteps <= 1.0 ? t_end : t_ + dt;
  }
}

void Network::step(double dt) {
  if (!validated_) validate();
  if (!(dt >= 0.0)) throw InputError("network", "dt", "must be >= 0 s");
  stepOnce(dt);
  t_ += dt;
}

void Network::stepOnce(double dt) {
  for (auto& b : boundaries_) b->computeFluxes(t_);
  for (auto& v : volumes_) v->closePorts(dt);  // port fluxes -> pipe ends (implicit: solved dp)
  for (auto& p : pipes_) p->step(dt);
  for (auto& v : volumes_) v->advance(dt);
  for (auto& b : boundaries_) b->afterStep(dt);
  last_dt_ = dt;
  ++steps_;
}

double Network::totalMass() const {
  double s = 0.0;
  for (const auto& p : pipes_) s += p->mass();
  for (const auto& v : volumes_) s += v->mass();
  return s;
}

double Network::totalEnergy() const {
  double s = 0.0;
  for (const auto& p : pipes_) s += p->energy();
  for (const auto& v : volumes_) s += v->energy();
  return s;
}

double Network::reservoirMassIn() const {
  double s = 0.0;
  for (const auto& v : volumes_)
    if (v->isReservoir()) s += v->cumulativeMassIn();
  return s;
}

double Network::reservoirEnergyIn() const {
  double s = 0.0;
  for (const auto& v : volumes_)
    if (v->isReservoir()) s += v->cumulativeEnergyIn();
  return s;
}

}  // namespace hbt::gasdyn
