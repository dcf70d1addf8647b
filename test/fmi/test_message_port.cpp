// PortFactory (src/fmi/node/message_port.hpp), without a ROS master: every message type of the
// package (one per msg/*.msg file) is known, and its layout -- the field names and types parsed
// from the type's generated definition text, checked once against the storage the generated
// serialiser visits (field count and C++ type of every field) -- lists exactly the fields of the
// .msg file, read here independently, in order.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "fmi/node/message_port.hpp"

namespace hbt::fmi {
namespace {

namespace fs = std::filesystem;

/// The field names of a .msg file: "type name" lines, without the header and constants.
std::vector<std::string> fieldsOfFile(const fs::path& p) {
  std::ifstream f(p);
  std::vector<std::string> out;
  std::string line;
  while (std::getline(f, line)) {
    line = line.substr(0, line.find('#'));
    std::istringstream w(line);
    std::string type, name;
    if (!(w >> type >> name) || line.find('=') != std::string::npos || type == "std_msgs/Header") continue;
    out.push_back(name);
  }
  return out;
}

TEST(MessagePort, EveryMessageOfThePackageIsKnownWithItsFieldsInOrder) {
  int types = 0;
  for (const auto& e : fs::directory_iterator(HBT_MSG_DIR)) {
    if (e.path().extension() != ".msg") continue;
    const std::string datatype = "hybrid_bus_twin/" + e.path().stem().string();
    ASSERT_TRUE(PortFactory::known(datatype)) << datatype;
    const MessageLayout l = PortFactory::layoutOf(datatype, "test", "key");  // storage checked here
    std::vector<std::string> names;
    for (const auto& f : l.fields()) names.push_back(f.name);
    EXPECT_EQ(names, fieldsOfFile(e.path())) << datatype;
    ++types;
  }
  EXPECT_GE(types, 16);
}

TEST(MessagePort, AnUnknownTypeNamesFileAndKey) {
  EXPECT_FALSE(PortFactory::known("std_msgs/Float64"));
  try {
    PortFactory::layoutOf("std_msgs/Float64", "src/x/node/topics.yaml", "publishes/state");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("src/x/node/topics.yaml: key 'publishes/state': std_msgs/Float64 is not a message type"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace hbt::fmi
