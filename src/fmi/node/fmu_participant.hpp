// The FMU participant: a participant of the lock-step served by an FMI 2.0 FMU (src/fmi, README
// "The FMU participant") instead of a model of ours -- in place of a native participant (same
// name, topics, macro step and Gauss-Seidel group: launch `<participant>_fmu:=PATH.fmu`) or as an
// extra one (its own launch include with a topics.yaml). A thin node: parameters and messages in,
// the ROS-free library hbt_fmi does the rest.
//
// Parameters (private): fmu_file [path], fmu_map_file [path, "" = none], fmu_map/ (the mapping
// file's keys, fmu_mapping.hpp), cosim/macro_step_s and cosim/thread as every participant (the
// YAML of the participant it replaces). Reads /scenario/out_dir (the FMU is extracted into
// <out>/fmu/<name>/), /scenario/<name> (parameters scenario.<name>), /stepper/until_s (to name
// what ends the run), the wiring (/twin/wiring/).
//
// configure(), before step 0: the FMU loaded and checked, the mapping resolved, the instance
// made (CoSimulation, or ModelExchange integrated by CVODE), parameters set in initialisation
// mode, the resolved mapping written to <out>/resolved_config/<name>_fmu.csv. Any rejection
// is the run's error naming the FMU file or the mapping file and key. At SYNC, still before
// step 0: the FMU's stopTime against the run's end (until, else the mission's end).
// step(t, P): the held inputs through their unit conversions into the FMU, doStep(P), the
// outputs back (FmuExchange: one message lookup per input topic, one set and one get call per
// variable type); /diagnostics has fmu_steps, fmu_do_step_s (wall time inside doStep: the FMU's
// own compute; the step's compute time the lock-step counts minus this is the participant's
// overhead) and the medians per step of both, fmu_do_step_us_median and fmu_overhead_us_median
// (step_timing.hpp: robust to preemption on a shared machine; twin bench fmu); an FMU failure (status other than OK/Warning, NaN output, a step past its stop
// time) throws hbt::ModelDivergence naming FMU, call or variable and time: the run stops, the
// bag is closed (the participant's usual failure path). A hung doStep is the stepper's step
// timeout (docs/protocol.md).
// Warnings: each Boolean output `<name>.warning.<w>` of the FMU is this participant's warning <w>
// (fmu_warnings.hpp), raised while the FMU holds it true, judged after every step and at t_0.
#pragma once
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cosim/participant.hpp"
#include "fmi/cs_instance.hpp"
#include "fmi/fmu_mapping.hpp"
#include "fmi/fmu_warnings.hpp"
#include "fmi/me_instance.hpp"
#include "fmi/node/fmu_exchange.hpp"
#include "fmi/node/message_port.hpp"
#include "fmi/step_timing.hpp"

namespace hbt::fmi {

class FmuParticipant : public cosim::Participant {
 public:
  FmuParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

  /// Typed ports for PortFactory (message_port.cpp).
  template <class M>
  cosim::Output typedOutput(const std::string& topic) {
    return addOutput<M>(topic);
  }
  template <class M>
  cosim::Input<M>& typedInput(const std::string& topic) {
    return addInput<M>(topic);
  }

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;
  void checkWarnings(cosim::core::Nanos t) override;
  /// The end of the mission as the participant it replaces announces it: an output field
  /// `mission_finished` (the vehicle's) that the FMU sets true; never for any other FMU.
  bool finished() const override { return mission_finished_; }
  /// The FMU's DefaultExperiment stopTime before the run's end (until, or the mission's end when
  /// until is 0: the stepper's SYNC) is an FmuError naming the FMU: the run ends before step 0.
  void checkRunEnd(double end_s) override;

 private:
  MappingSpec readSpec() const;
  MappingContext readContext() const;
  void loadFmu(const std::string& out_dir);
  void instantiate();
  void makePorts();
  void writeResolved(const std::string& out_dir) const;
  void readOutputs();
  void declareWarnings();
  void onLog(const std::string& instance, fmi2Status status, const std::string& category, const std::string& message);

  std::string fmu_file_;
  std::shared_ptr<const LoadedFmu> fmu_;
  ResolvedMapping map_;
  std::unique_ptr<Fmi2Instance> inst_;
  CsInstance* cs_ = nullptr;  // inst_ as its interface type
  MeInstance* me_ = nullptr;
  std::vector<VariableRef> in_refs_, out_refs_;             // per map_.inputs / map_.outputs
  std::map<std::string, std::unique_ptr<OutPort>> out_ports_;  // key -> port
  std::map<std::string, std::unique_ptr<InPort>> in_ports_;    // "/producer/key" -> port
  std::vector<InPort*> in_port_of_;    // per map_.inputs
  std::vector<OutPort*> out_port_of_;  // per map_.outputs
  std::unique_ptr<FmuExchange> exchange_;  // the step's exchange, planned in configure()
  int mission_finished_output_ = -1;  // index in map_.outputs of a field mission_finished, -1: none
  bool mission_finished_ = false;
  long log_warnings_ = 0, log_errors_ = 0;
  // wall time [s, steady clock] of each step inside doStep (the FMU's own compute) and outside
  // it (the overhead: exchange of inputs and outputs); /diagnostics
  StepTiming do_step_timing_, overhead_timing_;
  std::string last_log_;
  std::string step_log_;  // the FMU's last log message since the last checkWarnings ("" = none)
  // the FMU's warning outputs (fmu_warnings.hpp), their refs and the participant's warnings
  struct FmuWarning {
    WarningOutput output;
    VariableRef ref;
    cosim::core::Warning* warning = nullptr;
  };
  std::vector<FmuWarning> warnings_;
};

}  // namespace hbt::fmi
