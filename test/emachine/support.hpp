// Shared support of the e-machine tests (test_emachine.cpp, test_emachine_thermal.cpp): the
// shipped YAML as parameters, the .vemp data read by hand, and hand-solved references (the
// 4-node thermal network's steady state and an RK4 integration of it).
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "common/errors.hpp"
#include "common/units.hpp"
#include "common/yaml_params.hpp"
#include "emachine/emachine_model.hpp"
#include "../common/param_checks.hpp"

namespace hbt::emachine::test {

using units::celsiusToK;
using units::rpmToRadps;

inline EMachineParams yamlParams() {
  EMachineParams p;
  ParamSet ps;
  p.declare(ps);
  applyParams(ps, readYamlParams("config/emachine.yaml"), {"cosim/"});
  return p;
}

struct VempRow { double n_rpm, drive, recup; };

// The .vemp read line by line here, independently of CsvTable and of the envelope's sorting.
inline std::vector<VempRow> readVempByHand(const std::string& path) {
  std::ifstream f(path);
  std::string line;
  std::vector<VempRow> rows;
  bool header = true;
  while (std::getline(f, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) { header = false; continue; }
    std::istringstream is(line);
    std::string a, b, c;
    std::getline(is, a, ',');
    std::getline(is, b, ',');
    std::getline(is, c, ',');
    rows.push_back({std::stod(a), std::stod(b), std::stod(c)});
  }
  return rows;
}

constexpr double kNom = 48.0;

// Magnet temperature of the datasheet k_t (config/emachine.yaml electrical/torque_constant_ref_K):
// the magnet flux factor is 1 there and the hand formulas hold with the YAML's k_t.
constexpr double kMagnetRef_K = 293.15;

// Motoring / generating system efficiency (machine + inverter, EM shaft) at EM speed w, torque T,
// winding and magnet temperatures.
inline double efficiency(const LossModel& lm, double T, double w, double V, double Tw, double Tm) {
  const LossBreakdown b = lm.evaluate(T, w, V, Tw, Tm);
  const double P = T * w;
  return P > 0 ? P / (P + b.total()) : (-P - b.total()) / (-P);
}

// Nodal equations of the 4-node network written out by hand (W, S, R, H; coolant T_c on the
// housing, engine T_e on the housing and the rotor) and solved by Gaussian elimination with
// partial pivoting in this test.
inline std::vector<double> handSteadyState(const ThermalParams& t, const double q[4], double Tc, double Te) {
  const double gws = t.G_winding_stator_W_K, gwh = t.G_winding_housing_W_K, gsh = t.G_stator_housing_W_K,
               grs = t.G_rotor_stator_W_K, grh = t.G_rotor_housing_W_K, ghc = t.G_housing_coolant_W_K,
               ghe = t.G_housing_engine_W_K, gre = t.G_rotor_crank_W_K;
  double A[4][5] = {
      {gws + gwh, -gws, 0.0, -gwh, q[0]},
      {-gws, gws + gsh + grs, -grs, -gsh, q[1]},
      {0.0, -grs, grs + grh + gre, -grh, q[2] + gre * Te},
      {-gwh, -gsh, -grh, gwh + gsh + grh + ghc + ghe, q[3] + ghc * Tc + ghe * Te},
  };
  for (int c = 0; c < 4; ++c) {
    int piv = c;
    for (int r = c + 1; r < 4; ++r)
      if (std::abs(A[r][c]) > std::abs(A[piv][c])) piv = r;
    for (int k = 0; k < 5; ++k) std::swap(A[c][k], A[piv][k]);
    for (int r = c + 1; r < 4; ++r) {
      const double f = A[r][c] / A[c][c];
      for (int k = c; k < 5; ++k) A[r][k] -= f * A[c][k];
    }
  }
  std::vector<double> x(4);
  for (int r = 3; r >= 0; --r) {
    double s = A[r][4];
    for (int k = r + 1; k < 4; ++k) s -= A[r][k] * x[k];
    x[r] = s / A[r][r];
  }
  return x;
}

// RK4 of C dx/dt = q + g_c Tc + g_e Te - G x, written out from the same nodal equations.
inline void rk4Network(const ThermalParams& t, const double q[4], double Tc, double Te, double h, int n,
                       double x[4]) {
  const double C[4] = {t.C_winding_J_K, t.C_stator_J_K, t.C_rotor_J_K, t.C_housing_J_K};
  auto f = [&](const double* y, double* d) {
    const double W = y[0], S = y[1], R = y[2], H = y[3];
    d[0] = (q[0] - t.G_winding_stator_W_K * (W - S) - t.G_winding_housing_W_K * (W - H)) / C[0];
    d[1] = (q[1] + t.G_winding_stator_W_K * (W - S) - t.G_stator_housing_W_K * (S - H) -
            t.G_rotor_stator_W_K * (S - R)) / C[1];
    d[2] = (q[2] + t.G_rotor_stator_W_K * (S - R) - t.G_rotor_housing_W_K * (R - H) +
            t.G_rotor_crank_W_K * (Te - R)) / C[2];
    d[3] = (q[3] + t.G_winding_housing_W_K * (W - H) + t.G_stator_housing_W_K * (S - H) +
            t.G_rotor_housing_W_K * (R - H) - t.G_housing_coolant_W_K * (H - Tc) +
            t.G_housing_engine_W_K * (Te - H)) / C[3];
  };
  for (int k = 0; k < n; ++k) {
    double k1[4], k2[4], k3[4], k4[4], y[4];
    f(x, k1);
    for (int i = 0; i < 4; ++i) y[i] = x[i] + 0.5 * h * k1[i];
    f(y, k2);
    for (int i = 0; i < 4; ++i) y[i] = x[i] + 0.5 * h * k2[i];
    f(y, k3);
    for (int i = 0; i < 4; ++i) y[i] = x[i] + h * k3[i];
    f(y, k4);
    for (int i = 0; i < 4; ++i) x[i] += h / 6.0 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
}

}  // namespace hbt::emachine::test
