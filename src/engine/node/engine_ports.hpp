// The engine participant's topics: its closed-loop inputs from the thermal nodes and its three
// output messages filled from the model-neutral engine::EngineOutputs (SI, engine_model.hpp).
#pragma once
#include <hybrid_bus_twin/AftertreatmentState.h>
#include <boost/make_shared.hpp>
#include <hybrid_bus_twin/CoolingState.h>
#include <hybrid_bus_twin/EngineHeat.h>
#include <hybrid_bus_twin/EngineState.h>
#include <hybrid_bus_twin/ExhaustState.h>
#include <ros/ros.h>

#include "cosim/output.hpp"

#include "cosim/input_buffer.hpp"
#include "engine_interface/engine_model.hpp"

namespace hbt::engine {

/// The engine's closed loops with the thermal nodes: coolant and oil temperature from /cooling/state and
/// turbine-outlet back-pressure from /aftertreatment/state, each read (stamped t_k) only when the
/// scenario runs that participant. Without them 0 = none (the model's own defaults).
struct EngineLoopInputs {
  cosim::Input<hybrid_bus_twin::CoolingState>* cooling = nullptr;
  cosim::Input<hybrid_bus_twin::AftertreatmentState>* aftertreatment = nullptr;
  double coolantAt(const ros::Time& t) const {
    return cooling ? cooling->at(t).coolant_ht_temperature_k : 0.0;
  }
  double oilAt(const ros::Time& t) const {
    return cooling ? cooling->at(t).oil_temperature_k : 0.0;
  }
  double backPressureAt(const ros::Time& t) const {
    return aftertreatment ? aftertreatment->at(t).back_pressure_pa : 0.0;
  }
};

/// Publishers of /engine/state, /engine/exhaust, /engine/heat (advertised by the participant
/// through Participant::addOutput so that the step protocol knows them).
class EnginePorts {
 public:
  EnginePorts() = default;
  EnginePorts(cosim::Output state, cosim::Output exhaust, cosim::Output heat)
      : state_(std::move(state)), exhaust_(std::move(exhaust)), heat_(std::move(heat)) {}
  void publish(const ros::Time& t, const EngineOutputs& v) const {
    hybrid_bus_twin::EngineState s;
    s.header.stamp = t;
    s.engine_speed_rad_s = v.speed_rad_s;
    s.brake_torque_nm = v.brake_torque_Nm;
    s.torque_max_nm = v.max_torque_Nm;
    s.torque_min_nm = v.min_torque_Nm;
    s.fuel_mass_flow_kg_s = v.fuel_mass_flow_kg_s;
    s.fuel_mass_kg = v.fuel_mass_kg;
    s.positive_work_j = v.positive_work_J;
    s.motoring_work_j = v.motoring_work_J;
    s.boost_pressure_pa = v.boost_pressure_Pa;
    s.charge_air_temperature_k = v.charge_air_T_K;
    s.turbo_speed_rad_s = v.turbo_speed_rad_s;
    s.lambda = v.lambda;
    s.coolant_temperature_k = v.coolant_T_K;
    s.oil_temperature_k = v.oil_T_K;
    s.back_pressure_pa = v.back_pressure_Pa;
    s.friction_correction_nm = v.friction_correction_Nm;
    s.pumping_correction_nm = v.pumping_correction_Nm;
    state_.publish(boost::make_shared<hybrid_bus_twin::EngineState>(s));
    hybrid_bus_twin::ExhaustState x;
    x.header.stamp = t;
    x.mass_flow_kg_s = v.exhaust_mass_flow_kg_s;
    x.temperature_k = v.exhaust_T_K;
    x.y_o2 = v.y_O2;
    x.y_co2 = v.y_CO2;
    x.y_h2o = v.y_H2O;
    x.y_n2 = v.y_N2;
    x.nox_mass_flow_kg_s = v.nox_mass_flow_kg_s;
    x.nox_mass_kg = v.nox_mass_kg;
    x.mass_kg = v.exhaust_mass_kg;
    x.mass_temperature_kg_k = v.exhaust_mass_T_kg_K;
    x.temperature_time_k_s = v.exhaust_T_time_K_s;
    x.o2_mass_kg = v.o2_mass_kg;
    x.co2_mass_kg = v.co2_mass_kg;
    x.h2o_mass_kg = v.h2o_mass_kg;
    exhaust_.publish(boost::make_shared<hybrid_bus_twin::ExhaustState>(x));
    hybrid_bus_twin::EngineHeat h;
    h.header.stamp = t;
    h.heat_to_coolant_w = v.heat_to_coolant_W;
    h.heat_to_coolant_j = v.heat_to_coolant_J;
    h.heat_to_oil_w = v.heat_to_oil_W;
    h.heat_to_oil_j = v.heat_to_oil_J;
    h.coolant_pump_speed_rad_s = v.speed_rad_s;  // mechanical pump driven 1:1 by the crank
    h.coolant_pump_angle_rad = v.crank_angle_rad;
    heat_.publish(boost::make_shared<hybrid_bus_twin::EngineHeat>(h));
  }

 private:
  cosim::Output state_, exhaust_, heat_;
};

}  // namespace hbt::engine
