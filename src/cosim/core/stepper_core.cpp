#include "cosim/core/stepper_core.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

#include "cosim/core/step_watch.hpp"

namespace hbt::cosim::core {
namespace {
// Wall time the stepper waits for every CLOSED before it completes without the missing ones [s]:
// after FINISH the recorder flushes its bag (seconds on a loaded machine); after ABORT a
// participant that failed may never answer, so the run ends promptly.
constexpr double kCloseWaitAfterFinish_s = 5.0;
constexpr double kCloseWaitAfterAbort_s = 0.7;

std::string seconds(Nanos t) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(3) << toSec(t) << " s";
  return os.str();
}
}  // namespace

std::string validate(const StepperConfig& c) {
  const std::string w = c.where + ": key ";
  if (c.participants.empty()) return w + "'participants': missing or empty list of participant names";
  std::set<std::string> names;
  for (const auto& n : c.participants)
    if (!names.insert(n).second) return w + "'participants': '" + n + "' listed twice";
  if (!(c.dt_s >= 1e-4 && c.dt_s <= 1.0)) return w + "'dt_s': macro step must be in [1e-4, 1] s";
  if (!(c.timeout_s > 0.0) || !(c.startup_timeout_s > 0.0)) return w + "'timeout_s': must be > 0";
  if (std::isnan(c.until_s)) return w + "'until_s': NaN";
  if (!(c.clock_period_s >= 0.0 && c.clock_period_s <= 3600.0)) return w + "'clock_period_s': must be in [0, 3600] s";
  if (!(c.clock_wall_period_s >= 0.0 && c.clock_wall_period_s <= 60.0))
    return w + "'clock_wall_period_s': must be in [0, 60] s";
  if (c.window_steps < 1 || c.window_steps > 100000) return w + "'window_steps': must be in [1, 100000] base steps";
  std::set<std::string> seen;
  for (std::size_t g = 0; g < c.order.size(); ++g) {
    if (c.order[g].empty()) return w + "'order': group " + std::to_string(g + 1) + " is empty";
    for (const auto& n : c.order[g]) {
      if (!names.count(n))
        return w + "'order': '" + n + "' is not a participant of this run (key 'participants')";
      if (!seen.insert(n).second) return w + "'order': '" + n + "' appears twice";
    }
  }
  return "";
}

StepperCore::StepperCore(StepperConfig cfg, StepperTransport& tr) : cfg_(std::move(cfg)), tr_(tr) {
  dt_ns_ = toNanos(cfg_.dt_s);
  clock_period_ns_ = toNanos(cfg_.clock_period_s);
  for (const auto& n : cfg_.participants) peers_[n] = Peer{};
  if (cfg_.until_s > 0.0 && dt_ns_ > 0) {  // first k with t_k >= until_s (1 ns tolerance)
    const Nanos u = toNanos(cfg_.until_s) - 1;
    end_until_ = std::max<uint64_t>(1, static_cast<uint64_t>((u + dt_ns_ - 1) / dt_ns_));
  }
}

double StepperCore::missionDuration_s() const {
  double d = 0.0;
  for (const auto& kv : peers_) d = std::max(d, kv.second.mission_duration_s);
  return d;
}

Nanos StepperCore::runEnd() const {
  const double mission_s = missionDuration_s();
  double end_s = cfg_.until_s > 0.0 ? cfg_.until_s : 0.0;
  if (mission_s > 0.0) end_s = end_s > 0.0 ? std::min(end_s, mission_s) : mission_s;
  return toNanos(end_s);
}

void StepperCore::begin(double wall_s) {
  wall0_ = phase_since_ = wall_s;
  clockAt(0, wall_s);
}

void StepperCore::clockAt(Nanos t, double wall_s) {
  if (last_clock_ >= 0 && (t - last_clock_ < std::max<Nanos>(clock_period_ns_, 1) ||
                           wall_s - last_clock_wall_ < cfg_.clock_wall_period_s))
    return;
  last_clock_ = t;
  last_clock_wall_ = wall_s;
  tr_.publishClock(t);
}

