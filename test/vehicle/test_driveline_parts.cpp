// Driveline parts against the raw VECTO data and closed forms: torque converter (pump torque
// ∝ n², torque ratio at stall, loss >= 0), gear loss grid, retarder, VECTO RRC weighting, gear
// ratios -> engine speed, shift/lock-up rules, driver pedal allocation, parameter files.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "common/yaml_params.hpp"
#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"
#include "vehicle/driver.hpp"
#include "vehicle/shift_strategy.hpp"
#include "vehicle/torque_converter.hpp"
#include "vehicle/transmission_losses.hpp"
#include "vehicle/vehicle_model.hpp"
#include "../common/input_errors.hpp"

using namespace hbt;
using namespace hbt::vehicle;
using units::rpmToRadps;
using hbt::testing::expectInputError;

namespace {

const std::string kTc = "config/data/vehicle/generic_primary_bus_P31/torque_converter_APT-S_standard_values.vtcc";
const std::string kLoss = "config/data/vehicle/generic_primary_bus_P31/gear_loss_map_gears2_3_5_6.csv";

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST(TorqueConverter, PumpTorqueScalesWithSpeedSquaredAndMatchesFile) {
  const TorqueConverter tc(kTc, rpmToRadps(1000.0));
  const auto raw = CsvTable::read(kTc);
  const auto& nu = raw.column(raw.header()[0]);
  const auto& mu = raw.column(raw.header()[1]);
  const auto& mp = raw.column(raw.header()[2]);
  for (std::size_t i = 0; i < raw.rows(); ++i) {
    const double wp = rpmToRadps(1000.0);
    EXPECT_NEAR(tc.pumpTorque(wp, nu[i] * wp), mp[i], 1e-9 * (1 + std::fabs(mp[i])));
    const double tt = nu[i] > 1.0 ? mp[i] / mu[i] : mu[i] * mp[i];  // overrun: μ = T_p/T_t
    EXPECT_NEAR(tc.turbineTorque(wp, nu[i] * wp), tt, 1e-9 * (1 + std::fabs(mp[i])));
    for (double n : {700.0, 1500.0, 2200.0}) {  // T_p ∝ n² at constant ν
      const double w = rpmToRadps(n);
      EXPECT_NEAR(tc.pumpTorque(w, nu[i] * w), mp[i] * (n / 1000.0) * (n / 1000.0),
                  1e-9 * (1 + std::fabs(mp[i])));
    }
  }
  // Stall: torque ratio 1.80, 367.68 Nm at 1000 rpm.
  EXPECT_NEAR(tc.turbineTorque(rpmToRadps(1000.0), 0.0) / tc.pumpTorque(rpmToRadps(1000.0), 0.0), 1.80, 1e-12);
  // Power loss T_p ω_p - T_t ω_t >= 0 everywhere (traction and overrun).
  for (double x = 0.0; x <= 5.0; x += 0.01) {
    const double wp = rpmToRadps(1200.0), wt = x * wp;
    EXPECT_GE(tc.pumpTorque(wp, wt) * wp - tc.turbineTorque(wp, wt) * wt, -1e-9) << x;
  }
}

TEST(TorqueConverter, BadFileRejected) {
  const auto p1 = writeTemp("tc1.vtcc", "nu,mu,mp\n0.1,1.8,300\n0.5,1.2,200\n");
  EXPECT_THROW(TorqueConverter(p1, 100.0), InputError);
  const auto p2 = writeTemp("tc2.vtcc", "nu,mu,mp\n0,1.8,300\n0.5,-1,200\n");
  expectInputError([&] { TorqueConverter tc(p2, 100.0); }, p2, "mu");
  const auto p3 = writeTemp("tc3.vtcc", "nu,mu,mp\n0,1.8,300\n0.5,1.2,nan\n");
  EXPECT_THROW(TorqueConverter(p3, 100.0), InputError);
}

TEST(GearLossMap, GridValuesBilinearAndChecks) {
  const GearLossMap m(kLoss);
  EXPECT_NEAR(m.total(rpmToRadps(900.0), 600.0), 81.0, 1e-9);
  EXPECT_NEAR(m.total(rpmToRadps(900.0), -600.0), 81.0, 1e-9);  // symmetric in torque sign
  EXPECT_NEAR(m.drag(rpmToRadps(600.0)), 48.0, 1e-9);
  EXPECT_NEAR(m.total(rpmToRadps(1400.0), 1000.0), 0.5 * (106.0 + 118.0), 1e-9);  // bilinear
  EXPECT_NEAR(m.load(rpmToRadps(2000.0), 2500.0), 100.0, 1e-9);
  EXPECT_NEAR(m.total(rpmToRadps(5000.0), 9000.0), 220.0, 1e-9);  // clamped at the grid edge
  const auto p = writeTemp("loss.csv", "input speed [rpm],input torque [Nm],torque loss [Nm]\n0,0,10\n0,100,12\n600,0,11\n");
  EXPECT_THROW(GearLossMap{p}, InputError);
  const RetarderLoss r("config/data/vehicle/generic_primary_bus_P31/retarder_loss_map.csv");
  EXPECT_NEAR(r.torque(rpmToRadps(1000.0)), 12.0, 1e-9);
  EXPECT_EQ(RetarderLoss("").torque(100.0), 0.0);
}

namespace {
GearLossSetParams loadGearLossSet(const std::string& name) {
  GearLossSetParams g;
  ParamSet ps;
  ps.setPrefix("gearbox/");
  g.declare(ps);
  applyParams(ps, readYamlParams(gearLossSetFile("config", name)));
  return g;
}
// Loss at the gearbox input of gear g (1-based) as VehicleModel applies it: drag + f_g x load.
double setLoss(const GearLossMap& m, const GearLossSetParams& g, int gear, double n_rpm, double T_Nm) {
  const double w = rpmToRadps(n_rpm);
  return m.drag(w) + g.gear_load_loss_factor[gear - 1] * m.load(w, T_Nm);
}
}  // namespace

// Set "typical" (the default): VECTO's generic-bus AT efficiency 0.925 in every gear, no
// separate drag: eta = 1 - L/T_in = 0.925 at any speed, torque and gear.
TEST(GearLossSet, TypicalReproducesVectoGenericBusAtEfficiency) {
  const GearLossSetParams g = loadGearLossSet("typical");
  const GearLossSetParams def;  // the C++ defaults are the typical set
  EXPECT_EQ(g.gear_loss_map_file, def.gear_loss_map_file);
  EXPECT_EQ(g.gear_load_loss_factor, def.gear_load_loss_factor);
  const GearLossMap m(g.gear_loss_map_file);
  for (int gear = 1; gear <= 6; ++gear)
    for (double n : {700.0, 1000.0, 1400.0, 2200.0})
      for (double T : {150.0, 500.0, 1250.0, 1900.0, 3500.0}) {
        EXPECT_NEAR(1.0 - setLoss(m, g, gear, n, T) / T, 0.925, 1e-12) << gear << " " << n << " " << T;
        EXPECT_NEAR(setLoss(m, g, gear, n, -T), 0.075 * T, 1e-9);  // motoring: same loss
      }
  EXPECT_EQ(m.drag(rpmToRadps(1400.0)), 0.0);
}

// Set "vecto_standard": EU 2017/2400 Annex VI Appendix 8 for > 2 friction shift clutches,
// T_l,in = T_d0 + T_d1000 n/1000 + f_T T_in, T_d0 = T_d1000 = 0.015 T_max,in (2000 Nm) = 30 Nm,
// f_T = 0.04 indirect, 0.01 in the direct gear 4 — on and between the grid points.
TEST(GearLossSet, VectoStandardReproducesRegulationFormula) {
  const GearLossSetParams g = loadGearLossSet("vecto_standard");
  const GearLossMap m(g.gear_loss_map_file);
  const double Td = 0.015 * 2000.0;
  for (int gear = 1; gear <= 6; ++gear) {
    const double fT = gear == 4 ? 0.01 : 0.04;
    for (double n : {600.0, 900.0, 1400.0, 2000.0, 2250.0})
      for (double T : {0.0, 200.0, 500.0, 1000.0, 1900.0}) {
        const double formula = Td + Td * n / 1000.0 + fT * T;
        EXPECT_NEAR(setLoss(m, g, gear, n, T), formula, 1e-9) << gear << " " << n << " " << T;
      }
  }
  // The worked point of config/gearbox/*.yaml: 1400 rpm, 500 Nm in 3rd: 92 Nm (eta 0.816).
  EXPECT_NEAR(setLoss(m, g, 3, 1400.0, 500.0), 92.0, 1e-9);
}

TEST(GearLossSet, UnknownSetNameRejectedNamingTheArgument) {
  for (const std::string bad : {"measured", "", "../vehicle", "typical.yaml"}) {
    SCOPED_TRACE(bad);
    const std::string msg = expectInputError([&] { gearLossSetFile("config", bad); }, "config/gearbox", "gearbox");
    EXPECT_NE(msg.find("typical, vecto_standard"), std::string::npos) << msg;
  }
  EXPECT_EQ(gearLossSetFile("config", "typical"), "config/gearbox/typical.yaml");
  // A set whose factors do not match the gear count is rejected before the run.
  VehicleParams p;
  p.gearbox.gear_load_loss_factor = {1.0, 1.0};
  expectInputError([&] { p.validate("config/gearbox/x.yaml"); }, "config/gearbox/x.yaml",
                   "gearbox/gear_load_loss_factor");
}

TEST(RoadLoad, VectoRollingResistanceWeighting) {
  ChassisParams c;
  const RoadLoad r(c);
  const double m = 16660.0, g = 9.81;
  const double f = 0.38 * m * g / 2.0, rr = 0.62 * m * g / 4.0;
  const double crr = 0.38 * 0.0055 * std::pow(f / 31300.0, -0.1) + 0.62 * 0.0063 * std::pow(rr / 31300.0, -0.1);
  EXPECT_NEAR(r.rollingCoefficient(), crr, 1e-15);
  EXPECT_NEAR(r.rollingCoefficient(), 0.00608, 1e-5);
  EXPECT_NEAR(r.airDensity(293.15), 101325.0 / (287.05 * 293.15), 1e-12);
  EXPECT_NEAR(r.gradeForce(0.05), m * g * 0.05 / std::sqrt(1.0025), 1e-9);
}

TEST(Gearbox, RatiosGiveEngineSpeed) {
  VehicleModel vm{VehicleParams{}};
  const double ratios[] = {3.364, 1.909, 1.421, 1.000, 0.720, 0.615};
  const double v = units::kmhToMps(40.0);
  for (int g = 2; g <= 6; ++g) {
    vm.reset(v, g, 0.0);
    EXPECT_NEAR(vm.outputs().engine_speed_rad_s, v * ratios[g - 1] * 6.5 / 0.4915, 1e-9);
  }
  // 6th gear at 80 km/h: about 1730 rpm; 1st gear locked at 2200 rpm ≈ 18.6 km/h.
  EXPECT_NEAR(units::radpsToRpm(units::kmhToMps(80.0) * vm.ratio(6)), 1726.0, 2.0);
  EXPECT_NEAR(units::mpsToKmh(rpmToRadps(2200.0) / vm.ratio(1)), 18.6, 0.1);
}

TEST(ShiftStrategy, LinesHysteresisTimerLockup) {
  ShiftParams p;
  const std::vector<double> r{3.364, 1.909, 1.421, 1.000, 0.720, 0.615};
  const ShiftStrategy s(p, r, rpmToRadps(700.0));
  ShiftInputs in;
  in.accel_pedal = 1.0;
  const GearState l2{DriveMode::Locked, 2};
  in.engine_speed_rad_s = in.gearbox_input_speed_rad_s = rpmToRadps(2190.0);
  EXPECT_EQ(s.decide(l2, in), l2);
  in.engine_speed_rad_s = rpmToRadps(2205.0);
  EXPECT_EQ(s.decide(l2, in), (GearState{DriveMode::Locked, 3}));
  in.time_since_shift_s = 1.0;  // min time between shifts
  EXPECT_EQ(s.decide(l2, in), l2);
  in.time_since_shift_s = 10.0;
  // Pedal 0: upshift line 1200 rpm, but 1L->2L would land at 1300/1.762 = 738 rpm < 850+100.
  in.accel_pedal = 0.0;
  in.engine_speed_rad_s = rpmToRadps(1300.0);
  EXPECT_EQ(s.decide({DriveMode::Locked, 1}, in), (GearState{DriveMode::Locked, 1}));
  in.engine_speed_rad_s = rpmToRadps(1700.0);  // lands at 965 rpm >= 950
  EXPECT_EQ(s.decide({DriveMode::Locked, 1}, in), (GearState{DriveMode::Locked, 2}));
  // Downshift below 850 rpm at pedal 0; 2L -> 1C if the turbine speed would be < 1000 rpm.
  in.engine_speed_rad_s = rpmToRadps(840.0);
  EXPECT_EQ(s.decide({DriveMode::Locked, 4}, in), (GearState{DriveMode::Locked, 3}));
  in.engine_speed_rad_s = rpmToRadps(500.0);
  in.time_since_shift_s = 0.1;  // below idle: ignores the timer
  EXPECT_EQ(s.decide(l2, in), (GearState{DriveMode::Converter, 1}));
  // Lock-up 1C -> 1L at ν >= 0.85 and turbine >= 1000 rpm; unlock below 800 rpm.
  const GearState c1{DriveMode::Converter, 1};
  in.engine_speed_rad_s = rpmToRadps(1500.0);
  in.gearbox_input_speed_rad_s = rpmToRadps(1200.0);
  EXPECT_EQ(s.decide(c1, in), c1);
  in.gearbox_input_speed_rad_s = rpmToRadps(1300.0);
  EXPECT_EQ(s.decide(c1, in), (GearState{DriveMode::Locked, 1}));
  in.engine_speed_rad_s = rpmToRadps(790.0);
  EXPECT_EQ(s.decide({DriveMode::Locked, 1}, in), c1);
  // Neutral at stop; start request engages 1C from standstill.
  in.stopped_and_held = true;
  EXPECT_EQ(s.decide(c1, in), (GearState{DriveMode::Neutral, 0}));
  in.stopped_and_held = false;
  in.start_request = true;
  in.output_speed_rad_s = 0.0;
  EXPECT_EQ(s.decide({DriveMode::Neutral, 0}, in), c1);
}

TEST(Driver, PedalAllocation) {
  DriverParams p;
  Driver d(p, 10000.0);
  // Zero speed error: only the feed-forward acts.
  auto c = d.update(0.01, 10.0, 10.0, 3000.0, -2000.0, 8000.0);
  EXPECT_NEAR(c.accel_pedal, 0.5, 1e-12);
  EXPECT_EQ(c.brake_force_N, 0.0);
  d.reset();
  c = d.update(0.01, 10.0, 10.0, -12000.0, -2000.0, 8000.0);
  EXPECT_EQ(c.accel_pedal, 0.0);
  EXPECT_NEAR(c.brake_force_N, 10000.0, 1e-9);
  EXPECT_NEAR(c.brake_pedal, 10000.0 / 50000.0, 1e-12);
  // Stop hold.
  c = d.update(0.01, 0.2, 0.0, 0.0, -2000.0, 8000.0);
  EXPECT_TRUE(c.hold);
  EXPECT_GE(c.brake_force_N, 0.3 * 50000.0);
}

TEST(VehicleParams, YamlMatchesDeclarationAndBadValuesRejected) {
  VehicleParams p;
  ParamSet ps;
  p.declare(ps);
  ParamSource src = readYamlParams("config/vehicle.yaml");
  for (const auto& kv : readYamlParams("config/aux/vecto_p1_example.yaml").values) src.values.insert(kv);
  for (const auto& kv : readYamlParams("config/gearbox/typical.yaml").values) src.values.insert(kv);
  EXPECT_NO_THROW(applyParams(ps, src));
  for (const auto& e : ps.entries()) EXPECT_TRUE(src.values.count(e.key)) << "missing in YAML: " << e.key;
  EXPECT_NO_THROW(p.validate("config/vehicle.yaml"));
  VehicleModel vm(p);
  EXPECT_NEAR(vm.params().totalMass_kg(), 16660.0, 1e-9);

  ParamSource bad;
  bad.file = "vehicle.yaml";
  bad.set("chassis/payload", 1500.0);
  expectInputError([&] { applyParams(ps, bad); }, "vehicle.yaml", "chassis/payload");
  VehicleParams q;
  q.driveline.gear_ratios = {3.0, 3.5, 1.0, 0.9, 0.8, 0.7};
  expectInputError([&] { q.validate("vehicle.yaml"); }, "vehicle.yaml", "driveline/gear_ratios");
  VehicleParams r;
  r.driveline.torque_converter_file = "/nonexistent/tc.vtcc";
  EXPECT_THROW(VehicleModel{r}, InputError);
}
