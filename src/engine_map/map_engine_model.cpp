#include "engine_map/map_engine_model.hpp"

#include <cstdio>

#include "common/units.hpp"

namespace hbt::engine_map {

MapEngineModel::MapEngineModel(const MapEngineParams& p, const std::string& base_dir)
    : engine_(p, base_dir) {}

void MapEngineModel::resetModel(const engine::EngineInputs& in) {
  engine_.reset(in.speed_rad_s, 0.0, in.ambient_T_K, in.ambient_p_Pa);
  copyOutputs(in.speed_rad_s);
}

void MapEngineModel::stepModel(double dt_s, const engine::EngineInputs& in) {
  MapEngineInputs m;
  m.speed_rad_s = in.speed_rad_s;
  m.torque_request_Nm = in.torque_request_Nm;
  m.ambient_T_K = in.ambient_T_K;
  m.ambient_p_Pa = in.ambient_p_Pa;
  m.fuel_enabled = in.fuel_enabled;
  m.oil_T_K = in.oil_T_K;  // the cold-oil friction (the coolant temperature is not used)
  m.back_pressure_Pa = in.back_pressure_Pa;
  engine_.step(dt_s, m);
  copyOutputs(in.speed_rad_s);
}

void MapEngineModel::copyOutputs(double w) {
  const MapEngineOutputs& o = engine_.outputs();
  engine::EngineOutputs& v = out_;
  v.brake_torque_Nm = o.brake_torque_Nm;
  const double dT = o.friction_correction_Nm + o.pumping_correction_Nm;  // cold oil + back-pressure
  v.max_torque_Nm = engine_.fullLoadTorque(w) - dT;
  v.min_torque_Nm = engine_.motoringTorque(w) - dT;
  v.friction_correction_Nm = o.friction_correction_Nm;
  v.pumping_correction_Nm = o.pumping_correction_Nm;
  v.fuel_mass_flow_kg_s = o.fuel_mass_flow_kg_s;
  v.fuel_mass_kg = o.fuel_mass_kg;
  v.positive_work_J = o.positive_work_J;
  v.motoring_work_J = o.motoring_work_J;
  v.boost_pressure_Pa = o.gas.boost_pressure_Pa;
  v.charge_air_T_K = o.gas.intake_manifold_T_K;
  v.turbo_speed_rad_s = 0.0;  // no turbocharger in the map model
  v.lambda = o.gas.lambda;
  v.exhaust_mass_flow_kg_s = o.gas.exhaust_mass_flow_kg_s;
  v.exhaust_T_K = o.gas.exhaust_T_K;
  v.y_O2 = o.gas.comp.y_O2;
  v.y_CO2 = o.gas.comp.y_CO2;
  v.y_H2O = o.gas.comp.y_H2O;
  v.y_N2 = o.gas.comp.y_N2;
  v.nox_mass_flow_kg_s = o.gas.nox_mass_flow_kg_s;
  v.nox_mass_kg = o.nox_mass_kg;
  v.heat_to_coolant_W = o.gas.metal_heat_W;
  v.heat_to_coolant_J = o.metal_heat_J;
  v.heat_to_oil_W = o.gas.oil_heat_W;
  v.heat_to_oil_J = o.oil_heat_J;
  v.friction_W = o.gas.friction_W;
}

bool MapEngineModel::boostLimited(double m) const {
  const MapEngineOutputs& o = engine_.outputs();
  return inputs().torque_request_Nm > o.dynamic_max_torque_Nm + m &&
         o.dynamic_max_torque_Nm < o.max_torque_Nm - m;
}

std::string MapEngineModel::boostLimitedMessage(double duration_s) const {
  const MapEngineOutputs& o = engine_.outputs();
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "torque request %.0f Nm above the PT1 (turbo build-up) limit %.0f Nm, full load %.0f Nm, "
                "at %.0f rpm for %.1f s", inputs().torque_request_Nm, o.dynamic_max_torque_Nm,
                o.max_torque_Nm, units::radpsToRpm(inputs().speed_rad_s), duration_s);
  return buf;
}

void MapEngineModel::diagnosticValues(std::vector<engine::EngineDiagnosticValue>& kv) {
  using K = engine::EngineDiagnosticValue::Kind;
  const MapEngineOutputs& o = engine_.outputs();
  kv.push_back({"dynamic_full_load_nm", o.dynamic_max_torque_Nm, K::kNumber});
  kv.push_back({"full_load_nm", o.max_torque_Nm, K::kNumber});
  kv.push_back({"fuel_cut", o.fuel_cut ? 1.0 : 0.0, K::kFlag});
}

}  // namespace hbt::engine_map
