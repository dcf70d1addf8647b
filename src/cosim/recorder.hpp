// Recorder participant: writes every output topic of the run to a rosbag, in lock-step.
//
// At each of its steps t it waits until each recorded topic has its message held at t (stamped
// floor(t / P) * P for a producer of macro step P: the Jacobi rule of participant.hpp, whatever the
// groups) and writes them in a fixed (sorted) topic order with bag time = t, so two runs of one
// scenario give identical bag contents. It is an observer: stepped in the last group, at the
// record period when that is a multiple of the base step (else at every base step). At FINISH it waits for the final outputs (stamped t_end), writes them
// and closes the bag; at ABORT it writes what is complete and closes the bag, which stays
// readable. The twin's own message types are subscribed typed (no serialisation intra-process,
// recorded_topic.hpp); any other type is recorded type-erased (topic_tools::ShapeShifter).
//
// Parameters (private): bag_file [path], topics [list of topic names; absent = every output
// topic the participants announced: learnt from the stepper's SYNC table, so a new participant
// is recorded without touching the launch file; either way subscribed at the first SYNC, a
// participant's output on its observer lane (output.hpp: only the stamps the recorder reads
// reach it)], record_period_s [s]
// (0 = every macro step; otherwise the states stamped at multiples of the period are written,
// always including t = 0 and the final state).
//
// run.bag is written by an AsyncBagWriter (bag_writer.hpp): the lock-step thread only queues a
// copy of each message held at the record stamp; serialisation and the file run on its thread.
// Its queue's high-water marks are the recorder's diagnostic key/values (bag_queue_high_water_kib,
// bag_queue_high_water_messages, bag_queue_producer_waits).
//
// Diagnostics (optional, private diagnostics_bag_file [path]): every DiagnosticArray on
// /diagnostics (cosim/participant.hpp) is written as it arrives to that second bag (bag time =
// header.stamp), never to bag_file: compute times differ from run to run, run.bag must not. At
// FINISH the recorder closes only once it holds the final status (key final = true) of every
// participant named in diagnostics_from [list; absent = every participant of the SYNC table] --
// each carries the warnings of the whole run --
// or after diagnostics_wait_s [s wall, default 2] (a warning names the missing ones); its own
// final status it writes itself. At ABORT it closes at once with what it has.
//
// A stepper that fell silent while stepping (died or hung: core/protocol.hpp): the recorder
// closes its bags as at an ABORT, writes the run's status (private status_file [path], the
// stepper's; only if the stepper has not written it) naming the stepper and the time, then ends
// the stepper's process (SIGKILL, when it runs on this host: kStepperProcessParam) so that
// roslaunch stops the run (the stepper is a required node).
#pragma once
#include <diagnostic_msgs/DiagnosticArray.h>
#include <topic_tools/shape_shifter.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "cosim/participant.hpp"
#include "cosim/recorded_topic.hpp"

namespace hbt::cosim {

class Recorder : public Participant {
 public:
  /// [s] As a nodelet its thread (`cosim/thread: recorder`) runs what arrived, then sleeps this
  /// long, instead of being woken for each of the ~730,000 messages of a mission (one per topic
  /// and record period): the futex wake-ups cost the publishing threads 1-2 s of CPU in the map
  /// baseline. Half a millisecond is below the grant window (2 x 50 base steps, > 1 ms of wall
  /// time at the fastest), so the recorder's lag holds nobody up.
  static constexpr double kThreadPoll_s = 0.5e-3;
  Recorder(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override {}
  void step(const ros::Time& t, double dt_s) override;
  bool readyToClose(const ros::Time& t_end) const override;
  void topicsAnnounced(const std::vector<std::string>& topics,
                       const std::vector<std::string>& participants) override;
  void close(const ros::Time& t_end, bool aborted) override;
  void stepperLost(const ros::Time& t, const std::string& message) override;
  /// run.bag's writer queue: its high-water marks (bytes, messages) and the producer's waits.
  void diagnosticValues(core::Nanos t, std::vector<core::KeyValue>& kv) override;

 private:
  void writeAt(const ros::Time& t);
  void addTopic(const std::string& topic, const std::string& datatype, const std::string& subscribe_to);
  void onDiagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& m);
  void writeDiagnostics(const diagnostic_msgs::DiagnosticArray& m);
  bool diagnosticsComplete() const;
  /// Ends the stepper's process if it runs on this host; says what it did.
  std::string endStepper() const;
  std::unique_ptr<AsyncBagWriter> bag_;   // run.bag, written on its own thread
  std::string bag_file_;     // its path
  std::string status_file_;  // the run's status.json (written here only if the stepper fell silent)
  std::unique_ptr<BagFileWriter> diag_bag_;  // written on the recorder's thread (few messages)
  std::string diag_file_;   // its file name (messages)
  std::string diag_error_;  // a failed write of it: stops the run at the next step
  ros::Subscriber diag_sub_;
  ros::WallTimer diag_timer_;  // re-checks readyToClose while waiting for final statuses
  std::set<std::string> diag_waiting_;  // participants whose final status has not arrived
  bool diag_from_param_ = false;        // diagnostics_from given; else learnt from the SYNC table
  bool diag_from_table_ = false;
  double diag_wait_s_ = 2.0;
  mutable double diag_wait_since_ = -1.0;  // wall time [s] the close started waiting (-1: not)
  std::vector<std::unique_ptr<RecordedTopic>> topics_;  // sorted by name; inputs owned by the base
  ros::Time last_written_;
  uint64_t period_ns_ = 0;
  bool wrote_any_ = false;
  bool record_all_ = false;  // no `topics` parameter: record every announced output
  std::vector<std::string> listed_;  // the `topics` parameter (subscribed at the first SYNC)
};

}  // namespace hbt::cosim
