// Probe participant: a lock-step participant without a model, for measuring the protocol alone
// (scripts/twin bench cosim: base steps per second for N participants, nodes vs nodelets, one
// rate vs multi-rate, Jacobi vs ordered groups).
//
// Parameters (private): inputs [list of ProbeSignal topics it reads, may be empty],
// output [topic it publishes], cosim/macro_step_s [s] (optional, as every participant).
// Output: ProbeSignal values = [t_out_s, sum of the inputs' values[0]] stamped t_out = t + P: the
// second value makes the step depend on every input, so nothing is read without being used; by
// the held-value rule (participant.hpp) an input from a producer of macro step P_p in the same
// or a later group reads values[0] = floor(t / P_p) * P_p, from an earlier group that + P_p.
#pragma once
#include <hybrid_bus_twin/ProbeSignal.h>

#include <vector>

#include "cosim/participant.hpp"

namespace hbt::cosim {

class ProbeParticipant : public Participant {
 public:
  ProbeParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;

 private:
  std::vector<Input<hybrid_bus_twin::ProbeSignal>*> inputs_;
  Output pub_;
  double input_sum_ = 0.0;  // sum of the inputs' values[0] read at the last step
};

}  // namespace hbt::cosim
