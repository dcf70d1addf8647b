#include "cosim/probe_participant.hpp"

#include <boost/make_shared.hpp>

#include "common/errors.hpp"

namespace hbt::cosim {

void ProbeParticipant::configure() {
  std::vector<std::string> inputs;
  std::string output;
  if (pnh_.hasParam("inputs") && !pnh_.getParam("inputs", inputs))
    throw InputError(configFile(), "inputs", "must be a list of topic names");
  if (!pnh_.getParam("output", output) || output.empty())
    throw InputError(configFile(), "output", "missing: the topic this probe publishes");
  for (const auto& topic : inputs) inputs_.push_back(&addInput<hybrid_bus_twin::ProbeSignal>(topic));
  pub_ = addOutput<hybrid_bus_twin::ProbeSignal>(output);
}

void ProbeParticipant::step(const ros::Time& t, double /*dt_s*/) {
  input_sum_ = 0.0;
  for (auto* in : inputs_) input_sum_ += in->at(t).values.at(0);
}

void ProbeParticipant::publishOutputs(const ros::Time& t) {
  auto s = boost::make_shared<hybrid_bus_twin::ProbeSignal>();
  s->header.stamp = t;
  s->values = {t.toSec(), input_sum_};
  pub_.publish(s);
}

}  // namespace hbt::cosim
