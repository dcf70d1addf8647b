#include "engine_1d/turbo_adapters.hpp"

#include <algorithm>
#include <cmath>

#include "common/units.hpp"

namespace hbt::engine_1d {
namespace {
// Compressor efficiency [-] returned where no temperature rise is represented (choke side,
// windmilling, no work in the map): dT = T0 (pr^k - 1) / eta ~ 0.
constexpr double kNoTemperatureRiseEfficiency = 1e3;
constexpr int kPsiPoints = 2001;
// Lowest pressure ratio of the compressor grid [-] (deep choke / throttling of a slow wheel).
constexpr double kPrLow = 0.3;
}

CompressorFlowMap::CompressorFlowMap(const turbo::Compressor& c, int n_speed, int n_pr)
    : p_ref_(c.pRef()), T_ref_(c.tRef()), k_(c.gas().k()) {
  double n_top = 0.0, pr_top = 1.0;
  for (const auto& l : c.map().lines()) {
    n_top = std::max(n_top, l.speed_rpm);
    for (double pr : l.pr) pr_top = std::max(pr_top, pr);
  }
  n_max_ = 1.3 * n_top;
  // PI = 1 is a grid node: the stationary or slow wheel's flow has a kink there (orifice flow
  // K sqrt(1 - PI) below, no forward flow against a pressure rise above), which a cell spanning
  // PI = 1 would smear into a forward flow at PI > 1 (at N = 0: 18 g/s at PI = 1, 1.4 g/s at
  // PI = 1.0115, where the map gives 0). The grid spans [pr_lo, pr_lo + (n_pr - 1) dpr] with
  // pr_lo <= kPrLow and the top >= 1.3 x the highest measured PI.
  const double dpr = (1.3 * pr_top - kPrLow) / (n_pr - 1);
  const double pr_lo = 1.0 - std::ceil((1.0 - kPrLow) / dpr) * dpr;
  const double pr_hi = pr_lo + (n_pr - 1) * dpr;
  const turbo::CompressorMap& m = c.map();
  const auto node = [](double pr) { return std::fabs(pr - 1.0) < 1e-9 ? 1.0 : pr; };  // exact 1
  flow_ = Grid2D(0.0, n_max_, n_speed, pr_lo, pr_hi, n_pr,
                 [&](double n, double pr) { return m.atPressureRatio(n, node(pr)).flow_kg_s; });
  work_ = Grid2D(0.0, n_max_, n_speed, pr_lo, pr_hi, n_pr,
                 [&](double n, double pr) { return m.atPressureRatio(n, node(pr)).work; });
}

double CompressorFlowMap::massFlow(double p0, double T0, double p_down, double w) const {
  const double sq = std::sqrt(T0 / T_ref_);
  const double n = units::radpsToRpm(w > 0.0 ? w : 0.0) / sq;
  const double m = flow_(n, p_down / p0) * (p0 / p_ref_) / sq;
  return m > 0.0 ? m : 0.0;
}

double CompressorFlowMap::efficiency(double p0, double T0, double p_down, double w) const {
  const double pr = p_down / p0;
  if (pr <= 1.0) return kNoTemperatureRiseEfficiency;  // choke side / windmilling: no temperature rise represented
  const double n = units::radpsToRpm(w > 0.0 ? w : 0.0) / std::sqrt(T0 / T_ref_);
  const double work = work_(n, pr), hs = std::pow(pr, k_) - 1.0;
  if (!(work > 1e-9)) return kNoTemperatureRiseEfficiency;
  return hs / work;
}

double CompressorFlowMap::temperatureRatio(double p0, double T0, double p_down, double w,
                                           double k) const {
  const double pr = p_down / p0;
  if (pr > 1.0 && std::fabs(k - k_) < 1e-12) {
    const double n = units::radpsToRpm(w > 0.0 ? w : 0.0) / std::sqrt(T0 / T_ref_);
    const double work = work_(n, pr);
    if (work > 1e-9) return 1.0 + work;
  }
  return FlowMap::temperatureRatio(p0, T0, p_down, w, k);
}

TurbineFlowMap::TurbineFlowMap(const turbo::TurbineEntry& e, const turbo::Wastegate* wg,
                               int n_speed, int n_er)
    : share_(e.share()), er_max_(6.0), R_(e.map().gas().R), has_wg_(wg != nullptr) {
  const turbo::TurbineMap& m = e.map();
  double n_top = 0.0;
  for (const auto& l : m.lines()) n_top = std::max(n_top, l.speed);
  const double n_max = 1.4 * n_top;
  mfp_ = Grid2D(0.0, n_max, n_speed, 1.0, er_max_, n_er,
                [&](double n, double er) { return m.at(n, er).mfp; });
  eta_ = Grid2D(0.0, n_max, n_speed, 1.0, er_max_, n_er,
                [&](double n, double er) { return m.at(n, er).eta; });
  const PerfectGas& g = m.gas();
  psi_.resize(kPsiPoints);
  for (int i = 0; i < kPsiPoints; ++i) psi_[i] = g.psi(static_cast<double>(i) / (kPsiPoints - 1));
  // Cd A_max of the wastegate from its own law at a choked reference state (p0 = 1e5 Pa, T0 = 1 K):
  // mdot = Cd A_max 1e5/sqrt(R) psi*.
  if (wg) wg_coeff_ = wg->massFlow(1e5, 1.0, 0.0, 1.0) * std::sqrt(R_) / 1e5 / psi_[0];
}

void TurbineFlowMap::flows(double p0, double T0, double p_down, double w, double& me,
                           double& mw) const {
  me = mw = 0.0;
  if (!(p0 > p_down) || !(T0 > 0.0)) return;
  const double er = p0 / p_down, sq = std::sqrt(T0);
  const double nr = units::radpsToRpm(w > 0.0 ? w : 0.0) / sq;
  me = share_ * mfp_(nr, er) * (p0 * 1e-3) / sq;
  if (me < 0.0) me = 0.0;
  if (has_wg_ && opening_ > 0.0) {
    const double x = (1.0 / er) * (kPsiPoints - 1);
    int i = static_cast<int>(x);
    if (i > kPsiPoints - 2) i = kPsiPoints - 2;
    const double f = x - i;
    const double psi = (1 - f) * psi_[i] + f * psi_[i + 1];
    mw = wg_coeff_ * opening_ * p0 / std::sqrt(R_ * T0) * psi;
  }
}

double TurbineFlowMap::massFlow(double p0, double T0, double p_down, double w) const {
  double me, mw;
  flows(p0, T0, p_down, w, me, mw);
  return me + mw;
}

double TurbineFlowMap::efficiency(double p0, double T0, double p_down, double w) const {
  double me, mw;
  flows(p0, T0, p_down, w, me, mw);
  if (!(me + mw > 0.0)) return 0.0;
  const double er = p0 / p_down, nr = units::radpsToRpm(w > 0.0 ? w : 0.0) / std::sqrt(T0);
  const double eta = eta_(nr, er);
  return (eta > 0.0 ? eta : 0.0) * me / (me + mw);
}

}  // namespace hbt::engine_1d
