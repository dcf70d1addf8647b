#include "aftertreatment/scr_storage.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "aftertreatment/gas.hpp"
#include "common/dormand_prince.hpp"
#include "common/errors.hpp"

namespace hbt::aftertreatment {

namespace {
constexpr double kDH_std = 407.1e3;   // J per mol NO (standard SCR)
constexpr double kDH_fast = 757.0e3;  // J per fast-SCR event
constexpr double kDH_no2 = 455.5e3;   // J per mol NO2 (NO2 SCR)
constexpr double kDH_ox = 316.8e3;    // J per mol NH3 oxidised
}  // namespace

ScrStorage::ScrStorage(const ScrKinetics& k, int slices, double Vs, double rtol, double atol_theta,
                       int max_steps)
    : k_(k), n_(slices), Vs_(Vs), rtol_(rtol), atol_theta_(atol_theta),
      max_steps_(max_steps), theta_(slices, 0.0), Vdot_(slices), kd_(slices), bT_(slices),
      kstd_(slices), kfast_(slices), kno2_(slices), kox_(slices), scratch_(slices),
      q_(slices + 5, 0.0) {
  rk_ = std::make_unique<DormandPrince>("aftertreatment SCR", n_, n_ + 5, rtol_,
                                        std::vector<double>(n_, atol_theta_), max_steps_);
}

ScrStorage::~ScrStorage() = default;

void ScrStorage::setCoverage(double theta) {
  std::fill(theta_.begin(), theta_.end(), theta);
  rk_->reset();
}

double ScrStorage::storedMol() const {
  double s = 0.0;
  for (double t : theta_) s += t;
  return s * k_.omega_mol_m3 * Vs_;
}

double ScrStorage::equilibriumCoverage(double T, double c) const {
  // f(theta) = k_ads c (1 - theta) - k_des exp(-E (1 - alpha theta)/RT) theta: decreasing and
  // concave on [0, 1], f(0) >= 0 >= f(1). Newton kept inside the bracket [lo, hi] (a step leaving
  // it bisects instead); stops when the step is below 1e-15.
  const double kd = k_.k_des * std::exp(-k_.E_des / (kRu * T));
  const double b = k_.E_des * k_.alpha / (kRu * T);
  const double ka = k_.k_ads * c;
  double lo = 0.0, hi = 1.0, th = 0.0;
  for (int it = 0; it < 100; ++it) {
    const double e = kd * std::exp(b * th);
    const double f = ka * (1.0 - th) - e * th;
    if (f == 0.0) return th;
    (f > 0.0 ? lo : hi) = th;
    const double df = -ka - e * (1.0 + b * th);  // < 0
    double next = th - f / df;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - th) <= 1e-15) return next;
    th = next;
  }
  return th;
}

