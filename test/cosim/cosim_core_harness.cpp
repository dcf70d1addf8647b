#include "cosim_core_harness.hpp"

namespace hbt::cosim::core::testing {

FakeParticipant::FakeParticipant(Bus& bus, std::string name, std::vector<std::string> in,
                                 std::vector<std::string> out, Faults f, bool obs)
    : core(std::move(name), *this), outputs(std::move(out)), faults(std::move(f)), observer(obs), bus_(bus) {
  for (const auto& topic : in) {
    inputs.push_back(std::make_unique<FakeInput>(topic, [this] { core.onArrival(); }));
    bus.subscribers[(observer ? "lane:" : "") + topic].push_back(inputs.back().get());
  }
}

void FakeParticipant::topicsAnnounced(const std::vector<std::string>& topics,
                                      const std::vector<std::string>& /*participants*/) {
  announced_tables.push_back(topics);
  if (!record_all) return;
  for (const auto& topic : topics) {
    bool known = false;
    for (const auto& in : inputs) known = known || in->resolvedTopic() == topic;
    if (known) continue;
    inputs.push_back(std::make_unique<FakeInput>(topic, [this] { core.onArrival(); }));
    bus_.subscribers[(observer ? "lane:" : "") + topic].push_back(inputs.back().get());
    core.addInput(inputs.back().get());
  }
}

void FakeParticipant::runEndKnown(Nanos t_end) {
  run_ends.push_back(t_end);
  if (faults.runs_until_s >= 0.0 && t_end > toNanos(faults.runs_until_s))
    throw std::runtime_error("model.fmu: stopTime " + std::to_string(faults.runs_until_s) + " s is before the end");
}

void FakeParticipant::configure() {
  if (faults.configure_throws) throw std::runtime_error("cfg.yaml: key 'mass_kg': must be > 0");
  for (auto& in : inputs) core.addInput(in.get());
  for (const auto& o : outputs) core.addOutput(o);
  core.setObserver(observer);
  if (on_configure) on_configure(core);
}

StepLog FakeParticipant::readAll(Nanos t) const {
  StepLog log{t, 0.0, {}};
  for (const auto& in : inputs) log.read[in->resolvedTopic()] = in->at(t);
  return log;
}

void FakeParticipant::publishOutputs(Nanos t) {
  published.push_back(t);
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const std::string topic = outputs[i];
    core.publish(
        i, t,
        [this, topic, t] {
          sent[topic].push_back(t);
          for (FakeInput* in : bus_.subscribers[topic]) bus_.postTopic([in, t] { in->deliver(t, t); });
        },
        [this, topic, t] {
          sent_lane[topic].push_back(t);
          for (FakeInput* in : bus_.subscribers["lane:" + topic]) bus_.postTopic([in, t] { in->deliver(t, t); });
        });
  }
}

void FakeParticipant::step(Nanos t, double dt_s) {
  if (faults.throw_at_step >= 0 && static_cast<int64_t>(core.next()) == faults.throw_at_step)
    throw std::runtime_error("boom");
  bus_.wall += faults.step_wall_s;
  StepLog log = readAll(t);
  log.dt_s = dt_s;
  (observer ? records : steps).push_back(log);
  t_ = t + toNanos(dt_s);
}

bool FakeParticipant::finished() const {
  return faults.finish_at_s >= 0.0 && toSec(t_) >= faults.finish_at_s - 1e-9;
}

void FakeParticipant::close(Nanos t_end, bool aborted) {
  closed_at.push_back(t_end);
  closed_aborted.push_back(aborted);
  if (observer && !aborted && (records.empty() || records.back().t < t_end))
    records.push_back(readAll(t_end));
}

bool FakeParticipant::readyToClose(Nanos t_end) const {
  if (faults.never_ready_to_close) return false;
  if (!observer) return true;
  for (const auto& in : inputs)
    if (!in->readyFor(t_end)) {
      ++close_waits;
      return false;
    }
  return true;
}

void FakeParticipant::sendStatus(const Status& s) {
  if (hung) return;
  bus_.post([this, s] {
    if (!bus_.stepperHung()) bus_.stepper->onStatus(s, bus_.wall);
  });
  // silent_from_step: dies once it has reported it is done below k
  if (faults.silent_from_step >= 0 && s.status == St::Done &&
      s.step >= static_cast<uint64_t>(faults.silent_from_step))
    hung = true;
}

double FakeParticipant::wallNow() const { return bus_.wall; }

void FakeParticipant::command(const Command& c) {
  if (faults.never_announce || hung) return;
  const auto silent = static_cast<uint64_t>(faults.silent_from_step);
  if (c.command == Cmd::Grant && faults.silent_from_step >= 0 &&
      (observer ? c.observer_step : c.step) > silent) {
    Command clamped = c;  // steps what it can below k, then hangs there for good
    clamped.step = clamped.observer_step = silent;
    core.onCommand(clamped);
    return;
  }
  core.onCommand(c);
}

FakeParticipant& Bus::add(const std::string& name, std::vector<std::string> in,
                          std::vector<std::string> out, Faults f, bool observer) {
  parts.push_back(std::make_unique<FakeParticipant>(*this, name, std::move(in), std::move(out), f, observer));
  return *parts.back();
}

FakeParticipant& Bus::addRecorder(std::vector<std::string> topics, double period_s) {
  FakeParticipant& r = add("recorder", std::move(topics), {}, {}, true);
  if (period_s > 0.0)
    r.on_configure = [period_s](ParticipantCore& c) {
      c.requestPeriod({period_s, "recorder parameters (launch file)", "record_period_s", true});
    };
  return r;
}

FakeParticipant& Bus::get(const std::string& name) {
  for (auto& p : parts)
    if (p->core.name() == name) return *p;
  throw std::runtime_error("no participant " + name);
}

void Bus::sendCommand(const Command& c) {
  commands.push_back(c);
  for (auto& p : parts) {
    FakeParticipant* fp = p.get();
    post([fp, c] { fp->command(c); });
  }
}

void Bus::postTopic(std::function<void()> f) {
  if (seed == 0) post(std::move(f));
  else topic_pool.push_back(std::move(f));
}

void Bus::pump() {
  for (std::size_t n = 0; !queue.empty() || !topic_pool.empty(); ++n) {
    if (n > 50000000) throw std::runtime_error("bus: runaway");
    seed = seed * 1103515245u + 12345u;  // LCG: which lane, which message
    const unsigned r = (seed >> 16) & 0x7fff;
    if (!topic_pool.empty() && (queue.empty() || r % 2 == 0)) {
      const std::size_t i = r % topic_pool.size();
      auto f = std::move(topic_pool[i]);
      topic_pool.erase(topic_pool.begin() + static_cast<long>(i));
      f();
      continue;
    }
    auto f = std::move(queue.front());
    queue.pop_front();
    f();
  }
}

void Bus::run(StepperConfig cfg, double max_wall_s) {
  stepper = std::make_unique<StepperCore>(std::move(cfg), *this);
  for (auto& p : parts)
    if (!p->faults.never_announce) p->core.start();
  stepper->begin(wall);
  for (int tick = 1; !completed && wall < max_wall_s; ++tick) {
    pump();
    wall += 0.05;
    if (!stepperHung()) stepper->onTick(wall);
    if (tick % 2 == 0)
      for (auto& p : parts)
        if (!p->faults.never_announce && !p->hung) p->core.onTick();
    pump();
  }
}

}  // namespace hbt::cosim::core::testing
