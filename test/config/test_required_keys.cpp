// Required keys, generated over the shipped configuration: for every YAML file the nodes read
// (each participant's with its warning thresholds, the auxiliary and gear loss sets, the mission, the diagnostics, the 1D
// engine and its sub-files), the file as shipped holds every key its model declares (but the
// intended defaults and the keys another file sets), and removing any one of them is an
// InputError naming that file and that key -- never the model's built-in value, silently. The
// classes are tested, not keys by hand: the list of keys comes from the models' declarations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "aftertreatment/aftertreatment_warnings.hpp"
#include "aftertreatment/ats_params.hpp"
#include "battery/battery_params.hpp"
#include "battery/battery_warnings.hpp"
#include "common/errors.hpp"
#include "common/params.hpp"
#include "common/yaml_params.hpp"
#include "../common/input_errors.hpp"
#include "cooling/cooling_params.hpp"
#include "cooling/cooling_warnings.hpp"
#include "hvac/hvac_params.hpp"
#include "hvac/hvac_warnings.hpp"
#include "cosim/core/diagnostics_params.hpp"
#include "cylinder/cylinder_params.hpp"
#include "emachine/emachine_params.hpp"
#include "emachine/emachine_warnings.hpp"
#include "engine/engine_warnings.hpp"
#include "engine_1d/engine_1d_params.hpp"
#include "engine_map/map_engine.hpp"
#include "ems/ems_params.hpp"
#include "mission/mission_preprocessor.hpp"
#include "turbo/turbo_config.hpp"
#include "vehicle/vehicle_params.hpp"
#include "vehicle/vehicle_warnings.hpp"

