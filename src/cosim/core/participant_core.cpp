#include "cosim/core/participant_core.hpp"

#include <chrono>

#include <algorithm>
#include <exception>
#include <iomanip>
#include <sstream>

#include "common/errors.hpp"
#include "cosim/core/process_cpu.hpp"

namespace hbt::cosim::core {
namespace {
// Compute time is read on the steady clock (vDSO, ~0.1 us per reading here), not the thread
// CPU clock: CLOCK_THREAD_CPUTIME_ID is a system call, 2.6 us per reading on this VM, i.e. 42 us
// per base step for 8 participants -- most of a nodelet exchange (scripts/twin bench cosim).
// On a thread that is not preempted the two agree; under load it counts the waiting too.
double monotonicNow() { return steadyNow_s(); }

std::string seconds(Nanos t) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(3) << toSec(t) << " s";
  return os.str();
}
}  // namespace

double ParticipantHooks::wallNow() const { return monotonicNow(); }

std::size_t ParticipantCore::addOutput(const std::string& resolved_topic) {
  outputs_.push_back(Output{resolved_topic, {}, {}});
  return outputs_.size() - 1;
}

void ParticipantCore::start() {
  try {
    const double c0 = monotonicNow();
    h_.configure();
    compute_s_ += monotonicNow() - c0;
    if (period_given_) {
      const double p = period_req_.period_s;
      if (std::isnan(p)) throw InputError(period_req_.where, period_req_.key, "NaN");
      if (!(p > 0.0) || !std::isfinite(p))
        throw InputError(period_req_.where, period_req_.key,
                         "macro step must be > 0 s (an integer multiple of the stepper's base step)");
    }
    configured_ = true;
  } catch (const std::exception& e) {
    fail(std::string("configuration failed: ") + e.what());
  }
}

bool ParticipantCore::checkPeriod(double base_dt_s) {
  base_dt_s_ = base_dt_s;
  base_ns_ = toNanos(base_dt_s);
  multiple_ = 1;
  dt_s_ = base_dt_s;
  if (period_given_ && base_ns_ > 0) {
    const Nanos p = toNanos(period_req_.period_s);
    const Nanos m = (p + base_ns_ / 2) / base_ns_;
    if (m >= 1 && m * base_ns_ == p) {
      multiple_ = static_cast<uint32_t>(m);
      if (m > 1) dt_s_ = period_req_.period_s;
    } else if (!period_req_.fallback) {
      std::ostringstream os;
      os << period_req_.period_s << " s is not an integer multiple of the stepper's base step "
         << base_dt_s << " s";
      fail("configuration failed: " +
           std::string(InputError(period_req_.where, period_req_.key, os.str()).what()));
      return false;
    }
  }
  period_ns_ = static_cast<Nanos>(multiple_) * base_ns_;
  return true;
}

void ParticipantCore::fail(const std::string& what) {
  failed_ = true;
  error_ = name_ + ": " + what;
  h_.logError(error_);
  report(St::Error, n_, static_cast<Nanos>(n_) * base_ns_, error_);
}

void ParticipantCore::report(St status, uint64_t step, Nanos t, const std::string& msg) {
  Status s;
  s.node = name_;
  s.status = status;
  s.step = step;
  s.t = t;
  s.compute_time_s = compute_s_;
  s.process_cpu_s = processCpuSeconds();
  s.process = processName();
  s.message = msg;
  if (status == St::Announce || status == St::Ready) {
    for (const InputPort* in : inputs_) s.inputs.push_back(in->resolvedTopic());
  }
  if (status == St::Announce) {
    for (const Output& o : outputs_) s.outputs.push_back(o.topic);
    s.observer = observer_;
    s.mission_duration_s = mission_duration_s_;
  }
  s.step_multiple = multiple_;
  h_.sendStatus(s);
}

bool ParticipantCore::onTick() {
  if (closed_ || closing_) return false;
  if (started_) {
    watchStepper();
    return !closed_;
  }
  if (failed_) report(St::Error, 0, 0, error_);
  else if (configured_) report(St::Announce, 0, 0);
  return true;
}

void ParticipantCore::watchStepper() {
  const double now = h_.wallNow();
  // its own thread did not run for a while (starved, or blocked by another participant's step on
  // it): what the stepper sent meanwhile waits in its queue, unread -- count afresh
  if (now - last_tick_wall_ > report_wall_s_) last_heard_wall_ = std::max(last_heard_wall_, now);
  last_tick_wall_ = now;
  const double silent_s = now - last_heard_wall_;
  const double limit_s = kStepperSilenceReportPeriods * report_wall_s_;
  if (silent_s <= limit_s) return;
  const Nanos t = static_cast<Nanos>(n_) * base_ns_;
  std::ostringstream os;
  os << "no command from the stepper for " << std::fixed << std::setprecision(1) << silent_s
     << std::defaultfloat << std::setprecision(6) << " s (its heartbeat comes every " << report_wall_s_
     << " s; the limit is " << limit_s << " s): the stepper died or hung; closed at t = " << seconds(t);
  const std::string message = os.str();
  h_.logError(name_ + ": " + message);
  try {
    h_.close(t, true);
  } catch (const std::exception& e) {
    h_.logError(name_ + ": closing failed: " + e.what());
  }
  closed_ = true;
  h_.stepperLost(t, message);
}

