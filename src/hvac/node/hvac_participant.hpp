// ROS bridge of the HVAC: converts messages and parameters, nothing else. Model:
// hbt::hvac::HvacModel (../hvac_model.hpp).
//
// Inputs  (stamped t_k): /cooling/state (HT coolant temperature; heater_j differenced over this
//                        node's macro step = the mean heat the convectors delivered to the cabin),
//                        /vehicle/state (speed: doors open at a standstill; engine_on: the
//                        belt-driven A/C compressor turns).
// Output  (stamped t_k): /hvac/state (HvacState): the heating demand and cabin temperature the
//                        cooling participant's convectors serve, the auxiliary heater's heat into
//                        the HT coolant, the compressor and electric loads the vehicle books.
// Parameters: private namespace = config/hvac.yaml; /scenario/ambient_temperature_c,
// /scenario/ambient_pressure_pa, /scenario/payload_kg (the passengers), /scenario/start (cold:
// the cabin at ambient; warm: at the nearest set point).
// Diagnostics (docs/diagnostics.md): warning cabin_discomfort (the cabin more than
// diagnostics/band_K outside the set points for diagnostics/duration_s); key/values cabin
// temperature, heating demand, heater on, compressor power.
#pragma once
#include <hybrid_bus_twin/CoolingState.h>
#include <hybrid_bus_twin/VehicleState.h>

#include <memory>

#include "common/units.hpp"
#include "cosim/participant.hpp"
#include "hvac/hvac_model.hpp"
#include "hvac/hvac_warnings.hpp"

namespace hbt::hvac {

class HvacParticipant : public cosim::Participant {
 public:
  HvacParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void checkWarnings(cosim::core::Nanos t) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;

 private:
  std::unique_ptr<HvacModel> model_;
  HvacWarnings warnings_;  // diagnostics/ of config/hvac.yaml
  cosim::Input<hybrid_bus_twin::CoolingState>* cooling_ = nullptr;
  cosim::Input<hybrid_bus_twin::VehicleState>* vehicle_ = nullptr;
  cosim::Output state_pub_;
  double ambient_T_K_ = 298.15, ambient_p_Pa_ = units::kStandardAtmosphere_Pa;
  double heating_setpoint_K_ = 293.15, cooling_setpoint_K_ = 297.15;
  bool started_ = false;
  double prev_heater_J_ = 0.0;  // cooling's cumulative convector heat at the previous step [J]
  cosim::core::Warning* discomfort_ = nullptr;
};

}  // namespace hbt::hvac
