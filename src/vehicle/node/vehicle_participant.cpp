#include "vehicle/node/vehicle_participant.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/DriverDemand.h>
#include <hybrid_bus_twin/EngineCommand.h>
#include <hybrid_bus_twin/VehicleState.h>
#include <hybrid_bus_twin/VehicleToCooling.h>

#include <functional>

#include "common/errors.hpp"
#include "common/yaml_params.hpp"
#include "common/units.hpp"
#include "cosim/param_loader.hpp"
#include "emachine/emachine_params.hpp"
#include "mission/scenario_mission.hpp"

namespace hbt::vehicle {

// The idle speed is the engine's: idle_speed_rad_s of config/engine_map.yaml (in the scenario's
// config folder; both engine models start there). Only that key is read from it.
void VehicleParticipant::readEngineIdleSpeed(VehicleParams& p) {
  const std::string file = cosim::scenarioConfigFile(nh_, "engine_map.yaml");
  const ParamSource all = readYamlParams(file);
  const auto it = all.values.find("idle_speed_rad_s");
  if (it == all.values.end())
    throw InputError(file, "idle_speed_rad_s", "missing: the engine's idle speed (the vehicle's idle governor holds it)");
  ParamSource one;
  one.file = file;
  one.values.insert(*it);
  ParamSet ps;
  ps.add("idle_speed_rad_s", p.driveline.idle_speed_rad_s, "rad/s", 30.0, 150.0, "engine idle speed");
  applyParams(ps, one);
}

// A file of the scenario's own sets, read on its own so that errors name its file and key:
// the group `prefix` (aux/, gearbox/) of `file`, every key required.
void VehicleParticipant::readSet(const std::string& file, const std::string& prefix,
                                 const std::function<void(ParamSet&)>& declare) {
  ParamSet ps;
  ps.setPrefix(prefix);
  declare(ps);
  applyParamFile(ps, file);
}

void VehicleParticipant::readScenarioSets(VehicleParams& p) {
  std::string aux_set, gearbox_set;
  if (nh_.getParam("/scenario/aux_set", aux_set))  // the auxiliary set (launch argument aux)
    readSet(cosim::scenarioConfigFile(nh_, "aux/" + aux_set + ".yaml"), "aux/",
            [&](ParamSet& ps) { p.aux.declare(ps); });
  if (nh_.getParam("/scenario/gearbox_set", gearbox_set))  // the gear loss set (launch argument gearbox)
    readSet(cosim::scenarioConfigFile(nh_, "gearbox/" + gearbox_set + ".yaml"), "gearbox/",
            [&](ParamSet& ps) { p.gearbox.declare(ps); });
}

// Hybrid: the P1 rotor turns with the crank (ratio² x its inertia), from config/emachine.yaml.
void VehicleParticipant::addEMachineInertia(VehicleParams& p) {
  if (!inScenario("emachine")) return;
  const std::string file = cosim::scenarioConfigFile(nh_, "emachine.yaml");
  emachine::EMachineParams ep;
  ParamSet eps;
  ep.declare(eps);
  applyParamFile(eps, file);
  p.driveline.engine_inertia_kg_m2 += ep.data.crankInertia_kgm2();
}

void VehicleParticipant::readPayloadAndAmbient(VehicleParams& p) {
  double payload_kg = p.chassis.payload_kg;
  nh_.param("/scenario/payload_kg", payload_kg, payload_kg);
  ambient_T_K_ = cosim::scenarioAmbient_K(nh_);
  p.chassis.ambient_pressure_Pa = cosim::scenarioAmbientPressure_Pa(nh_);
  if (!(payload_kg >= 0.0 && payload_kg <= 15000.0))
    throw InputError("scenario (launch argument)", "payload", "must be in [0, 15000] kg");
  p.chassis.payload_kg = payload_kg;
}

// The mission, planned for this bus (src/mission/scenario_mission.hpp), and the grade along it.
void VehicleParticipant::buildMission(const VehicleParams& p, const std::string& pkg) {
  mission::ScenarioMission m;
  m.mission_file = cosim::scenarioConfigFile(nh_, "mission.yaml");
  nh_.param<std::string>("/scenario/cycle_file", m.cycle_file, "");
  m.package_dir = pkg;
  nh_.param<std::string>("/scenario/out_dir", m.out_dir, "");
  m.bus.mass_kg = p.totalMass_kg();
  m.bus.rotating_mass_kg = model_->vehicleInertiaMass_kg() - p.totalMass_kg();
  m.bus.cda_m2 = p.chassis.cda_m2;
  m.bus.rrc = model_->roadLoad().rollingCoefficient();
  profile_ = mission::buildScenarioMission(m);
  setMissionDuration(profile_.duration_s());  // announced to the stepper (progress line only)
  const auto& cyc = profile_.cycle();
  std::vector<double> grade(cyc.grade_percent.size());
  for (std::size_t i = 0; i < grade.size(); ++i) grade[i] = cyc.grade_percent[i] / 100.0;
  model_->setGradeProfile(cyc.distance_m, grade);
}

void VehicleParticipant::declareTopics() {
  engine_ = &addInputFrom<hybrid_bus_twin::EngineState>("engine", "state");
  if (inScenario("cooling")) cooling_ = &addInputFrom<hybrid_bus_twin::CoolingState>("cooling", "state");
  if (inScenario("hvac")) hvac_ = &addInputFrom<hybrid_bus_twin::HvacState>("hvac", "state");
  const bool hybrid = inScenario("ems");  // the EMS splits the driver's demand
  if (hybrid) {
    ems_ = &addInputFrom<hybrid_bus_twin::EmsCommand>("ems", "command");
    em_ = &addInputFrom<hybrid_bus_twin::EMachineState>("emachine", "state");
  }
  state_pub_ = addOwnOutput<hybrid_bus_twin::VehicleState>("state");
  if (hybrid) demand_pub_ = addOwnOutput<hybrid_bus_twin::DriverDemand>("driver_demand");
  else command_pub_ = addOwnOutput<hybrid_bus_twin::EngineCommand>("engine_command");
  cooling_pub_ = addOwnOutput<hybrid_bus_twin::VehicleToCooling>("to_cooling");
}

void VehicleParticipant::configure() {
  VehicleParams p;
  readScenarioSets(p);
  ParamSet ps;
  p.declare(ps);
  cosim::applyRosParams(pnh_, ps, configFile(), {}, {"aux/", "gearbox/"});  // their own files (above)
  readEngineIdleSpeed(p);
  readPayloadAndAmbient(p);
  addEMachineInertia(p);
  p.validate(configFile());
  std::string pkg;
  nh_.param<std::string>("/scenario/package_dir", pkg, ".");
  model_ = std::make_unique<VehicleModel>(p, pkg);
  buildMission(p, pkg);
  model_->reset(profile_.speedAt(0.0), 0, p.driveline.idle_speed_rad_s, 0.0);
  if (cosim::scenarioWarmStart(nh_))  // a bus mid-shift: driveline_oil/*/warm_start_K
    model_->setOilTemperatures(p.driveline_oil.gearbox.warm_start_K, p.driveline_oil.axle.warm_start_K);
  else  // a morning start: the oils at the ambient
    model_->setOilTemperatures(ambient_T_K_, ambient_T_K_);
  declareTopics();
  readWarningThresholds(warnings_);
  warnings_.validate(configFile());
  not_tracking_ = &addWarning("driver_not_tracking", warnings_.duration_s);
  speed_error_ = std::make_unique<cosim::core::Hysteresis>(warnings_.speed_error_kmh, warnings_.speed_error_release_kmh);
}

/// Pedal position taken as saturated: the driver has no authority left [-].
constexpr double kPedalSaturated = 0.99;

void VehicleParticipant::checkWarnings(cosim::core::Nanos t) {
  const VehicleOutputs& o = model_->outputs();
  const double target_kmh = 3.6 * profile_.speedAt(cosim::core::toSec(t));  // as in /vehicle/state
  const double err_kmh = target_kmh - 3.6 * o.speed_m_s;
  const bool large = speed_error_->update(std::abs(err_kmh));
  // the target is reachable while the pedal that would close the gap is not saturated
  const bool authority = err_kmh > 0.0 ? o.accel_pedal < kPedalSaturated : o.brake_pedal < kPedalSaturated;
  const VehicleWarnings& d = warnings_;
  if (not_tracking_->update(t, large && authority))
    not_tracking_->setMessage(cosim::core::formatText(
        "speed %.1f km/h vs target %.1f km/h: |error| above %.1f km/h for %.1f s with the %s pedal at %.2f",
        3.6 * o.speed_m_s, target_kmh, d.speed_error_kmh, d.duration_s,
        err_kmh > 0.0 ? "accelerator" : "brake", err_kmh > 0.0 ? o.accel_pedal : o.brake_pedal));
}

void VehicleParticipant::diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  const VehicleOutputs& o = model_->outputs();
  const double target_kmh = 3.6 * profile_.speedAt(cosim::core::toSec(t));
  kv.push_back({"speed_kmh", formatNumber(3.6 * o.speed_m_s)});
  kv.push_back({"target_speed_kmh", formatNumber(target_kmh)});
  kv.push_back({"speed_error_kmh", formatNumber(target_kmh - 3.6 * o.speed_m_s)});
  kv.push_back({"gear", std::to_string(o.gear)});
  kv.push_back({"accelerator_pedal", formatNumber(o.accel_pedal)});
  kv.push_back({"brake_pedal", formatNumber(o.brake_pedal)});
  kv.push_back({"distance_m", formatNumber(o.distance_m)});
}