std::string StepperCore::missing(bool (*pred)(const Peer&)) const {
  std::string out;
  for (const auto& n : cfg_.participants)
    if (!pred(peers_.at(n))) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string StepperCore::buildGroups() {
  std::map<std::string, std::string> producer;
  for (const auto& n : cfg_.participants)
    for (const auto& topic : peers_[n].outputs) {
      auto [it, fresh] = producer.emplace(topic, n);
      if (!fresh && it->second != n)
        return "topic " + topic + " is published by both " + it->second + " and " + n;
    }
  groups_.clear();
  if (cfg_.order.empty()) {
    groups_.push_back(cfg_.participants);  // Jacobi: everybody at once
  } else {
    std::set<std::string> listed;
    for (const auto& g : cfg_.order) {
      std::vector<std::string> grp;
      for (const auto& n : g) {
        listed.insert(n);
        if (!peers_[n].observer) grp.push_back(n);
      }
      if (!grp.empty()) groups_.push_back(grp);
    }
    for (const auto& n : cfg_.participants)
      if (!listed.count(n) && !peers_[n].observer)
        return cfg_.where + ": key 'order': participant '" + n + "' is in no group";
    if (groups_.empty()) groups_.emplace_back();
    for (const auto& n : cfg_.participants)  // observers (the recorder): always in the last group
      if (peers_[n].observer) groups_.back().push_back(n);
  }
  for (std::size_t g = 0; g < groups_.size(); ++g)
    for (const auto& n : groups_[g]) peers_[n].group = static_cast<uint32_t>(g);
  return "";
}

void StepperCore::onStatus(const Status& s, double wall_s) {
  auto it = peers_.find(s.node);
  if (it == peers_.end()) return;  // not a participant of this run
  Peer& p = it->second;
  p.compute_s = s.compute_time_s;
  p.cpu.cpu_s = s.process_cpu_s;
  p.cpu.process = s.process;
  switch (phase_) {
    case Phase::Announce:
    case Phase::Sync:
      if (s.status == St::Error) { finish(true, s.message, wall_s); return; }
      p.announced = true;
      if (s.status == St::Announce) {
        p.outputs = s.outputs;
        p.inputs = s.inputs;
        p.observer = s.observer;
        p.mission_duration_s = s.mission_duration_s;
      } else if (s.status == St::Ready || s.status == St::Waiting) {
        p.has_status = true;
        p.last_status = s.status;
        p.last_step = s.step;
        p.waiting_for = s.message;
        p.multiple = s.step_multiple < 1 ? 1 : s.step_multiple;
        if (s.status == St::Ready) {
          p.inputs = s.inputs;
          p.cpu.cpu_at_start_s = s.process_cpu_s;
        }
      }
      return;
    case Phase::Stepping:
      if (s.status == St::Waiting) {  // answer to a QUERY: where it is (not progress: no reset)
        p.answered = true;
        p.waiting_for = s.message;
        if (s.step > p.next) {
          p.next = s.step;
          update(wall_s);
        }
        return;
      }
      if (s.status != St::Done && s.status != St::Finished && s.status != St::Error) return;
      last_progress_ = wall_s;
      query_sent_ = false;
      starved_wait_s_ = 0.0;
      if (s.status == St::Error) {
        p.failed = true;
        p.error = s.message;
        p.next = std::max(p.next, s.step);
        if (s.step < end_error_) {
          end_error_ = s.step;
          error_reason_ = s.message;
        }
      } else {
        p.next = std::max(p.next, s.step);
        if (s.status == St::Finished) {  // after its step n - multiple
          const uint64_t k_f = s.step >= p.multiple ? s.step - p.multiple : 0;
          if (k_f + 1 < end_finished_) {
            end_finished_ = k_f + 1;
            finished_by_ = s.node;
          }
        }
      }
      update(wall_s);
      return;
    case Phase::Closing:
      if (s.status == St::Closed) {
        p.closed = true;
        if (missing([](const Peer& q) { return q.closed; }).empty()) complete();
      }
      return;
    case Phase::Done:
      return;
  }
}

void StepperCore::sendSync() {
  ++sync_round_;
  Command c;
  c.command = Cmd::Sync;
  c.step = sync_round_;
  c.t = runEnd();  // everyone has announced: the end as known before step 0
  c.dt_s = cfg_.dt_s;
  fillTable(c.table, false);  // everyone has announced: observers learn the topics to read from it
  tr_.sendCommand(c);
}

void StepperCore::sendStart() {
  Command c;
  c.command = Cmd::Start;
  c.dt_s = cfg_.dt_s;
  fillTable(c.table, true);
  tr_.sendCommand(c);
}

void StepperCore::fillTable(Table& t, bool readers) const {
  std::map<std::string, std::size_t> index;
  for (const auto& n : cfg_.participants) {
    const Peer& p = peers_.at(n);
    t.participants.push_back(n);
    t.participant_multiple.push_back(p.multiple);
    t.participant_group.push_back(p.group);
    for (const auto& topic : p.outputs) {
      index[topic] = t.topics.size();
      t.topics.push_back(topic);
      t.topic_multiple.push_back(p.multiple);
      t.topic_group.push_back(p.group);
    }
  }
  t.window = cfg_.window_steps;
  t.report_wall_s = heartbeatPeriod_s();
  if (!readers) return;
  for (const auto& n : cfg_.participants) {
    const Peer& c = peers_.at(n);
    for (const auto& topic : c.inputs) {
      const auto it = index.find(topic);
      if (it == index.end()) continue;  // no producer in this run: nothing to decimate
      t.reader_topic.push_back(static_cast<uint32_t>(it->second));
      t.reader_multiple.push_back(c.multiple);
      t.reader_fresh.push_back(!c.observer && t.topic_group[it->second] < c.group);
      t.reader_observer.push_back(c.observer);
    }
  }
}

uint64_t StepperCore::endStep() const { return std::min({end_until_, end_finished_, end_error_}); }

void StepperCore::update(double wall_s) {
  if (phase_ != Phase::Stepping) return;
  uint64_t d = kNever, all = kNever;  // done through: non-observers, everyone
  for (const auto& kv : peers_) {
    all = std::min(all, kv.second.next);
    if (!kv.second.observer) d = std::min(d, kv.second.next);
  }
  const uint64_t e = endStep();
  if (e != kNever && all >= e) {  // the end is committed: nobody can report anything below e
    k_ = e;
    t_ = static_cast<Nanos>(e) * dt_ns_;
    if (last_clock_ < t_) {  // observers see the end time
      last_clock_ = t_;
      tr_.publishClock(t_);
    }
    const bool by_error = end_error_ == e && end_error_ < std::min(end_until_, end_finished_);
    for (const auto& kv : peers_)  // failed in a step the lock-step would never have run
      if (kv.second.failed && !(by_error && kv.second.error == error_reason_))
        tr_.warn("stepper: ignored, in a step at or after the end of the run (t = " + seconds(t_) +
                 "): " + kv.second.error);
    if (by_error) finish(true, error_reason_, wall_s);
    else if (end_finished_ == e) finish(false, "end of mission", wall_s);
    else finish(false, "until_s reached", wall_s);
    return;
  }
  const uint64_t w = cfg_.window_steps;
  const uint64_t slowest = all == kNever ? 0 : all;
  const uint64_t h = std::min(slowest / w * w + 2 * w, e);
  const uint64_t h_obs = std::min(d == kNever ? e : d + 1, e);
  const uint64_t l = std::min(d == kNever ? slowest : d, e);
  if (h != horizon_ || h_obs != horizon_obs_) {
    horizon_ = h;
    horizon_obs_ = h_obs;
    confirmed_ = l;
    Command c;
    c.command = Cmd::Grant;
    c.step = h;
    c.observer_step = h_obs;
    c.confirmed = l;
    c.t = static_cast<Nanos>(h) * dt_ns_;
    c.dt_s = cfg_.dt_s;
    ++grants_;
    last_grant_ = c;
    last_sent_wall_ = wall_s;
    tr_.sendCommand(c);
  }
  if (slowest != k_) {
    k_ = slowest;
    t_ = static_cast<Nanos>(slowest) * dt_ns_;
    clockAt(t_, wall_s);
    tr_.progress(false);
  }
}

void StepperCore::onTick(double wall_s) {
  // The stepper itself did not run for a while (its thread starved, or blocked writing to a full
  // console pipe): what arrived meanwhile waits unread behind this tick. The wall time it was
  // away counts for nobody's timeout.
  if (last_tick_wall_ >= 0.0 && wall_s - last_tick_wall_ > heartbeatPeriod_s()) {
    const double away_s = wall_s - last_tick_wall_;
    last_progress_ += away_s;
    phase_since_ += away_s;
  }
  last_tick_wall_ = wall_s;
  switch (phase_) {
    case Phase::Announce:
    case Phase::Sync: {
      if (wall_s - phase_since_ > cfg_.startup_timeout_s) {
        const std::string m = missing([](const Peer& p) { return p.announced; });
        std::string links;
        for (const auto& n : cfg_.participants)
          if (!peers_[n].waiting_for.empty()) links += " " + n + ":" + peers_[n].waiting_for;
        finish(true, "start-up timed out after " + std::to_string(cfg_.startup_timeout_s) + " s; " +
                         (m.empty() ? "links not connected:" + links : "no answer from: " + m),
               wall_s);
        return;
      }
      if (phase_ == Phase::Announce) {
        if (!missing([](const Peer& p) { return p.announced; }).empty()) return;
        const std::string err = buildGroups();
        if (!err.empty()) { finish(true, err, wall_s); return; }
        phase_ = Phase::Sync;
        sendSync();
        return;
      }
      bool all_ready = true;
      for (const auto& n : cfg_.participants) {
        const Peer& p = peers_[n];
        all_ready = all_ready && p.has_status && p.last_status == St::Ready && p.last_step == sync_round_;
      }
      if (!all_ready) { sendSync(); return; }
      phase_ = Phase::Stepping;
      wall0_ = last_progress_ = wall_s;
      k_ = 0;
      t_ = 0;
      for (auto& kv : peers_) kv.second.waiting_for.clear();
      sendStart();
      update(wall_s);
      return;
    }
    case Phase::Stepping:
      if (wall_s - last_progress_ > cfg_.timeout_s + starved_wait_s_) {
        if (starved(wall_s)) {  // alive but starved of CPU: wait for it, say so once
          if (starved_wait_s_ == 0.0)
            tr_.warn("stepper: " + starved_names_ + " runnable but starved of CPU: waiting beyond the " +
                     std::to_string(cfg_.timeout_s) + " s timeout");
          starved_wait_s_ += 0.5 * cfg_.timeout_s;
          probePeers(wall_s);
        } else {
          timeout(wall_s);
        }
      } else if (wall_s - last_progress_ > 0.5 * cfg_.timeout_s && !query_sent_) {
        query_sent_ = true;
        probePeers(wall_s);
        for (auto& kv : peers_) kv.second.answered = false;
        Command c;
        c.command = Cmd::Query;
        c.step = k_;
        c.t = t_;
        c.dt_s = cfg_.dt_s;
        last_sent_wall_ = wall_s;
        tr_.sendCommand(c);
      } else {
        heartbeat(wall_s);
      }
      return;
    case Phase::Closing:
      if (wall_s - phase_since_ > (aborted_ ? kCloseWaitAfterAbort_s : kCloseWaitAfterFinish_s)) {
        tr_.warn("stepper: no CLOSED from " + missing([](const Peer& p) { return p.closed; }));
        complete();
      }
      return;
    case Phase::Done:
      return;
  }
}

void StepperCore::heartbeat(double wall_s) {
  if (grants_ == 0 || wall_s - last_sent_wall_ < heartbeatPeriod_s()) return;
  last_sent_wall_ = wall_s;
  ++heartbeats_;
  tr_.sendCommand(last_grant_);  // idempotent: the horizons every participant already has
}

void StepperCore::probePeers(double wall_s) {
  for (auto& kv : peers_) {
    kv.second.probed = tr_.taskState(kv.first, kv.second.cpu.process);
    kv.second.probed_wall = wall_s;
  }
}

bool StepperCore::starved(double wall_s) {
  if (starved_wait_s_ >= (kMaxStarvedWait_timeouts - 1.0) * cfg_.timeout_s) return false;
  const uint64_t e = endStep();
  std::string names;
  bool any = false;
  for (const auto& n : cfg_.participants) {
    const Peer& p = peers_.at(n);
    if (p.next >= e || (query_sent_ && p.answered)) continue;  // not silent
    const TaskState now = tr_.taskState(n, p.cpu.process);
    const bool runnable = now.known && p.probed.known && (now.state == 'R' || now.state == 'D');
    const double dt = wall_s - p.probed_wall;
    if (!runnable || !(dt > 0.0) || now.cpu_s - p.probed.cpu_s >= kStarvedCpuShare * dt) return false;
    names += (any ? ", " : "") + n;
    any = true;
  }
  if (any) starved_names_ = names;
  return any;
}

void StepperCore::timeout(double wall_s) {
  std::string silent, waits;
  const uint64_t e = endStep();
  for (const auto& n : cfg_.participants) {
    Peer& p = peers_[n];
    if (p.next >= e) continue;  // done: nothing to wait for
    if (query_sent_ && p.answered) {
      if (!p.waiting_for.empty()) waits += "; " + n + ": " + p.waiting_for;
    } else {
      silent += (silent.empty() ? "" : ", ") + n + " (done through t = " +
                seconds(static_cast<Nanos>(p.next) * dt_ns_) + ")";
      p.closed = true;  // silent participants will not close anything: do not wait
    }
  }
  std::ostringstream os;
  os << std::defaultfloat;
  if (!silent.empty())
    os << "participant(s) " << silent << " did not answer within " << cfg_.timeout_s
       << " s: node died or hung";
  else
    os << "no participant progressed for " << cfg_.timeout_s << " s (done through t = " << seconds(t_) << ")";
  os << waits;
  const std::string stuck = StepWatch::describe(steadyNow_s());  // mode:=nodelets: who blocks the thread
  if (!stuck.empty()) os << "; " << stuck;
  if (starved_wait_s_ > 0.0)
    os << "; waited " << starved_wait_s_ << " s more for " << starved_names_ << " (starved of CPU)";
  finish(true, os.str(), wall_s);
}

void StepperCore::finish(bool aborted, const std::string& reason, double wall_s) {
  if (phase_ == Phase::Closing || phase_ == Phase::Done) return;
  aborted_ = aborted;
  reason_ = reason;
  tr_.progress(true);
  tr_.runEnded(aborted, reason);
  phase_ = Phase::Closing;
  phase_since_ = wall_s;
  Command c;
  c.command = aborted ? Cmd::Abort : Cmd::Finish;
  c.step = k_;
  c.t = t_;
  c.dt_s = cfg_.dt_s;
  c.reason = reason;
  tr_.sendCommand(c);
  if (phase_ == Phase::Closing && missing([](const Peer& p) { return p.closed; }).empty()) complete();
}

void StepperCore::complete() {
  if (phase_ == Phase::Done) return;
  phase_ = Phase::Done;
  tr_.complete();
}

}  // namespace hbt::cosim::core
