#include "cosim/core/diagnostics.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>

namespace hbt::cosim::core {

void WindowStats::add(double x) {
  max_ = n_ ? std::max(max_, x) : x;
  total_max_ = total_n_ ? std::max(total_max_, x) : x;
  ++n_;
  ++total_n_;
  sum_ += x;
  total_sum_ += x;
}

void WindowStats::closeWindow() {
  n_ = 0;
  sum_ = max_ = 0.0;
}

Hysteresis::Hysteresis(double on_level, double off_level) : on_level_(on_level), off_level_(off_level) {
  if (!(off_level <= on_level)) throw std::invalid_argument("Hysteresis: off level above on level");
}

bool Hysteresis::update(double x) {
  if (!on_ && x > on_level_) on_ = true;
  else if (on_ && x < off_level_) on_ = false;
  return on_;
}

Warning::Warning(std::string name, Nanos on_delay) : name_(std::move(name)), on_delay_(on_delay) {
  if (on_delay < 0) throw std::invalid_argument("Warning " + name_ + ": negative on-delay");
}

bool Warning::update(Nanos t, bool condition) {
  if (seen_ && active_) active_ns_ += t - last_t_;
  last_t_ = t;
  seen_ = true;
  if (!condition) {
    cond_ = active_ = false;
    return false;
  }
  if (!cond_) {
    cond_ = true;
    since_ = t;
  }
  if (active_ || t - since_ < on_delay_) return false;
  active_ = true;
  ++raised_;
  if (first_t_ < 0) first_t_ = t;
  return true;
}

void Warning::setMessage(const std::string& message) {
  msg_ = message;
  if (raised_ == 1 && first_msg_.empty()) first_msg_ = message;
}

void Diagnostics::setPeriod(Nanos period) {
  if (period <= 0) throw std::invalid_argument("Diagnostics: period must be > 0");
  period_ = period;
}

Warning& Diagnostics::addWarning(const std::string& name, double on_delay_s) {
  for (const auto& w : warnings_)
    if (w->name() == name) throw std::invalid_argument("Diagnostics: warning " + name + " declared twice");
  warnings_.push_back(std::make_unique<Warning>(name, toNanos(on_delay_s)));
  return *warnings_.back();
}

bool Diagnostics::due(Nanos t) {
  if (t < next_due_) return false;
  next_due_ = (t / period_ + 1) * period_;
  return true;
}

DiagStatus Diagnostics::status(Nanos t, bool final, double compute_time_s) {
  DiagStatus s;
  auto kv = [&s](const std::string& k, const std::string& v) { s.values.push_back({k, v}); };
  kv("sim_time_s", formatSeconds(t));
  kv("final", final ? "true" : "false");
  kv("steps_window", std::to_string(step_ms_.count()));
  kv("step_compute_ms_mean", formatNumber(step_ms_.mean()));
  kv("step_compute_ms_max", formatNumber(step_ms_.max()));
  kv("steps_total", std::to_string(step_ms_.totalCount()));
  kv("step_compute_ms_mean_run", formatNumber(step_ms_.totalMean()));
  kv("step_compute_ms_max_run", formatNumber(step_ms_.totalMax()));
  kv("compute_time_s", formatNumber(compute_time_s));
  std::string checked, active, earlier;
  for (const auto& w : warnings_) {
    checked += (checked.empty() ? "" : ", ") + w->name();
    if (w->active()) active += (active.empty() ? "" : ", ") + w->name();
    else if (w->raised()) earlier += (earlier.empty() ? "" : ", ") + w->name();
  }
  kv("warnings_checked", checked);
  for (const auto& w : warnings_) {
    if (!w->raised()) continue;
    const std::string p = "warning/" + w->name() + "/";
    kv(p + "first_time_s", formatSeconds(w->firstTime()));
    kv(p + "raised", std::to_string(w->raised()));
    kv(p + "active", w->active() ? "true" : "false");
    kv(p + "active_s", formatSeconds(w->activeTime()));
    kv(p + "message", w->firstMessage());
  }
  s.level = active.empty() ? DiagStatus::Ok : DiagStatus::Warn;
  if (!active.empty()) s.message = "active: " + active;
  if (!earlier.empty()) s.message += (s.message.empty() ? "" : "; ") + std::string("earlier: ") + earlier;
  if (s.message.empty()) s.message = "OK";
  step_ms_.closeWindow();
  return s;
}

std::string formatSeconds(Nanos t) {
  char buf[40];
  const char* sign = t < 0 ? "-" : "";
  const uint64_t a = static_cast<uint64_t>(t < 0 ? -t : t);
  std::snprintf(buf, sizeof buf, "%s%" PRIu64 ".%09" PRIu64, sign, a / 1000000000u, a % 1000000000u);
  return buf;
}

std::string formatNumber(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

std::string formatText(const char* fmt, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  return buf;
}

}  // namespace hbt::cosim::core
