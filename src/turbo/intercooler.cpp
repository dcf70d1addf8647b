#include "turbo/intercooler.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace hbt::turbo {

Intercooler::Intercooler(const IntercoolerParams& p, const std::string& source,
                         const std::string& kp)
    : p_(p) {
  const std::string kx = kp + "effectiveness_flow_kg_s", ky = kp + "effectiveness";
  if (p.effectiveness.empty() || p.effectiveness.size() != p.effectiveness_flow_kg_s.size())
    throw InputError(source, ky, "needs one value per entry of " + kx);
  for (double e : p.effectiveness)
    if (!(e >= 0.0 && e <= 1.0)) throw InputError(source, ky, "values must be in [0,1]");
  std::vector<double> x = p.effectiveness_flow_kg_s, y = p.effectiveness;
  if (x.size() == 1) {  // constant effectiveness
    x.push_back(x[0] + 1.0);
    y.push_back(y[0]);
  }
  eps_ = Table1D(x, y, source, kx);
  if (!(p.dp_ref_flow_kg_s > 0.0) || !(p.dp_ref_temperature_K > 0.0) ||
      !(p.dp_ref_pressure_Pa > 0.0) || !(p.dp_ref_Pa >= 0.0))
    throw InputError(source, kp + "dp_ref_Pa", "reference point must be positive");
  K_ = p.dp_ref_Pa * p.dp_ref_pressure_Pa /
       (p.dp_ref_flow_kg_s * p.dp_ref_flow_kg_s * p.dp_ref_temperature_K);
}

double Intercooler::effectiveness(double m) const {
  return std::clamp(eps_(std::max(m, 0.0)), 0.0, 1.0);
}

double Intercooler::outletTemperature(double T_in, double T_amb, double m) const {
  const double Tc = T_amb + p_.cooling_air_offset_K;
  return T_in - effectiveness(m) * (T_in - Tc);
}

double Intercooler::pressureDrop(double m, double T_in, double p_in) const {
  if (!(p_in > 0.0)) return 0.0;
  return K_ * m * m * std::max(T_in, 0.0) / p_in;
}

double Intercooler::massFlowForDrop(double dp, double T_in, double p_in) const {
  if (!(dp > 0.0) || !(T_in > 0.0) || !(K_ > 0.0)) return 0.0;
  return std::sqrt(dp * std::max(p_in, 0.0) / (K_ * T_in));
}

}  // namespace hbt::turbo
