// Explicit Runge-Kutta 5(4) of Dormand and Prince with adaptive steps, for small non-stiff or
// mildly stiff systems integrated over many short intervals with inputs that jump between them
// (a one-step method: nothing of an interval's history is carried into the next, so a jump in the
// right-hand side at an interval boundary costs no restart).
//
// Method: J. R. Dormand, P. J. Prince, "A family of embedded Runge-Kutta formulae", J. Comput.
// Appl. Math. 6 (1980) 19-26 (the tableau of Hairer, Nørsett & Wanner, Solving Ordinary
// Differential Equations I, 2nd ed., Springer 1993, Table 5.2, with its step-size control,
// section II.4). Seven stages, the last one the first of the next step (FSAL); 5th-order
// solution, local error estimated from the embedded 4th-order one:
//   y_{n+1} = y_n + h Σ b_i k_i,  err = h Σ (b_i - b̂_i) k_i,
//   ‖err‖ = sqrt(mean_i (err_i / (atol_i + rtol max(|y_n,i|, |y_{n+1},i|)))²)   (accepted if ≤ 1),
//   h_new = h min(5, max(0.2, 0.9 ‖err‖^(-1/5)))   (no growth right after a rejection).
// Integrals (optional): nq components q with dq/dt = g(y) that the state's derivatives do not
// depend on, advanced with the same stages and weights (q_{n+1} = q_n + h Σ b_i g(Y_i)), outside
// the error norm: their accuracy is the state's. Any linear invariant c·y + d·q whose derivative is
// constant is kept to round-off (a property of every Runge-Kutta method), so balances between the
// state and its integrals close exactly.
//
// The right-hand side: rhs(y, yd, qd) writes dy/dt into yd[n] and dq/dt into qd[nq] (qd null: not
// wanted). Storage is allocated once by the constructor; integrate() does not allocate.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "common/errors.hpp"

namespace hbt {

class DormandPrince {
 public:
  /// n states with absolute tolerances atol[n] (in y's units) and relative tolerance rtol, nq
  /// integrals, at most max_steps accepted or rejected steps per integrate(); owner names the
  /// model in error messages.
  DormandPrince(std::string owner, int n, int nq, double rtol, std::vector<double> atol, long max_steps)
      : owner_(std::move(owner)), n_(n), nq_(nq), rtol_(rtol), atol_(std::move(atol)), max_steps_(max_steps),
        y1_(n), ys_(n), q1_(nq) {
    if (n <= 0 || nq < 0 || static_cast<int>(atol_.size()) != n || !(rtol > 0.0) || max_steps <= 0)
      throw ModelDivergence(owner_, "Runge-Kutta", "need n > 0, nq >= 0, one absolute tolerance per state, rtol > 0");
    for (auto& k : k_) k.assign(n, 0.0);
    for (auto& g : g_) g.assign(nq, 0.0);
  }

  /// Advances y[n] (and the integrals q[nq], if nq > 0) over [0, t_end] [s], the last step ending
  /// exactly at t_end, starting with the step size the previous call ended with (t_end at the
  /// first call). Returns the steps taken (accepted + rejected). Throws ModelDivergence naming
  /// `quantity` on a non-finite state or after max_steps.
  template <class Rhs>
  long integrate(Rhs&& rhs, double t_end, double* y, double* q, const char* quantity) {
    double t = 0.0;
    double h = h_next_ > 0.0 ? std::min(h_next_, t_end) : t_end;
    long steps = 0;
    bool rejected = false;
    rhs(y, k_[0].data(), nq_ ? g_[0].data() : nullptr);
    while (t < t_end) {
      if (++steps > max_steps_)
        throw ModelDivergence(owner_, quantity, "more than " + std::to_string(max_steps_) + " Runge-Kutta steps");
      const bool last = t + h >= t_end * (1.0 - 1e-12);
      const double hs = last ? t_end - t : h;
      const double e = trialStep(rhs, hs, y);
      if (!std::isfinite(e)) throw ModelDivergence(owner_, quantity, "non-finite value");
      if (e <= 1.0) {
        t = last ? t_end : t + hs;
        for (int i = 0; i < n_; ++i) y[i] = y1_[i];
        if (nq_)
          for (int i = 0; i < nq_; ++i) q[i] += q1_[i];
        std::swap(k_[0], k_[6]);  // FSAL
        if (nq_) std::swap(g_[0], g_[6]);
        const double f = std::min(kMaxGrowth, std::max(kMinShrink, kSafety * std::pow(std::max(e, 1e-10), -0.2)));
        if (!last || hs >= h) h = hs * (rejected ? std::min(1.0, f) : f);
        rejected = false;
      } else {
        h = hs * std::max(kMinShrink, kSafety * std::pow(e, -0.2));
        rejected = true;
      }
    }
    h_next_ = h;
    return steps;
  }

  /// Forgets the step size carried between calls (the next integrate() starts with its t_end).
  void reset() { h_next_ = 0.0; }

 private:
  static constexpr double kSafety = 0.9, kMaxGrowth = 5.0, kMinShrink = 0.2;

  // One trial step of size h from y (k_[0], g_[0] = derivatives at y): the solution in y1_, the
  // integrals' increments in q1_, the stages 2..7 in k_/g_; returns the error norm.
  template <class Rhs>
  double trialStep(Rhs& rhs, double h, const double* y) {
    static constexpr double a[6][6] = {
        {1.0 / 5.0},
        {3.0 / 40.0, 9.0 / 40.0},
        {44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0},
        {19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0},
        {9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0},
        {35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0}};
    static constexpr double e[7] = {71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0,
                                    -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0};
    for (int s = 1; s <= 6; ++s) {
      double* Y = s < 6 ? ys_.data() : y1_.data();  // stage 7 is at the new solution
      for (int i = 0; i < n_; ++i) {
        double sum = 0.0;
        for (int j = 0; j < s; ++j) sum += a[s - 1][j] * k_[j][i];
        Y[i] = y[i] + h * sum;
      }
      rhs(Y, k_[s].data(), nq_ ? g_[s].data() : nullptr);
    }
    for (int i = 0; i < nq_; ++i) {  // b_i = the last row of a (b_7 = 0)
      double sum = 0.0;
      for (int j = 0; j < 6; ++j) sum += a[5][j] * g_[j][i];
      q1_[i] = h * sum;
    }
    double norm = 0.0;
    for (int i = 0; i < n_; ++i) {
      double sum = 0.0;
      for (int j = 0; j < 7; ++j) sum += e[j] * k_[j][i];
      const double w = atol_[i] + rtol_ * std::max(std::abs(y[i]), std::abs(y1_[i]));
      const double r = h * sum / w;
      norm += r * r;
    }
    return std::sqrt(norm / n_);
  }

  std::string owner_;
  int n_, nq_;
  double rtol_;
  std::vector<double> atol_;
  long max_steps_;
  double h_next_ = 0.0;
  std::array<std::vector<double>, 7> k_, g_;  // stage derivatives of the state and the integrals
  std::vector<double> y1_, ys_, q1_;
};

}  // namespace hbt
