// ROS bridge of the aftertreatment (DOC -> DPF -> SCR -> ASC): converts messages and parameters,
// nothing else. Model: hbt::aftertreatment::Aftertreatment (../aftertreatment.hpp).
//
// Inputs  (stamped t_k): /engine/exhaust (ExhaustState: mass flow, temperature, composition, NOx,
//                        HC, CO), /vehicle/to_cooling (VehicleToCooling: vehicle speed for the
//                        can's forced convection, ambient temperature).
// Outputs (stamped t_k): /aftertreatment/state (AftertreatmentState: back-pressure at the turbine
//                        outlet, brick temperatures, tailpipe NOx, NH3 slip, AdBlue, light-off,
//                        energy and NH3 balances).
// Parameters: private namespace = config/aftertreatment.yaml (AtsParams::declare);
// /scenario/ambient_temperature_c, /scenario/ambient_pressure_pa (tailpipe pressure).
// Initial state: cold start -- every brick (substrate, washcoat, can) at the scenario ambient
// temperature, the SCR store at scr_kinetics/initial_coverage (0 = empty), back-pressure =
// ambient pressure.
// Time stepping: the inputs of the macro steps are accumulated (time averages of the flows,
// mass-flow-weighted exhaust temperature and composition) and the model is advanced once every
// numerics/model_step_s; the state published between two model steps is the last one.
// Diagnostics (README "Diagnostics"): warning ats_below_light_off (the SCR not lit off --
// AftertreatmentState.light_off false -- for aftertreatment/light_off_grace_s without a break,
// config/diagnostics.yaml); key/values the CVODE steps of the SCR storage (in the window and in
// all), brick temperatures, conversion.
#pragma once
#include <hybrid_bus_twin/ExhaustState.h>
#include <hybrid_bus_twin/VehicleToCooling.h>

#include <memory>

#include "aftertreatment/aftertreatment.hpp"
#include "common/units.hpp"
#include "cosim/participant.hpp"

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
  void clearAccumulator();
  std::unique_ptr<Aftertreatment> model_;
  AtsParams params_;
  cosim::Input<hybrid_bus_twin::ExhaustState>* exhaust_ = nullptr;
  cosim::Input<hybrid_bus_twin::VehicleToCooling>* vehicle_ = nullptr;
  cosim::Output state_pub_;
  double ambient_T_K_ = 298.15;
  double ambient_p_Pa_ = units::kStandardAtmosphere_Pa;  // tailpipe pressure, /scenario/ambient_pressure_pa
  long cvode_steps_at_status_ = 0;  // SCR solver steps counted at the last status
  cosim::core::Warning* below_light_off_ = nullptr;
  // input accumulator over the macro steps of one model step
  double acc_t_ = 0.0, acc_m_ = 0.0, acc_mT_ = 0.0, acc_nox_ = 0.0, acc_hc_ = 0.0, acc_co_ = 0.0;
  double acc_yO2_ = 0.0, acc_yCO2_ = 0.0, acc_yH2O_ = 0.0, acc_T_ = 0.0, acc_v_ = 0.0, acc_Tamb_ = 0.0;
};

}  // namespace hbt::aftertreatment
