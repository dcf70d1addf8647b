#include "example_participant/node/trip_computer_participant.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/ProbeSignal.h>

#include "cosim/param_loader.hpp"

namespace hbt::example {

void TripComputerParticipant::configure() {
  TripComputerParams p;
  ParamSet ps;
  p.declare(ps);
  cosim::applyRosParams(pnh_, ps, configFile());
  model_ = std::make_unique<TripComputer>(p);
  engine_ = &addInputFrom<hybrid_bus_twin::EngineState>("engine", "state");
  vehicle_ = &addInputFrom<hybrid_bus_twin::VehicleState>("vehicle", "state");
  display_pub_ = addOwnOutput<hybrid_bus_twin::ProbeSignal>("display");
  readWarningThresholds(warnings_);
  long_idle_ = &addWarning("long_idle", warnings_.idle_s);
}

void TripComputerParticipant::step(const ros::Time& t, double dt_s) {
  const auto& e = engine_->at(t);
  const auto& v = vehicle_->at(t);
  TripInputs in;
  in.fuel_mass_kg = e.fuel_mass_kg;
  in.engine_speed_rad_s = e.engine_speed_rad_s;
  in.distance_m = v.distance_m;
  in.vehicle_speed_m_s = v.speed_m_s;
  model_->update(dt_s, in);
}

void TripComputerParticipant::checkWarnings(cosim::core::Nanos t) {
  const TripOutputs& o = model_->outputs();
  if (long_idle_->update(t, o.standstill_idle_s > 0.0))
    long_idle_->setMessage(cosim::core::formatText("engine idling at standstill for more than %.0f s", warnings_.idle_s));
}

void TripComputerParticipant::publishOutputs(const ros::Time& t) {
  const TripOutputs& o = model_->outputs();
  auto m = boost::make_shared<hybrid_bus_twin::ProbeSignal>();
  m->header.stamp = t;
  m->values = {o.fuel_l, o.distance_km, o.consumption_l_100km, o.shown ? 1.0 : 0.0, o.standstill_idle_s};
  display_pub_.publish(m);
}

}  // namespace hbt::example