namespace hbt {
namespace {

/// One shipped file and how the product reads it (its ParamSet, the prefixes set elsewhere).
struct ShippedFile {
  std::string file;                         // relative to the repository
  std::function<void(ParamSet&)> declare;   // the model's declaration, as its node makes it
  std::vector<std::string> set_elsewhere;   // keys another file or the scenario sets
};

template <class P>
std::function<void(ParamSet&)> declared(const std::string& prefix = "") {
  return [prefix](ParamSet& ps) {
    static P p;  // the references in ps must outlive the call: one object per model type
    ps.setPrefix(prefix);
    p.declare(ps);
    ps.setPrefix("");
  };
}

/// A sub-file the 1D engine's YAML names (key engine_1d/<key>), beside it in config/.
std::string engine1dSubFile(const std::string& key) {
  const ParamSource e = readYamlParams("config/engine_1d.yaml");
  const auto it = e.values.find("engine_1d/" + key);
  if (it == e.values.end() || !std::holds_alternative<std::string>(it->second))
    throw InputError("config/engine_1d.yaml", "engine_1d/" + key, "not found by the test");
  return "config/" + std::get<std::string>(it->second);
}

/// A participant's file: its model's keys and its warning thresholds (diagnostics/), as its node
/// reads them (Participant::readWarningThresholds).
template <class P, class W>
std::function<void(ParamSet&)> withWarnings(const std::function<void(W&, ParamSet&)>& declare_warnings) {
  return [declare_warnings](ParamSet& ps) {
    declared<P>()(ps);
    static W w;
    ps.setPrefix("diagnostics/");
    declare_warnings(w, ps);
    ps.setPrefix("");
  };
}
template <class P, class W>
std::function<void(ParamSet&)> withWarnings() {
  return withWarnings<P, W>([](W& w, ParamSet& ps) { w.declare(ps); });
}

std::vector<ShippedFile> shippedFiles() {
  return {
      {"config/aftertreatment.yaml", withWarnings<aftertreatment::AtsParams, aftertreatment::AftertreatmentWarnings>(), {}},
      {"config/battery.yaml", withWarnings<battery::BatteryParams, battery::BatteryWarnings>(), {}},
      {"config/cooling.yaml", withWarnings<cooling::CoolingParams, cooling::CoolingWarnings>(), {}},
      {"config/hvac.yaml", withWarnings<hvac::HvacParams, hvac::HvacWarnings>(), {}},
      {"config/emachine.yaml", withWarnings<emachine::EMachineParams, emachine::EMachineWarnings>(), {}},
      {"config/ems.yaml", declared<ems::EmsParams>(), {}},
      {"config/engine_map.yaml",
       withWarnings<engine_map::MapEngineParams, engine::EngineWarnings>(
           [](engine::EngineWarnings& w, ParamSet& ps) { w.declare(ps, "map"); }),
       {}},
      {"config/vehicle.yaml", withWarnings<vehicle::VehicleParams, vehicle::VehicleWarnings>(), {"aux/", "gearbox/"}},
      {"config/mission.yaml", declared<mission::MissionParams>(), {}},
      {"config/diagnostics.yaml", declared<cosim::core::DiagnosticsParams>(), {}},
      {"config/aux/vecto_p1_example.yaml", declared<vehicle::AuxParams>("aux/"), {}},
      {"config/aux/vecto_p1_example_48v.yaml", declared<vehicle::AuxParams>("aux/"), {}},
      {"config/aux/fan_only.yaml", declared<vehicle::AuxParams>("aux/"), {}},
      {"config/gearbox/typical.yaml", declared<vehicle::GearLossSetParams>("gearbox/"), {}},
      {"config/gearbox/vecto_standard.yaml", declared<vehicle::GearLossSetParams>("gearbox/"), {}},
      {"config/battery_pack/production_13s2p.yaml",
       [](ParamSet& ps) { static battery::BatteryParams b; b.declarePackSet(ps); }, {}},
      {"config/engine_1d.yaml",
       withWarnings<engine_1d::Engine1DConfig, engine::EngineWarnings>(
           [](engine::EngineWarnings& w, ParamSet& ps) { w.declare(ps, "1d"); }),
       {}},
      {engine1dSubFile("files/cylinder"), declared<cylinder::CylinderParams>(), {}},
      {engine1dSubFile("files/turbo"), [](ParamSet& ps) { static turbo::TurboConfig t; t.declare(ps, "turbo/"); }, {}},
  };
}

}  // namespace

TEST(RequiredKeys, EveryShippedFileHoldsEveryKeyAndEachRemovalIsNamed) {
  int files = 0, keys = 0;
  for (const ShippedFile& s : shippedFiles()) {
    SCOPED_TRACE(s.file);
    const ParamSource full = readYamlParams(s.file);
    ParamSet ps;
    s.declare(ps);
    ASSERT_NO_THROW(requireKeys(ps, full, s.set_elsewhere));
    for (const auto& e : ps.entries()) {
      bool elsewhere = false;
      for (const auto& p : s.set_elsewhere) elsewhere = elsewhere || e.key.rfind(p, 0) == 0;
      if (elsewhere || !e.default_source.empty()) continue;
      ParamSource cut = full;
      ASSERT_EQ(cut.values.erase(e.key), 1u) << e.key;
      try {
        requireKeys(ps, cut, s.set_elsewhere);
        ADD_FAILURE() << "removing " << e.key << " from " << s.file << " was accepted";
      } catch (const InputError& err) {
        const std::string what = err.what();
        EXPECT_NE(what.find(s.file), std::string::npos) << what;
        EXPECT_NE(what.find(e.key), std::string::npos) << what;
        EXPECT_NE(what.find("required key missing"), std::string::npos) << what;
      }
      ++keys;
    }
    ++files;
  }
  std::printf("required keys: %d keys of %d shipped files, each removal rejected naming file and key\n", keys, files);
  EXPECT_GT(keys, 400);
}

/// Reads the diagnostics/ section of `file` into `w` as the participant does; then validate.
template <class W>
void readWarnings(W& w, const ParamSource& file) {
  ParamSet ps;
  ps.setPrefix("diagnostics/");
  w.declare(ps);
  ParamSource own;
  own.file = file.file;
  for (const auto& kv : file.values)
    if (kv.first.rfind("diagnostics/", 0) == 0) own.values.insert(kv);
  applyParams(ps, own);
  w.validate(file.file);
}

TEST(WarningThresholds, ShippedValuesReadAndBadOnesNamed) {
  const ParamSource vehicle = readYamlParams("config/vehicle.yaml");
  vehicle::VehicleWarnings vw;
  readWarnings(vw, vehicle);
  EXPECT_EQ(vw.speed_error_kmh, 3.0);
  EXPECT_EQ(vw.speed_error_release_kmh, 2.0);
  const ParamSource cooling = readYamlParams("config/cooling.yaml");
  cooling::CoolingWarnings cw;
  readWarnings(cw, cooling);
  EXPECT_EQ(cw.overheat_c, 105.0);
  auto rejected = [](auto w, ParamSource src, const std::string& key, ParamValue v, const std::string& named) {
    src.set(key, v);
    hbt::testing::expectInputError([&] { readWarnings(w, src); }, src.file, named);
  };
  rejected(vehicle::VehicleWarnings{}, vehicle, "diagnostics/speed_eror_kmh", 3.0, "diagnostics/speed_eror_kmh");
  rejected(vehicle::VehicleWarnings{}, vehicle, "diagnostics/speed_error_release_kmh", 4.0,
           "diagnostics/speed_error_release_kmh");  // above the threshold: no hysteresis
  rejected(cooling::CoolingWarnings{}, cooling, "diagnostics/overheat_c", std::nan(""), "diagnostics/overheat_c");
  rejected(cooling::CoolingWarnings{}, cooling, "diagnostics/overheat_release_c", 110.0,
           "diagnostics/overheat_release_c");
  // the model reading the same file leaves the section to its participant
  cooling::CoolingParams cp;
  ParamSet cps;
  cp.declare(cps);
  EXPECT_NO_THROW(applyParams(cps, cooling));
}

TEST(RequiredKeys, AnIntendedDefaultMayBeLeftOutAndSaysWhy) {
  double a = 1.0, b = 2.0;
  ParamSet ps;
  ps.add("a_m", a, "m", 0.0, 10.0, "a length");
  ps.add("b_s", b, "s", 0.0, 10.0, "a time");
  ps.intendedDefault("the solver's own default");
  ParamSource src;
  src.file = "x.yaml";
  src.set("a_m", 3.0);
  EXPECT_NO_THROW(requireKeys(ps, src));
  applyParams(ps, src);
  EXPECT_EQ(b, 2.0);
  EXPECT_NE(describeParams(ps).find("intended default: the solver's own default"), std::string::npos);
  ParamSource none;
  none.file = "x.yaml";
  EXPECT_THROW(requireKeys(ps, none), InputError);  // a_m is required
  EXPECT_THROW(ps.intendedDefault(""), InputError);  // a default needs its source
}

}  // namespace hbt
