// ROS bridge of the aftertreatment (DOC -> DPF -> SCR -> ASC): converts messages and parameters,
// nothing else. Model: hbt::aftertreatment::Aftertreatment (../aftertreatment.hpp).
//
// Inputs  (held at t_k): /engine/exhaust (ExhaustState: cumulative exhaust mass, enthalpy-like
//                        mass x temperature, species and NOx totals; point values for the first
//                        step), /vehicle/to_cooling (VehicleToCooling: distance for the mean
//                        vehicle speed -- the can's forced convection --, ambient temperature).
// Outputs (stamped t_k + P): /aftertreatment/state (AftertreatmentState: back-pressure at the
//                        turbine outlet, brick and exhaust-line wall temperatures, tailpipe NOx,
//                        NH3 slip, AdBlue, light-off, DPF soot, energy, NH3 and soot balances).
// Parameters: private namespace = config/aftertreatment.yaml (AtsParams::declare; the macro step
// P = cosim/macro_step_s, 0.1 s: a thermal node); /scenario/ambient_temperature_c,
// /scenario/ambient_pressure_pa (tailpipe pressure).
// Initial state: cold start -- every brick (substrate, washcoat, can) and every exhaust-line wall
// at the scenario ambient temperature, the SCR store at scr_kinetics/initial_coverage (0 =
// empty), the DPF at dpf_flow/soot_load_g_L, back-pressure = ambient pressure.
// Time stepping: one model step per macro step P, fed the exact means of the 10 ms producers over
// the last P from their cumulative totals (../step_inputs.hpp).
// Diagnostics (docs/diagnostics.md): warning ats_below_light_off (the SCR not lit off --
// AftertreatmentState.light_off false -- for diagnostics/light_off_grace_s of config/aftertreatment.yaml
// without a break); key/values the Runge-Kutta steps of the SCR storage (in the window and in
// all), brick temperatures, conversion.
#pragma once
#include <hybrid_bus_twin/AftertreatmentState.h>
#include <hybrid_bus_twin/ExhaustState.h>
#include <hybrid_bus_twin/VehicleToCooling.h>

#include <memory>

#include "aftertreatment/aftertreatment.hpp"
#include "aftertreatment/step_inputs.hpp"
#include "common/units.hpp"
#include "cosim/participant.hpp"
#include "aftertreatment/aftertreatment_warnings.hpp"

namespace hbt::aftertreatment {

class AftertreatmentParticipant : public cosim::Participant {
 public:
  AftertreatmentParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void checkWarnings(cosim::core::Nanos t) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;

 private:
  /// The exhaust-line wall temperatures and the DPF soot fields of the state message.
  void publishLineAndSoot(hybrid_bus_twin::AftertreatmentState& s) const;
  std::unique_ptr<Aftertreatment> model_;
  AtsParams params_;
  AftertreatmentWarnings warnings_;  // diagnostics/ of config/aftertreatment.yaml
  cosim::Input<hybrid_bus_twin::ExhaustState>* exhaust_ = nullptr;
  cosim::Input<hybrid_bus_twin::VehicleToCooling>* vehicle_ = nullptr;
  cosim::Output state_pub_;
  double ambient_T_K_ = 298.15;
  double ambient_p_Pa_ = units::kStandardAtmosphere_Pa;  // tailpipe pressure, /scenario/ambient_pressure_pa
  long scr_steps_at_status_ = 0;  // SCR solver steps counted at the last status
  cosim::core::Warning* below_light_off_ = nullptr;
  StepInputs inputs_;  // step means from the producers' cumulative totals
};

}  // namespace hbt::aftertreatment