void ParticipantCore::applyTable(const Table& tb) {
  for (std::size_t i = 0; i < tb.participants.size() && i < tb.participant_group.size(); ++i)
    if (tb.participants[i] == name_) group_ = tb.participant_group[i];
  for (InputPort* in : inputs_) {
    HeldRule r;
    const std::string topic = in->resolvedTopic();
    for (std::size_t i = 0; i < tb.topics.size(); ++i) {
      if (tb.topics[i] != topic || i >= tb.topic_multiple.size() || i >= tb.topic_group.size())
        continue;
      r.period = static_cast<Nanos>(tb.topic_multiple[i]) * base_ns_;
      r.fresh = !observer_ && tb.topic_group[i] < group_;
    }
    in->setRule(r);
  }
  for (Output& o : outputs_) {
    o.readers.clear();
    for (std::size_t j = 0; j < tb.reader_topic.size(); ++j) {
      const uint32_t i = tb.reader_topic[j];
      if (i < tb.topics.size() && tb.topics[i] == o.topic && j < tb.reader_multiple.size() &&
          j < tb.reader_fresh.size())
        o.readers.push_back(Reader{tb.reader_multiple[j], tb.reader_fresh[j] != 0,
                                   j < tb.reader_observer.size() && tb.reader_observer[j] != 0});
    }
  }
  window_ = std::max<uint32_t>(1, tb.window);
  report_wall_s_ = tb.report_wall_s;
}

bool ParticipantCore::outputRead(std::size_t index, Nanos stamp) const {
  return outputRead(index, stamp, false) || outputRead(index, stamp, true);
}

bool ParticipantCore::outputRead(std::size_t index, Nanos stamp, bool observers) const {
  if (!started_ || base_ns_ <= 0 || index >= outputs_.size()) return true;
  const uint64_t s = static_cast<uint64_t>(stamp / base_ns_);
  for (const Reader& r : outputs_[index].readers)
    if (r.observer == observers && readsStamp(multiple_, r.multiple, r.fresh, s)) return true;
  return false;
}

void ParticipantCore::publish(std::size_t index, Nanos stamp, std::function<void()> send,
                              std::function<void()> send_to_observers) {
  const bool by_observer = outputRead(index, stamp, true);
  const bool by_other = outputRead(index, stamp, false);
  if (by_observer || by_other) {
    ++sent_;
    send();
  }
  if (!send_to_observers) {  // one topic for all: kept only if nobody read it
    if (by_observer || by_other) return;
    send_to_observers = std::move(send);
  } else if (by_observer) {
    ++sent_;
    send_to_observers();
    return;
  }
  // an observer may read it at t_end (on the lane if there is one)
  ++deferred_;
  outputs_[index].kept.push_back(Kept{static_cast<uint64_t>(stamp / base_ns_), std::move(send_to_observers)});
}

void ParticipantCore::trimKept(uint64_t confirmed) {
  // the run ends at a step >= confirmed: an observer reads stamp floor(k_end / m) * m at the end
  const uint64_t keep_from = confirmed / multiple_ * multiple_;
  for (Output& o : outputs_)
    while (!o.kept.empty() && o.kept.front().s < keep_from) o.kept.pop_front();
}

void ParticipantCore::sendKeptAt(uint64_t k_end) {
  const uint64_t s_end = k_end / multiple_ * multiple_;
  for (Output& o : outputs_)
    for (auto it = o.kept.begin(); it != o.kept.end(); ++it)
      if (it->s == s_end) {
        try {
          ++sent_;
          it->send();
        } catch (const std::exception& e) {
          h_.logError(name_ + ": publishing the final outputs failed: " + e.what());
        }
        o.kept.erase(it);
        break;
      }
}

