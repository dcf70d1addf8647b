#include "turbo/compressor_map.hpp"

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
  os << "speed line " << speed << " rpm";
  return os.str();
}

}  // namespace

CompressorMap CompressorMap::read(const std::string& path, const CompressorMapFormat& fmt,
                                  const CompressorMapOptions& opt) {
  const CsvTable t = CsvTable::read(path);
  const auto& n = t.column(fmt.col_speed);
  const auto& m = t.column(fmt.col_flow);
  const auto& pr = t.column(fmt.col_pr);
  const auto& eta = t.column(fmt.col_eff);
  std::vector<CompressorLine> lines;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    if (lines.empty() || lines.back().speed_rpm != n[r]) {
      lines.emplace_back();
      lines.back().speed_rpm = n[r];
    }
    lines.back().flow.push_back(m[r]);
    lines.back().pr.push_back(pr[r]);
    lines.back().eta.push_back(eta[r]);
  }
  return CompressorMap(std::move(lines), opt, path, fmt);
}

CompressorMap::CompressorMap(std::vector<CompressorLine> lines, const CompressorMapOptions& opt,
                             const std::string& source, const CompressorMapFormat& fmt)
    : source_(source), opt_(opt), lines_(std::move(lines)) {
  gas_.gamma = opt.gamma;
  build(fmt);
}

void CompressorMap::build(const CompressorMapFormat& fmt) {
  if (lines_.size() < 2) throw InputError(source_, fmt.col_speed, "need at least 2 speed lines");
  for (auto& l : lines_) {
    const std::string ln = lineName(l.speed_rpm);
    if (!(l.speed_rpm > 0.0)) throw InputError(source_, fmt.col_speed, ln + ": speed must be > 0");
    if (l.flow.size() < 2) throw InputError(source_, fmt.col_flow, ln + ": fewer than 2 points");
    for (std::size_t j = 0; j < l.flow.size(); ++j) {
      if (!(l.flow[j] > 0.0)) throw InputError(source_, fmt.col_flow, ln + ": flow must be > 0");
      if (!(l.pr[j] > 1.0))
        throw InputError(source_, fmt.col_pr, ln + ": pressure ratio must be > 1");
      if (!(l.eta[j] > 0.0 && l.eta[j] < 1.0))
        throw InputError(source_, fmt.col_eff, ln + ": efficiency must be in (0,1)");
    }
    std::vector<std::size_t> idx(l.flow.size());
    std::iota(idx.begin(), idx.end(), 0);
    std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return l.flow[a] < l.flow[b]; });
    CompressorLine s;
    s.speed_rpm = l.speed_rpm;
    for (auto i : idx) {
      s.flow.push_back(l.flow[i]);
      s.pr.push_back(l.pr[i]);
      s.eta.push_back(l.eta[i]);
    }
    for (std::size_t j = 1; j < s.flow.size(); ++j) {
      if (!(s.flow[j] > s.flow[j - 1]))
        throw InputError(source_, fmt.col_flow, ln + ": repeated flow value");
      if (!(s.pr[j] < s.pr[j - 1]))
        throw InputError(source_, fmt.col_pr,
                         ln + ": not monotonic (pressure ratio must fall as flow rises)");
    }
    l = std::move(s);
  }
  std::sort(lines_.begin(), lines_.end(),
            [](const auto& a, const auto& b) { return a.speed_rpm < b.speed_rpm; });
  for (std::size_t i = 1; i < lines_.size(); ++i) {
    const auto& a = lines_[i - 1];
    const auto& b = lines_[i];
    const std::string ln = lineName(b.speed_rpm);
    if (!(b.speed_rpm > a.speed_rpm))
      throw InputError(source_, fmt.col_speed, ln + ": speed repeated (lines must be contiguous)");
    if (!(b.pr.front() > a.pr.front()))
      throw InputError(source_, fmt.col_pr, ln + ": surge pressure ratio must rise with speed");
  }
  // A line that stops short of the choke flow of the line below it is continued along its last
  // segment until it passes that flow (keeps the choke flow rising with speed).
  for (std::size_t i = 1; i < lines_.size(); ++i) {
    auto& l = lines_[i];
    const double target = lines_[i - 1].flow.back() * (1.0 + 1e-3);
    const std::size_t n = l.flow.size();
    if (l.flow.back() >= target) continue;
    const double t = (target - l.flow[n - 2]) / (l.flow[n - 1] - l.flow[n - 2]);
    const double pr = l.pr[n - 2] + t * (l.pr[n - 1] - l.pr[n - 2]);
    if (!(pr > 1.0))
      throw InputError(source_, fmt.col_flow, lineName(l.speed_rpm) +
                                                  ": choke flow below that of the line beneath");
    l.flow.push_back(target);
    l.pr.push_back(pr);
    l.eta.push_back(std::max(l.eta[n - 2] + t * (l.eta[n - 1] - l.eta[n - 2]), 0.05));
  }
  // Union beta grid.
  beta_.clear();
  for (const auto& l : lines_) {
    const std::size_t n = l.flow.size();
    for (std::size_t j = 0; j < n; ++j) beta_.push_back(double(j) / double(n - 1));
  }
  std::sort(beta_.begin(), beta_.end());
  beta_.erase(std::unique(beta_.begin(), beta_.end(),
                          [](double a, double b) { return std::abs(a - b) < 1e-12; }),
              beta_.end());
  const std::size_t M = beta_.size(), L = lines_.size();
  speed_.assign(L, 0.0);
  m_.assign(L * M, 0.0);
  hs_.assign(L * M, 0.0);
  eta_.assign(L * M, 0.0);
  const double k = gas_.k();
  for (std::size_t i = 0; i < L; ++i) {
    const auto& l = lines_[i];
    speed_[i] = l.speed_rpm;
    const std::size_t n = l.flow.size();
    for (std::size_t j = 0; j < M; ++j) {
      double x = beta_[j] * double(n - 1);
      const double xr = std::round(x);
      if (std::abs(x - xr) < 1e-9) x = xr;
      std::size_t s = std::min<std::size_t>(static_cast<std::size_t>(x), n - 2);
      const double t = x - double(s);
      const double pr = l.pr[s] + t * (l.pr[s + 1] - l.pr[s]);
      m_[i * M + j] = l.flow[s] + t * (l.flow[s + 1] - l.flow[s]);
      hs_[i * M + j] = std::pow(pr, k) - 1.0;
      eta_[i * M + j] = l.eta[s] + t * (l.eta[s + 1] - l.eta[s]);
    }
  }
  scale(1.0);
}

