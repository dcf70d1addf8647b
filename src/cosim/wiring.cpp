#include "cosim/wiring.hpp"

#include "common/errors.hpp"

namespace hbt::cosim {
namespace {

/// The declarations file of `participant` as the launch recorded it (for messages).
std::string declarationsFile(const ros::NodeHandle& nh, const std::string& participant) {
  std::string file;
  if (!nh.getParam(std::string(kWiringNamespace) + "/" + participant + "/file", file))
    file = "src/" + participant + "/node/topics.yaml";
  return file;
}

/// Throws unless `participant`'s topics.yaml declares `key` as `datatype`; `use` says who does
/// what with the topic ("engine publishes", "vehicle reads").
void checkDeclared(const ros::NodeHandle& nh, const std::string& participant, const std::string& key,
                   const std::string& datatype, const std::string& use) {
  const std::string file = declarationsFile(nh, participant);
  const std::string topic = " " + topicName(participant, key);
  std::string declared;
  if (!nh.getParam(std::string(kWiringNamespace) + "/" + participant + "/publishes/" + key, declared))
    throw InputError(file, "publishes/" + key, "not declared, but " + use + topic + " (" + datatype + ")");
  if (declared != datatype)
    throw InputError(file, "publishes/" + key, "declares " + declared + ", but " + use + topic + " as " + datatype);
}

}  // namespace

std::string topicName(const std::string& participant, const std::string& key) {
  return "/" + participant + "/" + key;
}

bool inScenario(const ros::NodeHandle& nh, const std::string& participant) {
  bool registered = false;
  return nh.getParam(std::string(kParticipantRegistry) + "/" + participant, registered) && registered;
}

std::string inputTopic(const ros::NodeHandle& nh, const std::string& producer, const std::string& key,
                       const std::string& datatype, const std::string& reader) {
  if (!inScenario(nh, producer))
    throw InputError(declarationsFile(nh, producer), "publishes/" + key,
                     reader + " reads " + topicName(producer, key) + ", but " + producer +
                         " does not run in this scenario (launch/include/urban.launch)");
  checkDeclared(nh, producer, key, datatype, reader + " reads");
  return topicName(producer, key);
}

std::string outputTopic(const ros::NodeHandle& nh, const std::string& participant, const std::string& key,
                        const std::string& datatype) {
  checkDeclared(nh, participant, key, datatype, participant + " publishes");
  return topicName(participant, key);
}

}  // namespace hbt::cosim