void ParticipantCore::onCommand(const Command& c) {
  if (closed_) return;
  last_heard_wall_ = h_.wallNow();
  switch (c.command) {
    case Cmd::Sync: {
      if (failed_) { report(St::Error, c.step, 0, error_); return; }
      if (!configured_ || !checkPeriod(c.dt_s)) return;
      try {
        h_.runEndKnown(c.t);
      } catch (const std::exception& e) {
        fail(e.what());
        return;
      }
      try {
        h_.topicsAnnounced(c.table.topics, c.table.participants);
      } catch (const std::exception& e) {
        fail(std::string("subscribing to the announced topics failed: ") + e.what());
        return;
      }
      const std::string missing = h_.missingLinks();
      report(missing.empty() ? St::Ready : St::Waiting, c.step, 0, missing);
      return;
    }
    case Cmd::Start:
      if (failed_) { report(St::Error, 0, 0, error_); return; }
      if (!configured_ || started_ || !checkPeriod(c.dt_s)) return;
      started_ = true;
      applyTable(c.table);
      last_report_wall_ = last_tick_wall_ = last_heard_wall_;
      try {
        h_.publishOutputs(0);  // the state at t_0, before anyone steps
      } catch (const std::exception& e) {
        fail(std::string("publishing the initial outputs failed: ") + e.what());
      }
      return;
    case Cmd::Grant:
      if (!started_ || failed_) return;
      horizon_ = observer_ ? c.observer_step : c.step;
      trimKept(c.confirmed);
      tryStep();
      return;
    case Cmd::Query:
      if (!started_) return;
      report(St::Waiting, n_, static_cast<Nanos>(n_) * base_ns_, describeWait());
      return;
    case Cmd::Finish:
      closing_ = true;
      t_close_ = c.t;
      k_close_ = c.step;
      if (started_) sendKeptAt(c.step);
      tryClose();
      return;
    case Cmd::Abort:
      try {
        h_.close(c.t, true);
      } catch (const std::exception& e) {
        h_.logError(name_ + ": closing failed: " + e.what());
      }
      closed_ = true;
      report(St::Closed, c.step, c.t, c.reason);
      return;
  }
}

std::string ParticipantCore::describeWait() const {
  const Nanos t = static_cast<Nanos>(n_) * base_ns_;
  if (failed_) return "failed: " + error_;
  if (finished_) return "finished at t = " + seconds(t);
  if (n_ >= horizon_) return "done through t = " + seconds(t) + ", waiting for a grant";
  std::string w;
  for (const InputPort* in : inputs_)
    if (!in->readyFor(t))
      w += (w.empty() ? "" : ", ") + in->resolvedTopic() + " stamped " + seconds(in->stampFor(t));
  return "step " + std::to_string(n_) + " (t = " + seconds(t) + ") waits for " + (w.empty() ? "nothing" : w);
}

void ParticipantCore::onArrival() { tryStep(); }

void ParticipantCore::tryClose() {
  if (!closing_ || closed_ || !h_.readyToClose(t_close_)) return;
  try {
    h_.close(t_close_, false);
  } catch (const std::exception& e) {
    h_.logError(name_ + ": closing failed: " + e.what());
  }
  closed_ = true;
  closing_ = false;
  report(St::Closed, k_close_, t_close_);
}

void ParticipantCore::reportProgress(bool force) {
  const bool boundary = n_ / window_ > reported_ / window_;
  const bool granted_done = n_ >= horizon_ && reported_ < horizon_;
  if (!(force || boundary || granted_done)) {
    if (n_ <= reported_ || h_.wallNow() - last_report_wall_ < report_wall_s_) return;
  }
  reported_ = n_;
  last_report_wall_ = h_.wallNow();
  report(St::Done, n_, static_cast<Nanos>(n_) * base_ns_);
}

void ParticipantCore::tryStep() {
  const uint64_t n0 = n_;
  stepWhileReady();
  if (n_ != n0) last_heard_wall_ = h_.wallNow();  // a long step of its own is no silence
}

void ParticipantCore::stepWhileReady() {
  if (closing_) { tryClose(); return; }
  if (!started_ || failed_ || closed_ || finished_) return;
  while (n_ < horizon_) {
    const Nanos t = static_cast<Nanos>(n_) * base_ns_;
    for (const InputPort* in : inputs_)
      if (!in->readyFor(t)) return;  // wait for the inputs held at t_n
    const Nanos t_next = t + period_ns_;
    try {
      const double c0 = monotonicNow();
      watch_.enter(t, c0);
      h_.step(t, dt_s_);
      watch_.leave();
      compute_s_ += monotonicNow() - c0;
      h_.publishOutputs(t_next);
    } catch (const std::exception& e) {
      watch_.leave();
      fail("step " + std::to_string(n_) + " (t = " + std::to_string(t * 1e-9) + " s) failed: " + e.what());
      return;
    }
    // keep what a later step or the close at t_end >= t_n + base step may still read
    for (InputPort* in : inputs_) in->dropStampsBefore(in->stampFor(t + base_ns_));
    n_ += multiple_;
    if (h_.finished()) {
      finished_ = true;
      reported_ = n_;
      report(St::Finished, n_, t_next);
      return;
    }
    reportProgress(false);
  }
  reportProgress(false);  // everything granted done (also when a grant shrank below n)
}

}  // namespace hbt::cosim::core
