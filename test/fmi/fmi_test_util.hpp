// Helpers of the FMI tests: the test FMUs' paths, a fresh extraction directory, and the check
// that f() throws an exception of type E whose message contains every given fragment.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

#include <unistd.h>

namespace hbt::fmi::testing {

/// <build>/test_fmus/<name>.fmu (test/fmi/fmus/CMakeLists.txt)
inline std::string testFmu(const std::string& name) {
  return std::string(HBT_TEST_FMU_DIR) + "/" + name + ".fmu";
}

/// The directories freshDir() made in this process, removed after the last test.
class FreshDirs : public ::testing::Environment {
 public:
  static std::vector<std::filesystem::path>& made() {
    static std::vector<std::filesystem::path> dirs;
    return dirs;
  }
  void TearDown() override {
    for (const auto& d : made()) std::filesystem::remove_all(d);
  }
};
inline ::testing::Environment* const kFreshDirs = ::testing::AddGlobalTestEnvironment(new FreshDirs);

/// An empty directory below the system's temporary directory, unique per test and process.
inline std::string freshDir(const std::string& tag) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
      ("hbt_fmi_" + std::to_string(::getpid()) + "_" + info->name() + "_" + tag);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  FreshDirs::made().push_back(dir);
  return dir.string();
}

template <class E, class F>
std::string expectThrowWith(F&& f, std::initializer_list<std::string> fragments) {
  try {
    f();
  } catch (const E& e) {
    const std::string what = e.what();
    for (const std::string& frag : fragments) {
      EXPECT_NE(what.find(frag), std::string::npos) << "'" << frag << "' not in: " << what;
    }
    return what;
  }
  ADD_FAILURE() << "no exception of the expected type";
  return "";
}

}  // namespace hbt::fmi::testing
