// ROS bridge of the 48 V battery: converts messages and parameters, nothing else. Model:
// hbt::battery::BatteryModel (../battery_model.hpp).
//
// Input  (held-value rule, cosim/participant.hpp): /emachine/state (EMachineState:
//        electrical_power_w = DC power drawn from the battery [W], < 0 charging). The battery
//        runs at the e-machine's macro step (0.01 s) in a later Gauss-Seidel group: at step
//        t_k -> t_k + P it reads the e-machine's message stamped t_k + P, i.e. the DC power of the
//        e-machine's own step [t_k, t_k + P], and books exactly that energy (V_t I = P over the
//        step). In the same group (Jacobi) it would book the previous step's power instead.
//        The terminal power request is electrical_power_w + the vehicle's DC/DC input for the
//        24 V consumers (/vehicle/state dcdc_power_w, its auxiliary set; group 1, fresh) + the
//        pack's own ventilation fans (the model adds them). /vehicle/state speed_m_s = the air speed
//        over the (roof-mounted) housing.
// Output (stamped t_k + P): /battery/state (BatteryState): terminal voltage, current, SOC, cell
//        temperature, power limits for the next step, losses, cumulative energy bookkeeping.
//        A request beyond the power limits is delivered at the limit (request_limited,
//        unmet_power_w); the EMS is expected to respect discharge/charge_power_limit_w.
// Parameters: private namespace = config/battery.yaml (cell/table_file resolved against the
// package root, cosim::resolvePackagePath); /scenario/battery_pack (launch argument pack): a file
// config/battery_pack/<name>.yaml replacing the groups pack/ and housing/;
// /scenario/ambient_temperature_c = the air around the housing, constant (initial state: cells
// and housing at ambient, cold start; SOC = pack/initial_soc).
// Diagnostics (docs/diagnostics.md): warning battery_limited (request_limited for
// diagnostics/duration_s of config/battery.yaml); key/values SOC, cell temperature, power limits,
// time limited.
#pragma once
#include <hybrid_bus_twin/EMachineState.h>
#include <hybrid_bus_twin/VehicleState.h>

#include <memory>

#include "battery/battery_model.hpp"
#include "cosim/participant.hpp"
#include "battery/battery_warnings.hpp"

namespace hbt::battery {

class BatteryParticipant : public cosim::Participant {
 public:
  BatteryParticipant(ros::NodeHandle nh, ros::NodeHandle pnh) : Participant(nh, pnh) {}

 protected:
  void configure() override;
  void publishOutputs(const ros::Time& t) override;
  void step(const ros::Time& t, double dt_s) override;
  void checkWarnings(cosim::core::Nanos t) override;
  void diagnosticValues(cosim::core::Nanos t, std::vector<cosim::core::KeyValue>& kv) override;

 private:
  void readPackSet(BatteryParams& p);
  std::unique_ptr<BatteryModel> model_;
  cosim::Input<hybrid_bus_twin::EMachineState>* emachine_ = nullptr;
  cosim::Input<hybrid_bus_twin::VehicleState>* vehicle_ = nullptr;  // DC/DC load of the 24 V consumers
  cosim::Output state_pub_;
  double ambient_T_K_ = 298.15, dcdc_power_W_ = 0.0;  // last step's DC/DC load [W]
  cosim::core::Warning* limited_ = nullptr;
};

}  // namespace hbt::battery
