// Fmi2Library: the binary of the test FMU resolves every Co-Simulation function; the variant
// compiled without fmi2DoStep is rejected naming the missing function; a Model Exchange load
// of a Co-Simulation-only binary names the first Model Exchange function it lacks.
#include <gtest/gtest.h>

#include <filesystem>

#include "fmi/fmi2_library.hpp"
#include "fmi/fmu_error.hpp"
#include "fmi/loaded_fmu.hpp"
#include "fmi_test_util.hpp"

namespace hbt::fmi {
namespace {

using testing::expectThrowWith;
using testing::testFmu;

TEST(Fmi2Library, ResolvesTheCoSimulationFunctions) {
  auto fmu = LoadedFmu::load(testFmu("thermal_mass"), testing::freshDir("x"), InterfaceType::kCoSimulation);
  const Fmi2Functions& f = fmu->functions();
  EXPECT_NE(f.instantiate, nullptr);
  EXPECT_NE(f.doStep, nullptr);
  EXPECT_NE(f.getBooleanStatus, nullptr);
  EXPECT_EQ(f.getFMUstate, nullptr);  // optional, not exported by the test FMU
  EXPECT_STREQ(f.getTypesPlatform(), "default");
  EXPECT_STREQ(f.getVersion(), "2.0");
}

TEST(Fmi2Library, MissingFunctionNamed) {
  const std::string file = testFmu("missing_do_step");
  expectThrowWith<FmuError>(
      [&] { LoadedFmu::load(file, testing::freshDir("x"), InterfaceType::kCoSimulation); },
      {file, "does not export fmi2DoStep", "CoSimulation"});
}

TEST(Fmi2Library, ModelExchangeFunctionsRequiredForModelExchange) {
  const std::string dir = testing::freshDir("x");
  const FmuArchive a(testFmu("thermal_mass"));
  a.extractTo(dir);
  const std::string so = dir + "/binaries/linux64/thermal_mass.so";
  expectThrowWith<FmuError>([&] { Fmi2Library lib(so, InterfaceType::kModelExchange, a.file()); },
                            {a.file(), "does not export fmi2EnterEventMode", "ModelExchange"});
}

TEST(Fmi2Library, UnloadableBinaryNamed) {
  const std::string not_elf = std::string(HBT_TEST_FMU_SOURCE_DIR) + "/resources/thermal_mass.txt";
  expectThrowWith<FmuError>([&] { Fmi2Library lib(not_elf, InterfaceType::kCoSimulation, "f.fmu"); },
                            {"f.fmu", "cannot load binary", "thermal_mass.txt"});
}

}  // namespace
}  // namespace hbt::fmi