void ScrStorage::rhs(const double* y, double* yd, double* qd, double* out) const {
  const double Om = k_.omega_mol_m3;
  double nNH3 = in_.n_NH3_mol_s, nNO = in_.n_NO_mol_s, nNO2 = in_.n_NO2_mol_s;
  double sum_std = 0.0, sum_fast = 0.0, sum_no2 = 0.0, sum_ox = 0.0;
  for (int i = 0; i < n_; ++i) {
    const double th = std::clamp(y[i], 0.0, 1.0);
    const double V = Vdot_[i];
    const double r_des = kd_[i] * std::exp(bT_[i] * th) * Om * th;
    const double kads = k_.k_ads * Om * (1.0 - th);
    // NH3 (quasi-steady CSTR); with V = 0 the slice gas is at local equilibrium.
    const double den = V + Vs_ * kads;
    const double c3 = den > 0.0 ? (nNH3 + Vs_ * r_des) / den : 0.0;
    const double r_ads = kads * c3;
    // NO / NO2: A c1^2 + B c1 + C = 0 (see header)
    // NO / NO2 with W = V + e:  (V+a) b c1^2 + [(V+a) W + b V (c2in - c1in)] c1 - V W c1in = 0,
    // c2 = V c2in / (W + b c1)
    const double a = Vs_ * kstd_[i] * Om * th, b = Vs_ * kfast_[i] * Om * th;
    const double W = V + Vs_ * kno2_[i] * Om * th;
    double c1 = 0.0, c2 = 0.0;
    if (V > 0.0) {
      const double c1in = nNO / V, c2in = nNO2 / V;
      const double A2 = (V + a) * b, B2 = (V + a) * W + b * V * (c2in - c1in);
      const double C2 = V * W * c1in;  // = -C of the quadratic
      const double disc = std::sqrt(std::max(0.0, B2 * B2 + 4.0 * A2 * C2));
      c1 = (C2 > 0.0) ? 2.0 * C2 / (B2 + disc) : 0.0;
      c2 = V * c2in / (W + b * c1);
    }
    const double r_std = kstd_[i] * c1 * Om * th;
    const double r_fast = kfast_[i] * c1 * c2 * Om * th;
    const double r_no2 = kno2_[i] * c2 * Om * th;
    const double r_ox = kox_[i] * Om * th;
    if (yd) yd[i] = (r_ads - r_des - r_std - 2.0 * r_fast - (4.0 / 3.0) * r_no2 - r_ox) / Om;
    sum_std += Vs_ * r_std;
    sum_fast += Vs_ * r_fast;
    sum_no2 += Vs_ * r_no2;
    sum_ox += Vs_ * r_ox;
    if (qd) qd[5 + i] = Vs_ * (r_std * kDH_std + r_fast * kDH_fast + r_no2 * kDH_no2 + r_ox * kDH_ox);
    nNH3 = V * c3;
    nNO = V * c1;
    nNO2 = V * c2;
  }
  if (qd) {
    qd[0] = nNH3;
    qd[1] = sum_std;
    qd[2] = sum_fast;
    qd[3] = sum_no2;
    qd[4] = sum_ox;
  }
  if (out) {
    out[0] = nNO;
    out[1] = nNO2;
    out[2] = nNH3;
  }
}

ScrStepResult ScrStorage::step(double dt, const ScrInlet& in, const double* T_K, double* heat_J) {
  in_ = in;
  for (int i = 0; i < n_; ++i) {
    const double T = T_K[i];
    Vdot_[i] = in.n_total_mol_s * kRu * T / in.p_Pa;
    kd_[i] = k_.k_des * std::exp(-k_.E_des / (kRu * T));
    bT_[i] = k_.E_des * k_.alpha / (kRu * T);
    kstd_[i] = k_.k_std_ref * std::exp(-k_.E_std / kRu * (1.0 / T - 1.0 / k_.T_ref));
    kfast_[i] = k_.k_fast_ref * std::exp(-k_.E_fast / kRu * (1.0 / T - 1.0 / k_.T_ref));
    kno2_[i] = k_.k_no2_ref * std::exp(-k_.E_no2 / kRu * (1.0 / T - 1.0 / k_.T_ref));
    kox_[i] = k_.k_ox_ref * std::exp(-k_.E_ox / kRu * (1.0 / T - 1.0 / k_.T_ox_ref));
  }
  double* q = q_.data();
  std::fill(q_.begin(), q_.end(), 0.0);
  steps_ += rk_->integrate([this](const double* y, double* yd, double* qd) { rhs(y, yd, qd); }, dt,
                           theta_.data(), q, "NH3 coverage");
  const double* y = theta_.data();
  ScrStepResult r;
  for (int i = 0; i < n_; ++i) {
    if (!std::isfinite(y[i]) || y[i] < -1e-6 || y[i] > 1.0 + 1e-6)
      throw ModelDivergence("aftertreatment SCR slice " + std::to_string(i), "NH3 coverage",
                            "non-physical value " + std::to_string(y[i]));
    if (heat_J) heat_J[i] = q[5 + i];
  }
  r.nh3_slip_mol = q[0];
  r.std_mol = q[1];
  r.fast_mol = q[2];
  r.no2_mol = q[3];
  r.ox_mol = q[4];
  double out[3];
  // Outlet flows at the end state (instantaneous values for reporting).
  rhs(y, scratch_.data(), nullptr, out);
  r.n_NO_out_mol_s = out[0];
  r.n_NO2_out_mol_s = out[1];
  r.nh3_out_mol_s = out[2];
  return r;
}

}  // namespace hbt::aftertreatment
