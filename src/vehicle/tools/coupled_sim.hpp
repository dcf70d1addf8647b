// In-process lock-step coupling of VehicleModel and the map-based engine, exchanging signals
// once per macro step exactly like the ROS nodes do (Jacobi: each model receives the other's
// outputs of the previous exchange). Used by the vehicle_accel tool and the coupled tests.
#pragma once
#include <string>
#include <vector>

#include "engine_map/map_engine.hpp"
#include "vehicle/vehicle_model.hpp"

namespace hbt::vehicle {

class CoupledSim {
 public:
  CoupledSim(const VehicleParams& vp, const engine_map::MapEngineParams& ep,
             const std::string& base_dir = "")
      : veh_(withEngineIdle(vp, ep), base_dir), eng_(ep, base_dir) {}

  /// The vehicle's idle speed is the engine's (as the vehicle node reads it from engine_map.yaml).
  static VehicleParams withEngineIdle(VehicleParams vp, const engine_map::MapEngineParams& ep) {
    vp.driveline.idle_speed_rad_s = ep.idle_speed_rad_s;
    return vp;
  }

  /// Road grade (rise/run) vs the bus's own distance [m] (as the ROS vehicle participant).
  void setGradeProfile(const std::vector<double>& distance_m, const std::vector<double>& grade) {
    veh_.setGradeProfile(distance_m, grade);
  }

  /// Bus at speed v [m/s] in `gear` (0 = neutral) with the engine at idle (or k_g v).
  void reset(double v_m_s, int gear, double ambient_T_K = 293.15) {
    veh_.reset(v_m_s, gear, veh_.params().driveline.idle_speed_rad_s);
    vo_ = veh_.outputs();
    eng_.reset(vo_.engine_speed_rad_s, 0.0, ambient_T_K);
    eo_ = eng_.outputs();
    ambient_T_K_ = ambient_T_K;
    t_ = 0.0;
  }

  /// One macro step; `in` carries the driver targets / commands (engine fields are filled here).
  void step(double dt_s, VehicleInputs in) {
    in.engine_torque_Nm = eo_.brake_torque_Nm;
    in.engine_max_torque_Nm = eo_.max_torque_Nm;
    in.engine_min_torque_Nm = eo_.min_torque_Nm;
    in.ambient_T_K = ambient_T_K_;
    engine_map::MapEngineInputs ein;
    ein.speed_rad_s = vo_.engine_speed_rad_s;
    ein.torque_request_Nm = vo_.engine_torque_request_Nm;
    ein.ambient_T_K = ambient_T_K_;
    const VehicleOutputs vo = veh_.step(dt_s, in);
    const engine_map::MapEngineOutputs eo = eng_.step(dt_s, ein);
    vo_ = vo;
    eo_ = eo;
    t_ += dt_s;
  }

  const VehicleOutputs& vehicle() const { return vo_; }
  const engine_map::MapEngineOutputs& engine() const { return eo_; }
  const VehicleModel& vehicleModel() const { return veh_; }
  const engine_map::MapEngine& engineModel() const { return eng_; }
  double time() const { return t_; }

 private:
  VehicleModel veh_;
  engine_map::MapEngine eng_;
  VehicleOutputs vo_;
  engine_map::MapEngineOutputs eo_;
  double ambient_T_K_ = 293.15, t_ = 0.0;
};

}  // namespace hbt::vehicle
