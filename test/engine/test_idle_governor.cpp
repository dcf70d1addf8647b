// Idle after a bus stop: the vehicle's idle governor (config/vehicle.yaml driver/idle_*)
// coupled with each engine model through the twin's engine interface (engine_interface/engine_model.hpp)
// at the 10 ms exchange, each side receiving the other's outputs of the previous exchange as in
// the co-simulation (Jacobi). Vehicle and auxiliaries from config/vehicle.yaml and
// config/aux/vecto_p1_example.yaml, engines from config/engine_map.yaml and config/engine_1d.yaml.
//
// Manoeuvre: 30 km/h, the profile's -0.9 m/s² to rest, stand 8 s, drive off at 0.8 m/s². At
// standstill the engine holds the converter's stall torque in 1C (~260 Nm); the standstill-
// neutral shift then drops the load to aux + spin loss (~96 Nm with the ATF at 25 °C) and the crank speed by ~40 rpm
// (the turbine joins the crank). Idle settling time = from that shift until the engine speed stays
// within ±10 rpm of idle and the brake torque within ±10 Nm of its mean over the last second in
// neutral. Measured (this test's printout): map 0.48 s, 1D 0.52 s (659-717 rpm, >= 46 Nm); a
// fuel trim that integrates the engine's own response time (~0.13 s for the 1D engine) settles
// in about 5 s instead. Start-off speed RMSE: map 0.40, 1D 0.51 km/h (docs/validation.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "common/params.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "engine_1d/engine_1d_model.hpp"
#include "engine_map/map_engine_model.hpp"
#include "vehicle/vehicle_model.hpp"
#include "../vehicle/stop_profile.hpp"

using namespace hbt;

namespace {

constexpr double kDt = 0.01;       // macro step = exchange period [s]
constexpr double kAmbient_K = 298.15;

std::string repoRoot() {
  const char* d = std::getenv("HBT_SOURCE_DIR");
  return d ? std::string(d) : std::string(".");
}

vehicle::VehicleParams vehicleParams() {
  vehicle::VehicleParams vp;
  ParamSet ps;
  vp.declare(ps);
  ParamSource src = readYamlParams(repoRoot() + "/config/vehicle.yaml");
  for (const auto& kv : readYamlParams(repoRoot() + "/config/aux/vecto_p1_example.yaml").values)
    src.values.insert(kv);
  applyParams(ps, src);
  return vp;
}

std::unique_ptr<engine::EngineModel> makeEngine(const std::string& name) {
  if (name == "map") {
    engine_map::MapEngineParams mp;
    ParamSet ps;
    mp.declare(ps);
    applyParams(ps, readYamlParams(repoRoot() + "/config/engine_map.yaml"));
    return std::make_unique<engine_map::MapEngineModel>(mp, repoRoot());
  }
  return std::make_unique<engine_1d::Engine1DModel>(engine_1d::Engine1DParams::load(repoRoot()),
                                                   repoRoot());
}

// Target: one stop from 30 km/h, standing 8 s (test/vehicle/stop_profile.hpp).
struct StopProfile : vehicle::test::StopProfile {
  StopProfile() : vehicle::test::StopProfile(8.0) {}
};

struct StopResult {
  double settling_s = -1.0;             // idle settling time after the neutral shift
  double rpm_min = 1e9, rpm_max = 0.0;  // engine speed in neutral [rpm]
  double torque_min_Nm = 1e9, torque_max_after_1s_Nm = -1e9, torque_final_Nm = 0.0;
  double rpm_dev_after_1s = 0.0;        // max |n - n_idle| from 1 s after the shift [rpm]
  double neutral_s = 0.0;               // time in neutral [s]
  double startoff_rmse_kmh = 0.0;       // speed error over the 10 s after the target leaves 0
  double spin_loss_Nm = 0.0;            // neutral spin loss at the end of the stop (cold-oil factor in) [Nm]
  double aux_torque_Nm = 0.0;           // auxiliaries at idle [Nm]
};

StopResult runStop(const std::string& engine_name) {
  const vehicle::VehicleParams vp = vehicleParams();
  const double idle_rpm = units::radpsToRpm(vp.driveline.idle_speed_rad_s);
  vehicle::VehicleModel veh(vp, repoRoot());
  std::unique_ptr<engine::EngineModel> eng = makeEngine(engine_name);
  veh.reset(0.0, 0, vp.driveline.idle_speed_rad_s);
  eng->reset(kAmbient_K);
  vehicle::VehicleOutputs vo = veh.outputs();
  engine::EngineOutputs eo = eng->outputs();
  const StopProfile prof;
  std::vector<double> t_n, rpm, torque;  // the neutral phase at the stop
  double t_neutral = -1.0, se = 0.0, spin_factor = 0.0;
  int n_se = 0;
  bool engaged_again = false;
  for (int k = 0; (k + 1) * kDt < prof.t_go + 10.0 + 1e-9; ++k) {
    const double t1 = (k + 1) * kDt;
    vehicle::VehicleInputs vin;  // what the vehicle got at the last exchange
    vin.target_speed_m_s = prof.v(t1);
    vin.target_accel_m_s2 = prof.a(t1);
    vin.ambient_T_K = kAmbient_K;
    vin.engine_torque_Nm = eo.brake_torque_Nm;
    vin.engine_max_torque_Nm = eo.max_torque_Nm;
    vin.engine_min_torque_Nm = eo.min_torque_Nm;
    engine::EngineInputs ein;  // what the engine got at the last exchange
    ein.speed_rad_s = vo.engine_speed_rad_s;
    ein.torque_request_Nm = vo.engine_torque_request_Nm;
    ein.ambient_T_K = kAmbient_K;
    vo = veh.step(kDt, vin);
    eo = eng->step(kDt, ein);
    if (t1 > prof.t_dec && t_neutral < 0.0 && vo.gear == 0) t_neutral = t1;
    if (t_neutral > 0.0 && vo.gear != 0) engaged_again = true;
    if (t_neutral > 0.0 && !engaged_again) {
      t_n.push_back(t1);
      rpm.push_back(units::radpsToRpm(vo.engine_speed_rad_s));
      torque.push_back(eo.brake_torque_Nm);
      spin_factor = vo.gearbox_drag_factor;  // the ATF's cold-oil factor (the oil warms < 0.1 K here)
    }
    if (t1 > prof.t_go) {
      se += std::pow(units::mpsToKmh(vo.speed_m_s - prof.v(t1)), 2);
      ++n_se;
    }
  }
  StopResult r;
  if (t_n.empty()) return r;
  const double w_idle = vp.driveline.idle_speed_rad_s;
  r.spin_loss_Nm = vp.driveline.neutral_drag_torque_Nm * spin_factor;
  r.aux_torque_Nm = (vp.aux.steering_pump_W + vp.aux.air_compressor_W + vp.aux.alternator_W + vp.aux.fan_default_W) /
                    w_idle;
  r.neutral_s = t_n.back() - t_neutral + kDt;
  int nf = 0;
  for (std::size_t i = 0; i < t_n.size(); ++i)
    if (t_n[i] > t_n.back() - 1.0) {
      r.torque_final_Nm += torque[i];
      ++nf;
    }
  r.torque_final_Nm /= nf;
  r.settling_s = 0.0;
  for (std::size_t i = 0; i < t_n.size(); ++i) {
    const double since = t_n[i] - t_neutral + kDt;
    if (std::fabs(rpm[i] - idle_rpm) > 10.0 || std::fabs(torque[i] - r.torque_final_Nm) > 10.0)
      r.settling_s = since;
    r.rpm_min = std::min(r.rpm_min, rpm[i]);
    r.rpm_max = std::max(r.rpm_max, rpm[i]);
    r.torque_min_Nm = std::min(r.torque_min_Nm, torque[i]);
    if (since > 1.0) {
      r.torque_max_after_1s_Nm = std::max(r.torque_max_after_1s_Nm, torque[i]);
      r.rpm_dev_after_1s = std::max(r.rpm_dev_after_1s, std::fabs(rpm[i] - idle_rpm));
    }
  }
  r.startoff_rmse_kmh = std::sqrt(se / n_se);
  std::printf("%-3s idle after the stop: settling %.2f s, %.1f-%.1f rpm, brake torque min %.1f Nm, "
              "final %.1f Nm; from 1 s: |n - idle| <= %.1f rpm, torque <= %.1f Nm; %.2f s in "
              "neutral; start-off speed rmse %.3f km/h\n",
              engine_name.c_str(), r.settling_s, r.rpm_min, r.rpm_max, r.torque_min_Nm,
              r.torque_final_Nm, r.rpm_dev_after_1s, r.torque_max_after_1s_Nm, r.neutral_s,
              r.startoff_rmse_kmh);
  return r;
}

}  // namespace

