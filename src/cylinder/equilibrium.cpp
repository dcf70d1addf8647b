#include "cylinder/equilibrium.hpp"

#include <algorithm>
#include <cmath>

namespace hbt::cylinder {
namespace {

constexpr int kNs = 11;  // equilibrium species except Ar
const Species kSp[kNs] = {kH2, kO2, kN2, kCO, kH, kO, kN, kOH, kNO, kH2O, kCO2};
// Stoichiometric coefficients of the base species (H2, O2, N2, CO) forming each species.
const double kNu[kNs][4] = {{1, 0, 0, 0},     {0, 1, 0, 0},   {0, 0, 1, 0},     {0, 0, 0, 1},
                            {0.5, 0, 0, 0},   {0, 0.5, 0, 0}, {0, 0, 0.5, 0},   {0.5, 0.5, 0, 0},
                            {0, 0.5, 0.5, 0}, {1, 0.5, 0, 0}, {0, 0.5, 0, 1}};
// Element content (C, H, O, N).
const double kA[kNs][4] = {{0, 2, 0, 0}, {0, 0, 2, 0}, {0, 0, 0, 2}, {1, 0, 1, 0},
                           {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}, {0, 1, 1, 0},
                           {0, 0, 1, 1}, {0, 2, 1, 0}, {1, 0, 2, 0}};

bool gaussSolve(double A[5][5], double r[5], int n) {
  for (int c = 0; c < n; ++c) {
    int piv = c;
    for (int i = c + 1; i < n; ++i)
      if (std::fabs(A[i][c]) > std::fabs(A[piv][c])) piv = i;
    if (std::fabs(A[piv][c]) < 1e-300) return false;
    if (piv != c) {
      for (int k = 0; k < n; ++k) std::swap(A[c][k], A[piv][k]);
      std::swap(r[c], r[piv]);
    }
    for (int i = c + 1; i < n; ++i) {
      const double f = A[i][c] / A[c][c];
      for (int k = c; k < n; ++k) A[i][k] -= f * A[c][k];
      r[i] -= f * r[c];
    }
  }
  for (int i = n - 1; i >= 0; --i) {
    double s = r[i];
    for (int k = i + 1; k < n; ++k) s -= A[i][k] * r[k];
    r[i] = s / A[i][i];
  }
  return true;
}

}  // namespace

bool Equilibrium::solve(const std::array<double, 5>& b, double T, double p_Pa,
                        double x_out[kNumSpecies]) {
  const double lnP = std::log(p_Pa / kPref);
  // Base species active only if their element is present (H2<-H, O2<-O, N2<-N, CO<-C).
  const double btot = b[0] + b[1] + b[2] + b[3];
  const bool active[4] = {b[1] > 1e-12 * btot, b[2] > 1e-12 * btot, b[3] > 1e-12 * btot,
                          b[0] > 1e-12 * btot};
  const int elemOfBase[4] = {1, 2, 3, 0};
  double lnK[kNs];
  double g[4];
  for (int j = 0; j < 4; ++j) g[j] = gRT(kSp[j], T);
  for (int s = 0; s < kNs; ++s) {
    double dg = gRT(kSp[s], T);
    double sumNu = 0.0;
    for (int j = 0; j < 4; ++j) {
      dg -= kNu[s][j] * g[j];
      sumNu += kNu[s][j];
    }
    lnK[s] = -dg + (sumNu - 1.0) * lnP;  // pressure factor folded in
  }
  if (!warm_) {  // complete-combustion estimate
    const double nCO2 = b[0], nH2O = 0.5 * b[1], nN2 = 0.5 * b[3];
    const double nO2 = std::max(0.5 * (b[2] - 2 * b[0] - 0.5 * b[1]), 1e-4 * btot);
    const double n = nCO2 + nH2O + nN2 + nO2 + b[4];
    z_[0] = std::log(1e-4);
    z_[1] = std::log(nO2 / n);
    z_[2] = std::log(std::max(nN2, 1e-30) / n);
    z_[3] = std::log(1e-4);
    z_[4] = std::log(n);
  }
  double x[kNs];
  bool ok = false;
  for (iters_ = 1; iters_ <= 60; ++iters_) {
    for (int s = 0; s < kNs; ++s) {
      double lx = lnK[s];
      bool on = true;
      for (int j = 0; j < 4; ++j)
        if (kNu[s][j] != 0.0) {
          if (!active[j]) on = false;
          lx += kNu[s][j] * z_[j];
        }
      x[s] = on ? std::exp(std::min(lx, 50.0)) : 0.0;
    }
    const double n = std::exp(z_[4]);
    double F[5], J[5][5] = {};
    // Rows 0..3: element balances (C, H, O, N) scaled by btot; row 4: sum of mole fractions.
    for (int e = 0; e < 4; ++e) {
      double sum = 0.0;
      for (int s = 0; s < kNs; ++s) sum += kA[s][e] * x[s];
      F[e] = (n * sum - b[e]) / btot;
      J[e][4] = n * sum / btot;
      for (int j = 0; j < 4; ++j) {
        double d = 0.0;
        for (int s = 0; s < kNs; ++s) d += kA[s][e] * kNu[s][j] * x[s];
        J[e][j] = n * d / btot;
      }
    }
    double sx = b[4] / n - 1.0;
    for (int s = 0; s < kNs; ++s) sx += x[s];
    F[4] = sx;
    J[4][4] = -b[4] / n;
    for (int j = 0; j < 4; ++j) {
      double d = 0.0;
      for (int s = 0; s < kNs; ++s) d += kNu[s][j] * x[s];
      J[4][j] = d;
    }
    // Inactive base species: replace their equation (their element's balance) by dz_j = 0.
    for (int j = 0; j < 4; ++j)
      if (!active[j]) {
        const int e = elemOfBase[j];
        for (int k = 0; k < 5; ++k) J[e][k] = 0.0;
        J[e][j] = 1.0;
        F[e] = 0.0;
      }
    double res = 0.0;
    for (int k = 0; k < 5; ++k) res = std::max(res, std::fabs(F[k]));
    double dz[5];
    for (int k = 0; k < 5; ++k) dz[k] = -F[k];
    if (!gaussSolve(J, dz, 5)) break;
    double dmax = 0.0;
    for (int k = 0; k < 5; ++k) dmax = std::max(dmax, std::fabs(dz[k]));
    const double scale = dmax > 2.0 ? 2.0 / dmax : 1.0;
    for (int k = 0; k < 5; ++k) z_[k] += scale * dz[k];
    if (res < 1e-13 && dmax < 1e-9) {
      ok = true;
      break;
    }
  }
  warm_ = ok;
  for (int s = 0; s < kNumSpecies; ++s) x_out[s] = 0.0;
  for (int s = 0; s < kNs; ++s) x_out[kSp[s]] = x[s];
  x_out[kAr] = b[4] / std::exp(z_[4]);
  return ok;
}

double Equilibrium::molesPerKg() const { return std::exp(z_[4]); }

}  // namespace hbt::cylinder
