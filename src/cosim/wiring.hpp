// The wiring of the twin: which participants run in a scenario and what each publishes.
//
// One definition, read by the C++ nodes (here), the launch files and the Python tools
// (python/twin_tools/wiring.py):
//   - the participant list and scenario membership: one include of launch/include/participant.launch
//     per participant in launch/include/urban.launch (its `if` = the scenarios it belongs to); the
//     include registers /twin/participants/<name> (the stepper waits for every name there);
//   - its topics: src/<name>/node/topics.yaml (`publishes: {key: package/MessageType}`), loaded by
//     the same include into /twin/wiring/<name>/; the topic of key k is /<name>/<k>.
// A producer publishes only what it declares, with the declared type; a consumer reads only what a
// participant of the scenario declares. Anything else is an InputError naming topics.yaml and the
// key, raised in configure(), before the simulation starts.
#pragma once
#include <ros/ros.h>

#include <string>

namespace hbt::cosim {

/// Parameter namespace of the scenario's participant list: /twin/participants/<name> = true.
inline constexpr const char* kParticipantRegistry = "/twin/participants";
/// Parameter namespace of the participants' topic declarations: /twin/wiring/<name>/publishes/<key>.
inline constexpr const char* kWiringNamespace = "/twin/wiring";

/// The topic a participant publishes under `key`: "/<participant>/<key>".
std::string topicName(const std::string& participant, const std::string& key);

/// True when `participant` runs in this scenario (registered under kParticipantRegistry).
bool inScenario(const ros::NodeHandle& nh, const std::string& participant);

/// The topic `reader` reads from `producer`: checks that `producer` runs in this scenario and
/// declares `key` with message type `datatype` ("hybrid_bus_twin/EngineState"). Throws
/// hbt::InputError naming the producer's topics.yaml and the key.
std::string inputTopic(const ros::NodeHandle& nh, const std::string& producer, const std::string& key,
                       const std::string& datatype, const std::string& reader);

/// The topic `participant` publishes under `key`: checks that its topics.yaml declares `key` with
/// message type `datatype`. Throws hbt::InputError naming that file and the key.
std::string outputTopic(const ros::NodeHandle& nh, const std::string& participant, const std::string& key,
                        const std::string& datatype);

}  // namespace hbt::cosim