void VehicleParticipant::step(const ros::Time& t, double dt_s) {
  const auto& e = engine_->at(t);
  const double t_next = t.toSec() + dt_s;
  VehicleInputs in;
  in.target_speed_m_s = profile_.speedAt(t_next);
  in.target_accel_m_s2 = profile_.accelAt(t_next);
  in.engine_torque_Nm = e.brake_torque_nm;
  in.engine_max_torque_Nm = e.torque_max_nm;
  in.engine_min_torque_Nm = e.torque_min_nm;
  in.ambient_T_K = ambient_T_K_;
  if (cooling_) {
    const auto& c = cooling_->at(t);
    in.has_fan_power = true;
    in.fan_power_W = c.fan_drive_power_w;  // crank side, incl. clutch slip
    in.hvac_electric_W = c.electric_pump_power_w;  // heater circulation pump (24 V, engine stopped)
  }
  if (hvac_) {  // A/C compressor on the crank, the HVAC's 24 V load
    const auto& h = hvac_->at(t);
    in.hvac_compressor_W = h.compressor_power_w;
    in.hvac_electric_W += h.electric_power_w;
  }
  if (ems_) {  // the EMS's split for [t, t + dt]; the e-machine's torque of its step before
    const auto& c = ems_->at(t);
    const auto& m = em_->at(t);
    in.em_torque_Nm = m.torque_nm;
    in.em_max_torque_Nm = std::max(0.0, m.torque_max_nm);
    in.engine_on = engine_on_ = c.engine_on;
    in.brake_override = true;
    in.friction_brake_force_N = c.friction_brake_request_nm / model_->params().chassis.tyre_radius_m;
  }
  last_engine_max_Nm_ = in.engine_max_torque_Nm;
  last_engine_min_Nm_ = in.engine_min_torque_Nm;
  model_->step(dt_s, in);
  t_s_ = t_next;
}

