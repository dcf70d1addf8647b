#include "cosim/core/stepper_core.hpp"

#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>

namespace hbt::cosim::core {

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
}

double StepperCore::missionDuration_s() const {
  double d = 0.0;
  for (const auto& kv : peers_) d = std::max(d, kv.second.mission_duration_s);
  return d;
}

void StepperCore::begin(double wall_s) {
  wall0_ = phase_since_ = wall_s;
  clockAt(0);
}

void StepperCore::clockAt(Nanos t) {
  if (last_clock_ >= 0 && t - last_clock_ < std::max<Nanos>(clock_period_ns_, 1)) return;
  last_clock_ = t;
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
  if (s.status == St::Error) {
    if (phase_ != Phase::Closing && phase_ != Phase::Done) finish(true, s.message, wall_s);
    return;
  }
  switch (phase_) {
    case Phase::Announce:
    case Phase::Sync:
      p.announced = true;
      if (s.status == St::Announce) {
        p.outputs = s.outputs;
        p.observer = s.observer;
        p.mission_duration_s = s.mission_duration_s;
      } else if (s.status == St::Ready || s.status == St::Waiting) {
        p.has_status = true;
        p.last_status = s.status;
        p.last_step = s.step;
        p.waiting_for = s.message;
        p.multiple = s.step_multiple < 1 ? 1 : s.step_multiple;
      }
      return;
    case Phase::Stepping:
      if ((s.status == St::Done || s.status == St::Finished) && s.step == k_ && p.due && !p.done) {
        p.done = true;
        if (s.status == St::Finished) finished_seen_ = true;
        for (const auto& n : groups_[group_])
          if (peers_[n].due && !peers_[n].done) return;
        ++group_;
        commandNextGroup(wall_s);
      }
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
  c.dt_s = cfg_.dt_s;
  fillTable(c.table);  // everyone has announced: observers learn the topics to read from it
  tr_.sendCommand(c);
}

void StepperCore::sendStart() {
  Command c;
  c.command = Cmd::Start;
  c.dt_s = cfg_.dt_s;
  fillTable(c.table);
  tr_.sendCommand(c);
}

void StepperCore::fillTable(Table& table) const {
  Table& t = table;
  for (const auto& n : cfg_.participants) {
    const Peer& p = peers_.at(n);
    t.participants.push_back(n);
    t.participant_multiple.push_back(p.multiple);
    t.participant_group.push_back(p.group);
    for (const auto& topic : p.outputs) {
      t.topics.push_back(topic);
      t.topic_multiple.push_back(p.multiple);
      t.topic_group.push_back(p.group);
    }
  }
}

void StepperCore::beginStep(double wall_s) {
  clockAt(t_);
  group_ = 0;
  finished_seen_ = false;
  commandNextGroup(wall_s);
}

void StepperCore::commandNextGroup(double wall_s) {
  for (; group_ < groups_.size(); ++group_) {
    bool any = false;
    for (const auto& n : groups_[group_]) {
      Peer& p = peers_[n];
      p.due = k_ % p.multiple == 0;
      p.done = false;
      any = any || p.due;
    }
    if (!any) continue;
    Command c;
    c.command = Cmd::Step;
    c.step = k_;
    c.t = t_;
    c.dt_s = cfg_.dt_s;
    c.group = static_cast<uint32_t>(group_);
    step_sent_ = wall_s;
    ++step_commands_;
    tr_.sendCommand(c);
    return;
  }
  // base step k complete
  t_ += dt_ns_;
  ++k_;
  tr_.progress(false);
  if (finished_seen_) finish(false, "end of mission", wall_s);
  else if (cfg_.until_s > 0.0 && toSec(t_) >= cfg_.until_s - 1e-9) finish(false, "until_s reached", wall_s);
  else beginStep(wall_s);
}

void StepperCore::onTick(double wall_s) {
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
      wall0_ = wall_s;
      k_ = 0;
      t_ = 0;
      sendStart();
      beginStep(wall_s);
      return;
    }
    case Phase::Stepping:
      if (wall_s - step_sent_ > cfg_.timeout_s) {
        std::string m;
        for (const auto& n : groups_[group_]) {
          Peer& p = peers_[n];
          if (p.due && !p.done) m += (m.empty() ? "" : ", ") + n;
        }
        for (auto& kv : peers_)  // silent participants will not close anything: do not wait
          if (kv.second.due && !kv.second.done) kv.second.closed = true;
        std::ostringstream os;
        os << "participant(s) " << m << " did not answer step " << k_ << " (t = " << std::fixed
           << std::setprecision(3) << toSec(t_) << " s) within " << std::defaultfloat
           << cfg_.timeout_s << " s: node died or hung";
        finish(true, os.str(), wall_s);
      }
      return;
    case Phase::Closing:
      if (wall_s - phase_since_ > (aborted_ ? 0.7 : 5.0)) {
        tr_.warn("stepper: no CLOSED from " + missing([](const Peer& p) { return p.closed; }));
        complete();
      }
      return;
    case Phase::Done:
      return;
  }
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
