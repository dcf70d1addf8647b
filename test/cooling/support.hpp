// Test support: config/cooling.yaml into CoolingParams, as the node reads it.
#pragma once
#include "common/yaml_params.hpp"
#include "cooling/cooling_params.hpp"

namespace hbt::cooling::test {

/// Metal and oil above the engine loop [K] once the engine, its oil and its coolant all rise on
/// one ramp r [K/s] (the linear regime of a warm-up without losses): the oil node
///   C_o r = Q_o + G_om (a - b) - G_oc b
/// and what the coolant side takes up, D = G_mc a + G_oc b [W] (its capacities x r, plus any heat
/// drawn from it), solved by hand for a = θ_m - θ_c and b = θ_o - θ_c.
struct RampOffsets {
  double metal_K = 0.0, oil_K = 0.0;
};
inline RampOffsets rampOffsets(double G_mc, double G_om, double G_oc, double C_o, double Q_o, double r,
                               double D) {
  const double e = C_o * r - Q_o;  // G_om a - (G_om + G_oc) b = e;  G_mc a + G_oc b = D
  const double det = G_om * G_oc + G_mc * (G_om + G_oc);
  return {(e * G_oc + (G_om + G_oc) * D) / det, (G_om * D - G_mc * e) / det};
}

inline CoolingParams yamlParams() {
  CoolingParams p;
  ParamSet ps;
  p.declare(ps);
  // cosim/ keys (the node's macro step) belong to the participant base class, as in the node
  applyParams(ps, readYamlParams("config/cooling.yaml"), {"cosim/"});
  return p;
}

}  // namespace hbt::cooling::test
