// Recorder participant: writes every output topic of the run to a rosbag, in lock-step.
//
// At each of its steps t it waits until each recorded topic has its message held at t (stamped
// floor(t / P) * P for a producer of macro step P: the Jacobi rule of participant.hpp, whatever the
// groups) and writes them in a fixed (sorted) topic order with bag time = t, so two runs of one
// scenario give identical bag contents. It is an observer: stepped in the last group, at the
// record period when that is a multiple of the base step (else at every base step). At FINISH it waits for the final outputs (stamped t_end), writes them
// and closes the bag; at ABORT it writes what is complete and closes the bag, which stays
// readable. Topics are recorded type-erased (topic_tools::ShapeShifter), so the recorder does not
// depend on the message types.
//
// Parameters (private): bag_file [path], topics [list of topic names; absent = every output
// topic the participants announced: learnt from the stepper's SYNC table, so a new participant
// is recorded without touching the launch file], record_period_s [s]
// (0 = every macro step; otherwise the states stamped at multiples of the period are written,
// always including t = 0 and the final state).
#pragma once
#include <rosbag/bag.h>
#include <topic_tools/shape_shifter.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cosim/participant.hpp"

namespace hbt::cosim {

class Recorder : public Participant {
 public:
  Recorder(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override {}
  void step(const ros::Time& t, double dt_s) override;
  bool readyToClose(const ros::Time& t_end) const override;
  void topicsAnnounced(const std::vector<std::string>& topics) override;
  void close(const ros::Time& t_end, bool aborted) override;

 private:
  class RawInput;
  void writeAt(const ros::Time& t);
  void addTopic(const std::string& topic);
  std::unique_ptr<rosbag::Bag> bag_;
  std::vector<RawInput*> topics_;  // sorted by name; owned by the participant base
  ros::Time last_written_;
  uint64_t period_ns_ = 0;
  bool wrote_any_ = false;
  bool record_all_ = false;  // no `topics` parameter: record every announced output
};

}  // namespace hbt::cosim
