#include "cylinder/losses.hpp"

#include "common/oil_viscosity.hpp"
#include "common/units.hpp"

#include <algorithm>
#include <cmath>

namespace hbt::cylinder {

double woschniCoefficient(double B, double p_Pa, double T, double w, double C0) {
  // pow(x, e) = exp(e ln x): one log per factor; w and p are positive here.
  return C0 * std::exp(-0.2 * std::log(B) + 0.8 * std::log(p_Pa * 1e-3 * std::max(w, 1e-6)) -
                       0.55 * std::log(T));
}

double hohenbergCoefficient(double V, double p_Pa, double T, double cm, double C_H) {
  return C_H * std::exp(-0.06 * std::log(V) + 0.8 * std::log(p_Pa * 1e-5) - 0.4 * std::log(T) +
                        0.8 * std::log(cm + 1.4));
}

double WoschniParams::velocity(bool gas_exchange, bool combustion, double cm, double B, double S,
                               double Vd, double Tr, double pr, double Vr, double p,
                               double pmot) const {
  const double cu_cm = swirl_ratio * units::kPi * B / (2.0 * S);
  const double C1 = gas_exchange ? 6.18 + 0.417 * cu_cm : 2.28 + 0.308 * cu_cm;
  double w = C1 * cm;
  if (combustion && !gas_exchange) w += C2_m_sK * Vd * Tr / (pr * Vr) * std::max(p - pmot, 0.0);
  return w;
}

void WallTemperatures::evaluate(double Tc, double load, double& head, double& liner,
                                double& piston) const {
  const double L = std::clamp(load, 0.0, 1.2);
  head = Tc + head_dT0_K + head_dTload_K * L;
  liner = Tc + liner_dT0_K + liner_dTload_K * L;
  piston = Tc + piston_dT0_K + piston_dTload_K * L;
}

double ChenFlynn::viscosityFactor(double Tc) const {
  return oilViscosityFactor(Tc + oil_minus_coolant_K, T_oil_ref_K, vogel_b_K, vogel_c_K, visc_exponent);
}

double ChenFlynn::fmep_Pa(double pmax_Pa, double cm, double Tc) const {
  return fmepAtOil_Pa(pmax_Pa, cm, Tc + oil_minus_coolant_K);
}

double ChenFlynn::fmepAtOil_Pa(double pmax_Pa, double cm, double T_oil) const {
  const double bar = A_bar + B * pmax_Pa * 1e-5 + C_bar_s_m * cm + D_bar_s2_m2 * cm * cm;
  return bar * 1e5 * oilViscosityFactor(T_oil, T_oil_ref_K, vogel_b_K, vogel_c_K, visc_exponent);
}

}  // namespace hbt::cylinder
