#include "cosim/core/step_watch.hpp"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <mutex>
#include <sstream>

namespace hbt::cosim::core {
namespace {
std::mutex& registryMutex() {
  static std::mutex m;
  return m;
}
std::vector<StepWatch*>& registry() {
  static std::vector<StepWatch*> r;
  return r;
}
}  // namespace

double steadyNow_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

StepWatch::StepWatch(std::string participant) : participant_(std::move(participant)) {
  std::lock_guard<std::mutex> lock(registryMutex());
  registry().push_back(this);
}

StepWatch::~StepWatch() {
  std::lock_guard<std::mutex> lock(registryMutex());
  auto& r = registry();
  r.erase(std::remove(r.begin(), r.end(), this), r.end());
}

std::vector<StepWatch::InStep> StepWatch::inStep(double now_s) {
  std::vector<InStep> out;
  std::lock_guard<std::mutex> lock(registryMutex());
  for (const StepWatch* w : registry()) {
    const Nanos t = w->t_.load(std::memory_order_acquire);
    if (t == kIdle) continue;
    out.push_back({w->participant_, t, now_s - w->since_s_.load(std::memory_order_relaxed)});
  }
  return out;
}

long StepWatch::threadOf(const std::string& participant) {
  std::lock_guard<std::mutex> lock(registryMutex());
  for (const StepWatch* w : registry())
    if (w->participant_ == participant) return w->tid_.load(std::memory_order_relaxed);
  return 0;
}

std::string StepWatch::describe(double now_s) {
  std::ostringstream os;
  for (const InStep& s : inStep(now_s))
    os << (os.tellp() > 0 ? "; " : "") << "in the stepper's process, " << s.participant
       << " has been inside its model step (from t = " << std::fixed << std::setprecision(3) << toSec(s.t)
       << " s) for " << std::setprecision(2) << s.for_s << " s";
  return os.str();
}

}  // namespace hbt::cosim::core
