// Protocol test participant: one mass of a two-mass oscillator split across two nodes.
//
//   m x'' = -k x - k_c (x - x_peer)        [N], x [m], m [kg], k, k_c [N/m]
//
// Each participant integrates its own mass (RK4, `substeps` per macro step) with the peer's
// position stamped t_k held constant over the step (Jacobi coupling, as every node of the twin).
// Two identical masses starting from x_a = x0, x_b = 0 have the exact solution
//   x_a = x0/2 (cos w1 t + cos w2 t),  x_b = x0/2 (cos w1 t - cos w2 t),
//   w1 = sqrt(k/m), w2 = sqrt((k + 2 k_c)/m),
// against which the co-simulation is checked (the coupling error is O(dt)).
// Publishes ProbeSignal values = [x_m, v_m_s] on ~/state. Parameters: peer_topic, x0_m, mass_kg,
// k_n_m, kc_n_m, substeps, finish_after_s (reports FINISHED there; 0 = never).
#include <hybrid_bus_twin/ProbeSignal.h>

#include "common/errors.hpp"
#include "cosim/participant.hpp"
#include "cosim/participant_main.hpp"

namespace hbt::test {

class Oscillator : public cosim::Participant {
 public:
  Oscillator(ros::NodeHandle nh, ros::NodeHandle pnh)
      : Participant(nh, pnh) {}

 protected:
  void configure() override {
    std::string peer;
    if (!pnh_.getParam("peer_topic", peer)) throw InputError("oscillator", "peer_topic", "missing");
    pnh_.param("x0_m", x_, 0.0);
    pnh_.param("mass_kg", m_, 1.0);
    pnh_.param("k_n_m", k_, 100.0);
    pnh_.param("kc_n_m", kc_, 20.0);
    pnh_.param("substeps", substeps_, 10);
    pnh_.param("finish_after_s", finish_after_s_, 0.0);
    if (!(m_ > 0.0)) throw InputError("oscillator", "mass_kg", "must be > 0");
    peer_ = &addInput<hybrid_bus_twin::ProbeSignal>(peer);
    pub_ = addOutput<hybrid_bus_twin::ProbeSignal>(pnh_.getNamespace() + "/state");
  }
  void publishOutputs(const ros::Time& t) override {
    hybrid_bus_twin::ProbeSignal s;
    s.header.stamp = t;
    s.values = {x_, v_};
    pub_.publish(s);
    t_ = t.toSec();
  }
  void step(const ros::Time& t, double dt_s) override {
    const double xp = peer_->at(t).values.at(0);
    const double h = dt_s / substeps_;
    auto acc = [&](double x) { return (-k_ * x - kc_ * (x - xp)) / m_; };
    for (int i = 0; i < substeps_; ++i) {
      const double k1x = v_, k1v = acc(x_);
      const double k2x = v_ + 0.5 * h * k1v, k2v = acc(x_ + 0.5 * h * k1x);
      const double k3x = v_ + 0.5 * h * k2v, k3v = acc(x_ + 0.5 * h * k2x);
      const double k4x = v_ + h * k3v, k4v = acc(x_ + h * k3x);
      x_ += h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
      v_ += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    }
    t_ = t.toSec() + dt_s;
  }
  bool finished() const override { return finish_after_s_ > 0.0 && t_ >= finish_after_s_ - 1e-9; }

 private:
  cosim::Input<hybrid_bus_twin::ProbeSignal>* peer_ = nullptr;
  cosim::Output pub_;
  double x_ = 0.0, v_ = 0.0, m_ = 1.0, k_ = 100.0, kc_ = 20.0, t_ = 0.0, finish_after_s_ = 0.0;
  int substeps_ = 10;
};

}  // namespace hbt::test

int main(int argc, char** argv) {
  return hbt::cosim::runNode<hbt::test::Oscillator>(argc, argv, "oscillator");
}
