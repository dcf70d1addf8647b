// FmuArchive: each rejection class of an FMU file (not a file, not a zip, no or malformed
// modelDescription.xml, FMI 1.0 / 3.0, no linux64 binary) with a message naming the file and
// the fault; and the extraction into a caller-given directory, byte-identical to the staged
// files the archive was zipped from and the same on a second extraction.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "fmi/fmu_archive.hpp"
#include "fmi/fmu_error.hpp"
#include "fmi_test_util.hpp"

namespace hbt::fmi {
namespace {

namespace fs = std::filesystem;
using testing::expectThrowWith;
using testing::testFmu;

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(FmuArchive, RejectsWhatIsNotAnFmuFile) {
  expectThrowWith<FmuError>([] { FmuArchive a("/nonexistent/x.fmu"); }, {"/nonexistent/x.fmu", "no such file"});
  const std::string dir = HBT_TEST_FMU_DIR;
  expectThrowWith<FmuError>([&] { FmuArchive a(dir); }, {dir, "not a regular file"});
  const std::string text = std::string(HBT_TEST_FMU_SOURCE_DIR) + "/resources/thermal_mass.txt";
  expectThrowWith<FmuError>([&] { FmuArchive a(text); }, {text, "not a zip archive"});
}

TEST(FmuArchive, RejectsBadModelDescriptions) {
  const std::string none = testFmu("no_model_description");
  expectThrowWith<FmuError>([&] { FmuArchive a(none); }, {none, "no modelDescription.xml"});
  const std::string bad = testFmu("malformed_xml");
  expectThrowWith<FmuError>([&] { FmuArchive a(bad); }, {bad, "modelDescription.xml", "malformed XML"});
  const std::string v1 = testFmu("fmi_1_0");
  expectThrowWith<FmuError>([&] { FmuArchive a(v1); }, {v1, "fmiVersion \"1.0\""});
  const std::string v3 = testFmu("fmi_3_0");
  expectThrowWith<FmuError>([&] { FmuArchive a(v3); }, {v3, "fmiVersion \"3.0\""});
}

TEST(FmuArchive, RejectsMissingBinaryAndInterface) {
  const std::string file = testFmu("no_linux64_binary");
  const FmuArchive a(file);  // the description alone is fine
  expectThrowWith<FmuError>([&] { a.binaryEntry(InterfaceType::kCoSimulation); },
                            {file, "no linux64 binary", "binaries/linux64/thermal_mass.so"});
  const FmuArchive good(testFmu("thermal_mass"));
  EXPECT_EQ(good.binaryEntry(InterfaceType::kCoSimulation), "binaries/linux64/thermal_mass.so");
  expectThrowWith<FmuError>([&] { good.binaryEntry(InterfaceType::kModelExchange); },
                            {"thermal_mass.fmu", "no <ModelExchange>"});
}

TEST(FmuArchive, ExtractsEveryEntryByteForByteAndDeterministically) {
  const FmuArchive a(testFmu("thermal_mass"));
  const std::string dir1 = testing::freshDir("1"), dir2 = testing::freshDir("2");
  a.extractTo(dir1);
  a.extractTo(dir2);
  const fs::path staged = fs::path(HBT_TEST_FMU_DIR) / "thermal_mass";  // what zip read
  int files = 0;
  for (const std::string& e : a.entries()) {
    if (e.back() == '/') continue;
    ++files;
    const std::string original = slurp(staged / e);
    EXPECT_FALSE(original.empty()) << e;
    EXPECT_EQ(slurp(fs::path(dir1) / e), original) << e;
    EXPECT_EQ(slurp(fs::path(dir2) / e), original) << e;
  }
  EXPECT_EQ(files, 3);  // modelDescription.xml, the binary, the resources file
  EXPECT_TRUE(fs::is_regular_file(fs::path(dir1) / "resources/thermal_mass.txt"));
}

}  // namespace
}  // namespace hbt::fmi