TEST(IdleGovernor, OneDEngineSettlesAfterAStopAsFastAsTheMapEngine) {
  const StopResult map = runStop("map");
  const StopResult e1d = runStop("1d");
  for (const StopResult* r : {&map, &e1d}) {
    ASSERT_GT(r->neutral_s, 7.0);  // the stop was served in neutral
    // aux (5.8 kW at 700 rpm = 79 Nm) + neutral spin loss 12 Nm x the ATF's cold-oil factor
    // (1.46 at 25 degC)
    EXPECT_GT(r->spin_loss_Nm, 12.0);
    EXPECT_NEAR(r->torque_final_Nm, r->aux_torque_Nm + r->spin_loss_Nm, 1.0);
    EXPECT_LE(r->rpm_dev_after_1s, 5.0);     // no oscillation left after 1 s
    EXPECT_LE(r->startoff_rmse_kmh, 0.7);    // drives off after the stop
  }
  // The map engine: not slower than before the fix (0.66 s).
  EXPECT_LE(map.settling_s, 0.6);
  // The 1D engine within 0.25 s of the map engine (its response: ~0.13 s at idle vs one
  // exchange); before the fix 5.0 s.
  EXPECT_LE(e1d.settling_s, map.settling_s + 0.25);
  // No overshoot beyond limits: the speed stays above the clutch impulse's dip (~660 rpm) and
  // below idle + 25 rpm (the pump load leaves ~0.13 s before the 1D torque follows); the brake
  // torque never dips towards motoring (before: -50 Nm) nor swings back above the final
  // torque + 15 Nm after the first second.
  EXPECT_GE(e1d.rpm_min, 650.0);
  EXPECT_LE(e1d.rpm_max, 725.0);
  EXPECT_GE(e1d.torque_min_Nm, 20.0);
  EXPECT_LE(e1d.torque_max_after_1s_Nm, e1d.torque_final_Nm + 15.0);
}
