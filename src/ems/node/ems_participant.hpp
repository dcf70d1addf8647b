// ROS bridge of the energy manager (hybrid only): converts messages and parameters, nothing else.
// Model: hbt::ems::EmsModel (../ems_model.hpp); its engine model is the VECTO map engine's steady
// fuel map (config/engine_map.yaml, as a real EMS carries a calibrated map whatever the plant is).
//
// Sits in the second Gauss-Seidel group (vehicle -> EMS -> engine, e-machine -> battery):
// Inputs: /vehicle/driver_demand (DriverDemand, fresh: stamped t_k + P, the demand for the next
//         step), /vehicle/state (the DC/DC's draw of this step, which the battery adds to the
//         e-machine's), /emachine/state (temperatures for the live torque limits), /battery/state
//         (SOC, T, power limits, terminal voltage),
//         /cooling/state (HT coolant) and /aftertreatment/state (SCR brick) when those
//         participants run (else the engine and ATS count as warm); /hvac/state
//         (engine_run_request: the belt-driven A/C needs the engine, no stop) when the hvac runs.
// Outputs (stamped t_k + P): /ems/command (EmsCommand: split, mode and reason, for the e-machine,
//         the vehicle and the bag), /ems/engine_command (EngineCommand for the engine node).
// Parameters: private namespace = config/ems.yaml; the map engine and the e-machine YAML of the
//         scenario's config folder (cosim::scenarioConfigFile), the controller's models of both.
//         Stop-start runs with either engine model.
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
#include <hybrid_bus_twin/VehicleState.h>

#include <memory>

#include "cosim/participant.hpp"
#include "emachine/emachine_model.hpp"
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

/// The controller's e-machine limit model: the e-machine model of the scenario's emachine.yaml
/// (its live limits, the function the e-machine clamps with).
class MachineLimitModel : public EmLimitModel {
 public:
  explicit MachineLimitModel(std::unique_ptr<emachine::EMachineModel> m) : m_(std::move(m)) {}
  void liveLimits(double w, double V, double T_w, double T_m, double& max_Nm, double& min_Nm) const override {
    const emachine::CrankLimits c = m_->limits(w, V, T_w, T_m);
    max_Nm = c.max_live;
    min_Nm = c.min_live;
  }
  double dcPower_W(double T, double w, double V, double T_w, double T_m) const override {
    return m_->dcPower(T, w, V, T_w, T_m);
  }

 private:
  std::unique_ptr<emachine::EMachineModel> m_;
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
  std::unique_ptr<emachine::EMachineModel> emachineModel() const;
  std::unique_ptr<MapFuelModel> fuel_;
  std::unique_ptr<MachineLimitModel> em_limits_;
  std::unique_ptr<EmsModel> model_;
  cosim::Input<hybrid_bus_twin::DriverDemand>* demand_ = nullptr;
  cosim::Input<hybrid_bus_twin::VehicleState>* vehicle_ = nullptr;
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
