#include "turbo/turbine_map.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "common/csv_table.hpp"
#include "common/errors.hpp"

namespace hbt::turbo {

namespace {

std::string lineName(double speed) {
  std::ostringstream os;
  os << "speed line " << speed << " rpm/sqrt(K)";
  return os.str();
}

double logG(double x) {
  if (!(x > 0.0)) return -INFINITY;
  if (x <= 1.0) return std::log(2.0 * x - x * x);
  return -(x - 1.0) * (x - 1.0);
}

}  // namespace

TurbineMap TurbineMap::read(const std::string& path, const TurbineMapFormat& fmt, PerfectGas gas) {
  const CsvTable t = CsvTable::read(path);
  const auto& n = t.column(fmt.col_speed);
  const auto& mfp = t.column(fmt.col_mfp);
  const auto& er = t.column(fmt.col_er);
  const auto& eta = t.column(fmt.col_eff);
  std::vector<TurbineLine> lines;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    if (lines.empty() || lines.back().speed != n[r]) {
      lines.emplace_back();
      lines.back().speed = n[r];
    }
    lines.back().er.push_back(er[r]);
    lines.back().mfp.push_back(mfp[r]);
    lines.back().eta.push_back(eta[r]);
  }
  return TurbineMap(std::move(lines), gas, path, fmt);
}

TurbineMap::TurbineMap(std::vector<TurbineLine> lines, PerfectGas gas, const std::string& source,
                       const TurbineMapFormat& fmt)
    : source_(source), gas_(gas), lines_(std::move(lines)) {
  build(fmt);
}

void TurbineMap::build(const TurbineMapFormat& fmt) {
  if (lines_.size() < 2) throw InputError(source_, fmt.col_speed, "need at least 2 speed lines");
  for (auto& l : lines_) {
    const std::string ln = lineName(l.speed);
    if (!(l.speed > 0.0)) throw InputError(source_, fmt.col_speed, ln + ": speed must be > 0");
    if (l.er.size() < 2) throw InputError(source_, fmt.col_er, ln + ": fewer than 2 points");
    std::vector<std::size_t> idx(l.er.size());
    std::iota(idx.begin(), idx.end(), 0);
    std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return l.er[a] < l.er[b]; });
    TurbineLine s;
    s.speed = l.speed;
    for (auto i : idx) {
      if (!(l.er[i] > 1.0)) throw InputError(source_, fmt.col_er, ln + ": expansion ratio must be > 1");
      if (!(l.mfp[i] > 0.0)) throw InputError(source_, fmt.col_mfp, ln + ": flow must be > 0");
      if (!(l.eta[i] > 0.0 && l.eta[i] < 1.0))
        throw InputError(source_, fmt.col_eff, ln + ": efficiency must be in (0,1)");
      s.er.push_back(l.er[i]);
      s.mfp.push_back(l.mfp[i]);
      s.eta.push_back(l.eta[i]);
    }
    for (std::size_t j = 1; j < s.er.size(); ++j) {
      if (!(s.er[j] > s.er[j - 1]))
        throw InputError(source_, fmt.col_er, ln + ": repeated expansion ratio");
      if (s.mfp[j] < s.mfp[j - 1])
        throw InputError(source_, fmt.col_mfp,
                         ln + ": not monotonic (flow must not fall as expansion ratio rises)");
    }
    l = std::move(s);
  }
  std::sort(lines_.begin(), lines_.end(),
            [](const auto& a, const auto& b) { return a.speed < b.speed; });
  for (std::size_t i = 1; i < lines_.size(); ++i)
    if (!(lines_[i].speed > lines_[i - 1].speed))
      throw InputError(source_, fmt.col_speed,
                       lineName(lines_[i].speed) + ": speed repeated (lines must be contiguous)");
  const double k = gas_.k();
  speed_.clear(); psi_first_.clear(); psi_last_.clear(); sq_first_.clear(); sq_last_.clear();
  eta_cap_ = 0.0;
  double S2 = 0, S3 = 0, S4 = 0, T1 = 0, T2 = 0;
  for (const auto& l : lines_) {
    speed_.push_back(l.speed);
    psi_first_.push_back(gas_.psi(1.0 / l.er.front()));
    psi_last_.push_back(gas_.psi(1.0 / l.er.back()));
    sq_first_.push_back(std::sqrt(1.0 - std::pow(l.er.front(), -k)));
    sq_last_.push_back(std::sqrt(1.0 - std::pow(l.er.back(), -k)));
    for (std::size_t j = 0; j < l.er.size(); ++j) {
      eta_cap_ = std::max(eta_cap_, l.eta[j]);
      const double nu = 1e-3 * l.speed / std::sqrt(1.0 - std::pow(l.er[j], -k));
      S2 += nu * nu; S3 += nu * nu * nu; S4 += nu * nu * nu * nu;
      T1 += l.eta[j] * nu; T2 += l.eta[j] * nu * nu;
    }
  }
  const double det = S2 * S4 - S3 * S3;
  const double a = (T1 * S4 - T2 * S3) / det, b = (S2 * T2 - S3 * T1) / det;
  if (!(a > 0.0 && b < 0.0))
    throw InputError(source_, fmt.col_eff,
                     "efficiency does not follow a parabola in blade-speed ratio (fit a=" +
                         std::to_string(a) + ", b=" + std::to_string(b) + ")");
  nu_opt_ = 1e3 * (-a / (2.0 * b));
  eta_max_fit_ = -a * a / (4.0 * b);
}