void VehicleParticipant::publishOutputs(const ros::Time& t) {
  const VehicleOutputs& o = model_->outputs();
  const double ts = t.toSec();
  hybrid_bus_twin::VehicleState s;
  s.header.stamp = t;
  s.speed_m_s = o.speed_m_s;
  s.target_speed_m_s = profile_.speedAt(ts);
  s.acceleration_m_s2 = o.accel_m_s2;
  s.distance_m = o.distance_m;
  s.grade_percent = 100.0 * o.grade;
  s.accelerator_pedal = o.accel_pedal;
  s.brake_pedal = o.brake_pedal;
  s.gear = o.gear;
  s.drive_mode = static_cast<uint8_t>(o.mode);
  s.converter_locked = o.tc_locked;
  s.engine_speed_rad_s = o.engine_speed_rad_s;
  s.wheel_torque_request_nm = o.crank_torque_demand_Nm;
  s.friction_brake_torque_nm = o.brake_force_N * model_->params().chassis.tyre_radius_m;  // driver's
  s.friction_brake_applied_nm = o.applied_brake_force_N * model_->params().chassis.tyre_radius_m;
  s.engine_on = engine_on_;
  s.aux_power_w = o.aux_power_W;
  s.tyre_rr_factor = o.tyre_rr_factor;
  s.gearbox_oil_temperature_k = o.gearbox_oil_T_K;
  s.axle_oil_temperature_k = o.axle_oil_T_K;
  s.gearbox_drag_factor = o.gearbox_drag_factor;
  s.gearbox_oil_heat_w = o.gearbox_oil_heat_W;
  s.axle_oil_heat_w = o.axle_oil_heat_W;
  s.gearbox_cooler_heat_w = o.gearbox_cooler_W;
  s.gearbox_cooler_heat_j = model_->gearboxOil().toCooler_J();
  const VehicleEnergy& en = o.energy;
  s.aux_deferred_j = en.aux_deferred_J;
  s.dcdc_power_w = o.dcdc_input_power_W;
  s.dcdc_energy_j = en.dcdc_J;
  s.engine_work_j = en.engine_J;
  s.em_work_j = en.em_J;
  s.aux_work_j = en.aux_J;
  s.fan_work_j = en.fan_J;
  s.aux_steering_work_j = en.steering_J;
  s.aux_pneumatic_work_j = en.pneumatic_J;
  s.aux_electric_work_j = en.electric_J;
  s.aux_hvac_work_j = en.hvac_J;
  s.gearbox_drag_loss_j = en.gearbox_drag_J;
  s.converter_loss_j = en.tc_loss_J;
  s.gear_loss_j = en.gear_load_loss_J;
  s.retarder_loss_j = en.retarder_J;
  s.axle_loss_j = en.axle_loss_J;
  s.shift_loss_j = en.shift_loss_J;
  s.rolling_loss_j = en.rolling_J;
  s.aero_loss_j = en.aero_J;
  s.potential_energy_j = en.grade_J;
  s.friction_brake_loss_j = en.brake_J;
  s.kinetic_energy_change_j = en.kinetic_J - en.kinetic_initial_J;
  s.wheel_work_j = en.wheel_J;
  s.energy_residual_j = en.residual_J();
  s.mission_finished = ts >= profile_.duration_s() - 1e-9;
  state_pub_.publish(boost::make_shared<hybrid_bus_twin::VehicleState>(s));

  const double r_tyre = model_->params().chassis.tyre_radius_m;
  if (ems_) {
    hybrid_bus_twin::DriverDemand d;
    d.header.stamp = t;
    d.crank_torque_request_nm = o.crank_torque_demand_Nm;
    d.wheel_brake_request_nm = o.brake_force_N * r_tyre;
    d.engine_speed_rad_s = o.engine_speed_rad_s;
    d.vehicle_speed_m_s = o.speed_m_s;
    d.gear = o.gear;
    d.converter_locked = o.tc_locked;
    d.crank_to_wheel_ratio = o.crank_to_wheel_ratio;
    d.tyre_radius_m = r_tyre;
    d.stopped = o.speed_m_s == 0.0 && o.stop_hold && o.mode == DriveMode::Neutral;
    d.start_request = o.start_request;
    d.accelerator_pedal = o.accel_pedal;
    d.engine_max_torque_nm = last_engine_max_Nm_;
    d.engine_min_torque_nm = last_engine_min_Nm_;
    d.ambient_temperature_k = ambient_T_K_;
    d.ambient_pressure_pa = model_->params().chassis.ambient_pressure_Pa;
    demand_pub_.publish(boost::make_shared<hybrid_bus_twin::DriverDemand>(d));
  } else {
    hybrid_bus_twin::EngineCommand c;
    c.header.stamp = t;
    c.engine_speed_rad_s = o.engine_speed_rad_s;
    c.torque_request_nm = o.engine_torque_request_Nm;
    c.engine_on = true;
    c.ambient_temperature_k = ambient_T_K_;
    c.ambient_pressure_pa = model_->params().chassis.ambient_pressure_Pa;
    command_pub_.publish(boost::make_shared<hybrid_bus_twin::EngineCommand>(c));
  }

  hybrid_bus_twin::VehicleToCooling vc;
  vc.header.stamp = t;
  vc.vehicle_speed_m_s = o.speed_m_s;
  vc.distance_m = o.distance_m;
  vc.ambient_temperature_k = ambient_T_K_;
  vc.gearbox_cooler_heat_j = model_->gearboxOil().toCooler_J();  // oil-to-coolant cooler -> HT engine loop
  cooling_pub_.publish(boost::make_shared<hybrid_bus_twin::VehicleToCooling>(vc));
}

}  // namespace hbt::vehicle
