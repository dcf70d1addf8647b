#include "turbo/turbine.hpp"

#include <algorithm>
#include <cmath>

#include "common/units.hpp"

namespace hbt::turbo {

TurbineState TurbineEntry::evaluate(double p_in, double T_in, double p_out, double w) const {
  TurbineState s;
  p_in = std::max(p_in, 1.0);
  T_in = std::max(T_in, 1.0);
  p_out = std::max(p_out, 1.0);
  w = std::max(w, 0.0);
  const PerfectGas& g = map_.gas();
  const double sqT = std::sqrt(T_in);
  s.reduced_speed = units::radpsToRpm(w) / sqT;
  s.expansion_ratio = p_in / p_out;
  const TurbineMap::Point p = map_.at(s.reduced_speed, s.expansion_ratio);
  s.mfp = p.mfp;
  s.eta = p.eta;
  s.region = p.region;
  s.mass_flow_kg_s = share_ * p.mfp * (p_in * 1e-3) / sqT;
  const double dhs = s.expansion_ratio > 1.0
                         ? 1.0 - std::pow(s.expansion_ratio, -g.k())
                         : 0.0;
  s.power_W = s.mass_flow_kg_s * g.cp() * T_in * dhs * p.eta;
  s.outlet_total_temperature_K = T_in * (1.0 - p.eta * dhs);
  s.torque_Nm = w > 1.0 ? s.power_W / w : 0.0;
  return s;
}

double Wastegate::area(double opening) const { return std::clamp(opening, 0.0, 1.0) * a_max_; }

double Wastegate::massFlow(double p_in, double T_in, double p_out, double opening) const {
  const double a = area(opening);
  if (!(a > 0.0) || !(p_in > p_out)) return 0.0;
  T_in = std::max(T_in, 1.0);
  return cd_ * a * p_in / std::sqrt(gas_.R * T_in) * gas_.psi(p_out / p_in);
}

TwinEntryState TwinEntryTurbine::evaluate(double p1, double T1, double p2, double T2,
                                          double p_out, double w, double wg_opening) const {
  TwinEntryState s;
  s.entry[0] = e_[0].evaluate(p1, T1, p_out, w);
  s.entry[1] = e_[1].evaluate(p2, T2, p_out, w);
  s.wastegate_flow_kg_s = wg_.massFlow(p1, T1, p_out, wg_opening);
  s.power_W = s.entry[0].power_W + s.entry[1].power_W;
  s.torque_Nm = s.entry[0].torque_Nm + s.entry[1].torque_Nm;
  const double m0 = s.entry[0].mass_flow_kg_s, m1 = s.entry[1].mass_flow_kg_s;
  s.total_flow_kg_s = m0 + m1 + s.wastegate_flow_kg_s;
  // Equal c_p: the mixed total temperature is the flow-weighted mean.
  const double h = m0 * s.entry[0].outlet_total_temperature_K +
                   m1 * s.entry[1].outlet_total_temperature_K + s.wastegate_flow_kg_s * T1;
  s.outlet_mixed_temperature_K =
      s.total_flow_kg_s > 0.0 ? h / s.total_flow_kg_s : 0.5 * (T1 + T2);
  return s;
}

}  // namespace hbt::turbo
