#include "cooling/radiator.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/errors.hpp"

namespace hbt::cooling {

double effectivenessCrossflowUnmixed(double ntu, double cr) {
  if (!(ntu > 0.0)) return 0.0;
  if (cr < 1e-12) return 1.0 - std::exp(-ntu);
  return 1.0 - std::exp(std::pow(ntu, 0.22) / cr * (std::exp(-cr * std::pow(ntu, 0.78)) - 1.0));
}

double ntuCrossflowUnmixed(double eps, double cr) {
  double lo = 0.0, hi = 50.0;
  if (!(eps >= 0.0) || eps >= effectivenessCrossflowUnmixed(hi, cr))
    throw std::domain_error("effectiveness not reachable");
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (effectivenessCrossflowUnmixed(mid, cr) < eps ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

Radiator::Radiator(const RadiatorRating& r, double air_cp_J_kgK, double coolant_cp_J_kgK,
                   const std::string& file, const std::string& key_prefix)
    : r_(r), cp_air_(air_cp_J_kgK), cp_cool_(coolant_cp_J_kgK) {
  const double ca = r.air_mass_flow_kg_s * cp_air_, cc = r.coolant_mass_flow_kg_s * cp_cool_;
  const double cmin = std::min(ca, cc), cmax = std::max(ca, cc);
  const double dT = r.coolant_in_K - r.air_in_K;
  if (!(dT > 0.0))
    throw InputError(file, key_prefix + "rated_coolant_in_K", "must be above the rated air inlet");
  const double eps = r.heat_W / (cmin * dT);
  double ntu = 0.0;
  try {
    ntu = ntuCrossflowUnmixed(eps, cmin / cmax);
  } catch (const std::domain_error&) {
    throw InputError(file, key_prefix + "rated_heat_W",
                     "needs effectiveness " + std::to_string(eps) +
                         ", not reachable at the rated flows and temperatures");
  }
  ua_ref_ = ntu * cmin;
  hA_air_ref_ = ua_ref_ / r.air_side_resistance_fraction;
  hA_cool_ref_ = ua_ref_ / (1.0 - r.air_side_resistance_fraction);
}

double Radiator::ua_W_K(double ma, double mc) const {
  if (!(ma > 0.0) || !(mc > 0.0)) return 0.0;
  const double ha = hA_air_ref_ * std::pow(ma / r_.air_mass_flow_kg_s, r_.air_flow_exponent);
  const double hc = hA_cool_ref_ * std::pow(mc / r_.coolant_mass_flow_kg_s, r_.coolant_flow_exponent);
  return 1.0 / (1.0 / ha + 1.0 / hc);
}

double Radiator::conductance_W_K(double ma, double mc) const {
  const double ua = ua_W_K(ma, mc);
  if (ua <= 0.0) return 0.0;
  const double ca = ma * cp_air_, cc = mc * cp_cool_;
  const double cmin = std::min(ca, cc), cmax = std::max(ca, cc);
  return effectivenessCrossflowUnmixed(ua / cmin, cmin / cmax) * cmin;
}

}  // namespace hbt::cooling