void TurbineMap::scale(double flow_factor, double speed_factor) {
  if (!(flow_factor > 0.0) || !std::isfinite(flow_factor))
    throw InputError(source_, "flow_scale", "flow scale factor must be > 0");
  if (!(speed_factor > 0.0) || !std::isfinite(speed_factor))
    throw InputError(source_, "speed_scale", "speed scale factor must be > 0");
  for (auto& l : lines_) {
    l.speed *= speed_factor;
    for (auto& v : l.mfp) v *= flow_factor;
  }
  for (auto& v : speed_) v *= speed_factor;
  nu_opt_ *= speed_factor;
}

double TurbineMap::bladeSpeedParameter(double n, double er) const {
  if (!(er > 1.0)) return INFINITY;
  return std::max(n, 0.0) / std::sqrt(1.0 - std::pow(er, -gas_.k()));
}

double TurbineMap::gRatio(double xq, double xc) const {
  const double d = logG(xq) - logG(xc);
  return std::exp(std::min(d, 30.0));
}

double TurbineMap::lineMfp(int i, double er, double psi_q) const {
  const auto& l = lines_[i];
  if (er < l.er.front()) return l.mfp.front() * psi_q / psi_first_[i];
  if (er > l.er.back()) return l.mfp.back() * psi_q / psi_last_[i];
  const std::size_t j = std::min<std::size_t>(
      std::upper_bound(l.er.begin(), l.er.end(), er) - l.er.begin() - 1, l.er.size() - 2);
  const double t = (er - l.er[j]) / (l.er[j + 1] - l.er[j]);
  return l.mfp[j] + t * (l.mfp[j + 1] - l.mfp[j]);
}

double TurbineMap::lineEta(int i, double er, double sq) const {
  const auto& l = lines_[i];
  const double x0 = l.speed / nu_opt_;
  if (er < l.er.front())
    return l.eta.front() * gRatio(std::min(x0 / sq, 1e3), x0 / sq_first_[i]);
  if (er > l.er.back()) return l.eta.back() * gRatio(x0 / sq, x0 / sq_last_[i]);
  const std::size_t j = std::min<std::size_t>(
      std::upper_bound(l.er.begin(), l.er.end(), er) - l.er.begin() - 1, l.er.size() - 2);
  const double t = (er - l.er[j]) / (l.er[j + 1] - l.er[j]);
  return l.eta[j] + t * (l.eta[j + 1] - l.eta[j]);
}

TurbineMap::Point TurbineMap::at(double n, double er) const {
  Point p;
  n = std::max(n, 0.0);
  if (!(er > 1.0)) {
    p.region = kNoFlow;
    return p;
  }
  const double psi_q = gas_.psi(1.0 / er);
  const double sq = std::sqrt(std::max(1.0 - std::pow(er, -gas_.k()), 1e-300));
  const int L = static_cast<int>(speed_.size());
  auto erFlags = [&](int i) {
    if (er < lines_[i].er.front()) p.region |= kErBelow;
    if (er > lines_[i].er.back()) p.region |= kErAbove;
  };
  double eta;
  if (n <= speed_.front() || n >= speed_.back()) {
    const int i = n <= speed_.front() ? 0 : L - 1;
    erFlags(i);
    p.mfp = lineMfp(i, er, psi_q);
    eta = lineEta(i, er, sq);
    if (n != speed_[i]) {
      p.region |= (i == 0 ? kBelowLines : kAboveLines);
      const double xq = std::min(n / (nu_opt_ * sq), 1e3);
      const double xe = std::min(speed_[i] / (nu_opt_ * sq), 1e3);
      eta *= gRatio(xq, xe);
    }
  } else {
    const int i = static_cast<int>(std::upper_bound(speed_.begin(), speed_.end(), n) -
                                   speed_.begin()) - 1;
    const double w = (n - speed_[i]) / (speed_[i + 1] - speed_[i]);
    erFlags(i);
    erFlags(i + 1);
    const double m0 = lineMfp(i, er, psi_q), m1 = lineMfp(i + 1, er, psi_q);
    const double e0 = lineEta(i, er, sq), e1 = lineEta(i + 1, er, sq);
    p.mfp = m0 + w * (m1 - m0);
    eta = e0 + w * (e1 - e0);
  }
  p.eta = std::clamp(eta, 0.0, eta_cap_);
  return p;
}

}  // namespace hbt::turbo
