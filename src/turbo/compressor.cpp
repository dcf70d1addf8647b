#include "turbo/compressor.hpp"

#include <algorithm>
#include <cmath>

#include "common/units.hpp"

namespace hbt::turbo {

Compressor::Compressor(CompressorMap map, double p_ref_Pa, double T_ref_K, PerfectGas gas)
    : map_(std::move(map)), p_ref_(p_ref_Pa), t_ref_(T_ref_K), gas_(gas) {}

CompressorState Compressor::evaluate(double p_in, double T_in, double p_out, double w) const {
  CompressorState s;
  p_in = std::max(p_in, 1.0);
  T_in = std::max(T_in, 1.0);
  p_out = std::max(p_out, 0.0);
  w = std::max(w, 0.0);
  const double theta = T_in / t_ref_;
  s.corrected_speed_rpm = units::radpsToRpm(w) / std::sqrt(theta);
  s.pressure_ratio = p_out / p_in;
  const CompressorMap::Point p = map_.atPressureRatio(s.corrected_speed_rpm, s.pressure_ratio);
  s.corrected_flow_kg_s = p.flow_kg_s;
  s.mass_flow_kg_s = p.flow_kg_s * (p_in / p_ref_) / std::sqrt(theta);
  s.eta = p.eta;
  s.region = p.region;
  s.outlet_total_temperature_K = T_in * (1.0 + p.work);
  s.power_W = s.mass_flow_kg_s * gas_.cp() * T_in * p.work;
  s.torque_Nm = w > 1.0 ? s.power_W / w : 0.0;
  return s;
}

}  // namespace hbt::turbo
