#include "aftertreatment/soot_filter.hpp"

#include <algorithm>
#include <cmath>

#include "aftertreatment/gas.hpp"

namespace hbt::aftertreatment {

namespace {
constexpr double kM_per_nm = 1e-9;
constexpr double kM3_per_cm3 = 1e-6;
}  // namespace

SootFilter::SootFilter(const SootParams& p, int slices, double slice_volume_m3)
    : p_(p), n_(slices), V_slice_(slice_volume_m3), m_(slices, 0.0) {}

void SootFilter::setUniformLoad(double load_g_L) {
  m_.assign(n_, load_g_L * V_slice_);  // g/L == kg/m^3
}

double SootFilter::mass_kg() const {
  double m = 0.0;
  for (double x : m_) m += x;
  return m;
}

double SootFilter::load_g_L() const { return mass_kg() / (V_slice_ * n_); }

double SootFilter::specificRate_1_s(double T, double c) const {
  const double A = p_.no2_A_nm_cm3_K05_s * kM_per_nm * kAvogadro * kM3_per_cm3;  // m/s per mol/m^3
  return 3.0 / p_.primary_particle_diameter_m * A * std::sqrt(T) * c * std::exp(-p_.no2_E_J_mol / (kRu * T));
}

SootStep SootFilter::step(double dt, double co2_kg_s, double n_NO2, double n_tot, double p,
                          const double* T, double* qr) {
  SootStep r;
  const double soot_in = p_.engine_out_g_per_kg_co2 * 1e-3 * co2_kg_s * dt;  // [kg]
  r.captured_kg = p_.filtration_efficiency * soot_in;
  r.slip_kg = soot_in - r.captured_kg;
  const double deposit = r.captured_kg / n_;
  const double s = p_.co2_selectivity;
  const double nu = 1.0 + s;                                 // NO2 per C
  const double dH = s * kDH_C_2NO2 + (1.0 - s) * kDH_C_NO2;  // J per mol C
  double no2_out = 0.0;
  for (int i = 0; i < n_; ++i) {
    qr[i] = 0.0;
    const double F = n_NO2 / n_;  // NO2 through this slice's wall [mol/s]
    double burnt_mol = 0.0;       // carbon [mol] over the step
    if (F > 0.0 && n_tot > 0.0 && m_[i] > 0.0) {
      const double Vdot = n_tot / n_ * kRu * T[i] / p;        // [m^3/s]
      const double k_per_c = specificRate_1_s(T[i], 1.0);   // k_m / c [m^3/(mol s)]
      const double kappa = nu * k_per_c * m_[i] / (kM_C * Vdot);
      burnt_mol = std::min(-F * std::expm1(-kappa) / nu * dt, (m_[i] + deposit) / kM_C);
    }
    m_[i] = std::max(0.0, m_[i] + deposit - burnt_mol * kM_C);
    no2_out += F - nu * burnt_mol / dt;
    r.no2_consumed_mol += nu * burnt_mol;
    r.carbon_co2_mol += s * burnt_mol;
    r.carbon_co_mol += (1.0 - s) * burnt_mol;
    qr[i] = burnt_mol * dH / dt;
  }
  r.n_NO2_out_mol_s = std::max(0.0, no2_out);
  return r;
}

}  // namespace hbt::aftertreatment
