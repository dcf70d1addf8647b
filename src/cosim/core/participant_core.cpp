#include "cosim/core/participant_core.hpp"

#include <chrono>

#include <ctime>
#include <exception>
#include <sstream>

#include "common/errors.hpp"

namespace hbt::cosim::core {
namespace {
// Compute time is read on the steady clock (vDSO, ~0.1 us per reading here), not the thread
// CPU clock: CLOCK_THREAD_CPUTIME_ID is a system call, 2.6 us per reading on this VM, i.e. 42 us
// per base step for 8 participants -- most of a nodelet exchange (scripts/twin bench cosim).
// On a thread that is not preempted the two agree; under load it counts the waiting too.
double monotonicNow() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

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
  report(St::Error, k_pending_, t_pending_, error_);
}

void ParticipantCore::report(St status, uint64_t step, Nanos t, const std::string& msg) {
  Status s;
  s.node = name_;
  s.status = status;
  s.step = step;
  s.t = t;
  s.compute_time_s = compute_s_;
  s.message = msg;
  if (status == St::Announce) {
    s.outputs = outputs_;
    s.observer = observer_;
    s.mission_duration_s = mission_duration_s_;
  }
  s.step_multiple = multiple_;
  h_.sendStatus(s);
}

bool ParticipantCore::onAnnounceTick() {
  if (closed_ || started_) return false;
  if (failed_) report(St::Error, k_pending_, t_pending_, error_);
  else if (configured_) report(St::Announce, 0, 0);
  return true;
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
}

void ParticipantCore::onCommand(const Command& c) {
  if (closed_) return;
  switch (c.command) {
    case Cmd::Sync: {
      if (failed_) { report(St::Error, c.step, 0, error_); return; }
      if (!configured_ || !checkPeriod(c.dt_s)) return;
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
      if (failed_) { report(St::Error, c.step, 0, error_); return; }
      if (!configured_ || started_ || !checkPeriod(c.dt_s)) return;
      started_ = true;
      applyTable(c.table);
      try {
        h_.publishOutputs(0);  // the state at t_0, before anyone steps
      } catch (const std::exception& e) {
        fail(std::string("publishing the initial outputs failed: ") + e.what());
      }
      return;
    case Cmd::Step:
      if (failed_) { report(St::Error, c.step, c.t, error_); return; }
      if (!started_ || c.group != group_ || c.step % multiple_ != 0) return;
      pending_ = true;
      k_pending_ = c.step;
      t_pending_ = c.t;
      tryStep();
      return;
    case Cmd::Finish:
      pending_ = false;
      closing_ = true;
      t_close_ = c.t;
      k_close_ = c.step;
      tryClose();
      return;
    case Cmd::Abort:
      try {
        h_.close(c.t, true);
      } catch (const std::exception& e) {
        h_.logError(name_ + ": closing failed: " + e.what());
      }
      closed_ = true;
      pending_ = false;
      report(St::Closed, c.step, c.t, c.reason);
      return;
  }
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

void ParticipantCore::tryStep() {
  if (closing_) { tryClose(); return; }
  if (!pending_ || failed_ || closed_) return;
  const Nanos t = t_pending_;
  for (const InputPort* in : inputs_)
    if (!in->readyFor(t)) return;  // wait for the inputs held at t_k
  pending_ = false;
  const Nanos t_next = t + period_ns_;
  try {
    const double c0 = monotonicNow();
    h_.step(t, dt_s_);
    compute_s_ += monotonicNow() - c0;
    h_.publishOutputs(t_next);
  } catch (const std::exception& e) {
    fail("step " + std::to_string(k_pending_) + " (t = " + std::to_string(t * 1e-9) +
         " s) failed: " + e.what());
    return;
  }
  // keep what a later step or the close at t_end >= t_k + base step may still read
  for (InputPort* in : inputs_) in->dropStampsBefore(in->stampFor(t + base_ns_));
  report(h_.finished() ? St::Finished : St::Done, k_pending_, t_next);
}

}  // namespace hbt::cosim::core
