// ROS bridge of the energy manager (hybrid only): converts messages and parameters, nothing else.
// Model: hbt::ems::EmsModel (../ems_model.hpp); its engine model is the VECTO map engine's steady
// fuel map (config/engine_map.yaml, as a real EMS carries a calibrated map whatever the plant is).
//
// Sits in the second Gauss-Seidel group (vehicle -> EMS -> engine, e-machine -> battery):
// Inputs: /vehicle/driver_demand (DriverDemand, fresh: stamped t_k + P, the demand for the next
//         step), /emachine/state (live torque limits), /battery/state (SOC, T, power limits),
//         /cooling/state (HT coolant) and /aftertreatment/state (SCR brick) when those
//         participants run (else the engine and ATS count as warm); /hvac/state
//         (engine_run_request: the belt-driven A/C needs the engine, no stop) when the hvac runs.
// Outputs (stamped t_k + P): /ems/command (EmsCommand: split, mode and reason, for the e-machine,
//         the vehicle and the bag), /ems/engine_command (EngineCommand for the engine node).
// Parameters: private namespace = config/ems.yaml; the map engine YAML of the scenario's config
//         folder (cosim::scenarioConfigFile); /scenario/engine_model (stop-start with the map
//         engine only: the 1D engine cannot be stopped and cranked).
// Diagnostics (docs/diagnostics.md): no warnings of its own (the limits it meets are the
// e-machine's and the battery's); key/values mode, reason, equivalence factor, stops/starts.
#pragma once
#include "common/units.hpp"
#include <hybrid_bus_twin/HvacState.h>
#include <hybrid_bus_twin/AftertreatmentState.h>
#include <hybrid_bus_twin/BatteryState.h>
#include <hybrid_bus_twin/CoolingState.h>
#include <hybrid_bus_twin/DriverDemand.h>
#include <hybrid_bus_twin/EMachineState.h>

#include <memory>

#include "cosim/participant.hpp"
#include "ems/ems_model.hpp"
#include "engine_map/map_engine.hpp"

namespace hbt::ems {

/// The controller's engine model over the VECTO map engine (steady fuel map).
class MapFuelModel : public FuelModel {
 public:
  explicit MapFuelModel(std::unique_ptr<engine_map::MapEngine> e) : e_(std::move(e)) {}
  double fuelRate_kg_s(double w, double T) const override { return e_->steadyFuel(w, T); }

 private:
  std::unique_ptr<engine_map::MapEngine> e_;
};

class EmsParticipant : public cosim::Participant {
 public:
  EmsParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;

 private:
  std::unique_ptr<MapFuelModel> fuel_;
  std::unique_ptr<EmsModel> model_;
  cosim::Input<hybrid_bus_twin::DriverDemand>* demand_ = nullptr;
  cosim::Input<hybrid_bus_twin::EMachineState>* em_ = nullptr;
  cosim::Input<hybrid_bus_twin::BatteryState>* battery_ = nullptr;
  cosim::Input<hybrid_bus_twin::CoolingState>* cooling_ = nullptr;
  cosim::Input<hybrid_bus_twin::AftertreatmentState>* ats_ = nullptr;
  cosim::Input<hybrid_bus_twin::HvacState>* hvac_ = nullptr;  // the hvac runs (hvac:=on) only
  cosim::Output command_pub_, engine_pub_;
  hybrid_bus_twin::DriverDemand last_demand_;
  double ambient_T_K_ = 298.15, ambient_p_Pa_ = units::kStandardAtmosphere_Pa;
};

}  // namespace hbt::ems