double CompressorMap::maxFlow() const {
  double m = 0.0;
  for (const auto& l : lines_) m = std::max(m, l.flow.back());
  return m;
}

void CompressorMap::scale(double f) {
  if (!(f > 0.0) || !std::isfinite(f))
    throw InputError(source_, "flow_scale", "flow scale factor must be > 0");
  const double sn = 1.0 / std::sqrt(f);
  for (auto& l : lines_) {
    l.speed_rpm *= sn;
    for (auto& v : l.flow) v *= f;
  }
  for (auto& v : speed_) v *= sn;
  for (auto& v : m_) v *= f;
  k_th_ = opt_.throttle_flow_fraction * maxFlow() / std::sqrt(1.0 - gas_.criticalPressureRatio());
}

CompressorMap::Sel CompressorMap::select(double n, int& region) const {
  n = std::max(n, 0.0);
  const int L = static_cast<int>(speed_.size());
  if (n <= speed_.front()) {
    if (n < speed_.front()) region |= kBelowLines;
    const double s = n / speed_.front();
    return {0, 0, 0.0, s, s * s};
  }
  if (n >= speed_.back()) {
    if (n > speed_.back()) region |= kAboveLines;
    const double s = n / speed_.back();
    return {L - 1, L - 1, 0.0, s, s * s};
  }
  const int i = static_cast<int>(std::upper_bound(speed_.begin(), speed_.end(), n) -
                                 speed_.begin()) - 1;
  const double w = (n - speed_[i]) / (speed_[i + 1] - speed_[i]);
  return {i, i + 1, w, 1.0, 1.0};
}

void CompressorMap::node(const Sel& s, int j, double& m, double& hs, double& eta) const {
  const std::size_t M = beta_.size();
  const std::size_t a = s.i0 * M + j, b = s.i1 * M + j;
  m = s.sm * (m_[a] + s.w * (m_[b] - m_[a]));
  hs = s.sh * (hs_[a] + s.w * (hs_[b] - hs_[a]));
  eta = eta_[a] + s.w * (eta_[b] - eta_[a]);
}

CompressorMap::Point CompressorMap::atPressureRatio(double speed_rpm, double pr) const {
  Point p;
  const Sel s = select(speed_rpm, p.region);
  pr = std::max(pr, 1e-9);
  const double k = gas_.k();
  const double hq = std::pow(pr, k) - 1.0;
  const double fl = opt_.eta_floor;
  const int M = static_cast<int>(beta_.size());
  double m0, h0, e0, mE, hE, eE;
  node(s, 0, m0, h0, e0);
  node(s, M - 1, mE, hE, eE);
  if (hq > h0) {  // left of surge
    const double hsh = opt_.shutoff_head_ratio * h0;
    p.region |= kSurgeSide;
    p.eta = std::max(e0, fl);
    p.work = hq / p.eta;
    if (hq >= hsh || h0 <= 0.0) {
      p.region |= kShutOff;
      p.flow_kg_s = 0.0;
    } else {
      p.flow_kg_s = m0 * (hsh - hq) / (hsh - h0);
    }
  } else if (hq < hE) {  // right of the last point: choke
    p.region |= kChokeSide;
    const double drop = std::min(1.0 - pr, 1.0 - gas_.criticalPressureRatio());
    p.flow_kg_s = std::max(mE, k_th_ * std::sqrt(std::max(drop, 0.0)));
    const double eEf = std::max(eE, fl);
    p.work = std::max(hE, 0.0) / eEf;
    p.eta = (hq > 0.0 && p.work > 0.0) ? std::clamp(hq / p.work, fl, eEf) : fl;
  } else {
    int lo = 0, hi = M - 1;
    double ml = m0, hl = h0, el = e0, mh = mE, hh = hE, eh = eE;
    while (hi - lo > 1) {
      const int mid = (lo + hi) / 2;
      double mm, hm, em;
      node(s, mid, mm, hm, em);
      if (hm >= hq) { lo = mid; ml = mm; hl = hm; el = em; }
      else { hi = mid; mh = mm; hh = hm; eh = em; }
    }
    const double t = hl > hh ? (hl - hq) / (hl - hh) : 0.0;
    p.flow_kg_s = ml + t * (mh - ml);
    p.eta = std::max(el + t * (eh - el), fl);
    p.work = std::max(hq, 0.0) / p.eta;
  }
  return p;
}

void CompressorMap::ridge(std::vector<double>& pr, std::vector<double>& flow) const {
  pr.clear();
  flow.clear();
  for (const auto& l : lines_) {
    const auto it = std::max_element(l.eta.begin(), l.eta.end());
    const auto j = static_cast<std::size_t>(it - l.eta.begin());
    pr.push_back(l.pr[j]);
    flow.push_back(l.flow[j]);
  }
}

}  // namespace hbt::turbo
