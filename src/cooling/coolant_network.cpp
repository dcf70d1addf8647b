#include "cooling/coolant_network.hpp"

namespace hbt::cooling {

namespace {
enum Node { kMetal = 0, kEngine = 1, kRadiator = 2, kConvector = 3, kLt = 4, kOil = 5 };
}  // namespace

NetworkFluxes CoolantNetwork::step(double h, double T_a, const NetworkCoefficients& k, NetworkState& T) const {
  using Mat = Eigen::Matrix<double, 6, 6>;
  using Vec = Eigen::Matrix<double, 6, 1>;
  Mat A = Mat::Zero();
  Vec b;
  // metal
  A(kMetal, kMetal) = C_.metal / h + k.G_mc + k.G_om + k.G_s;
  A(kMetal, kEngine) = -k.G_mc;
  A(kMetal, kOil) = -k.G_om;
  b(kMetal) = C_.metal / h * (T.metal - T_a) + k.Q_engine;
  // oil
  A(kOil, kOil) = C_.oil / h + k.G_om + k.G_oc;
  A(kOil, kMetal) = -k.G_om;
  A(kOil, kEngine) = -k.G_oc;
  b(kOil) = C_.oil / h * (T.oil - T_a) + k.Q_oil;
  // engine loop
  A(kEngine, kEngine) = C_.engine_loop / h + k.G_mc + k.G_oc + k.W_rad + k.W_heater;
  A(kEngine, kMetal) = -k.G_mc;
  A(kEngine, kOil) = -k.G_oc;
  A(kEngine, kRadiator) = -k.W_rad;
  A(kEngine, kConvector) = -k.W_heater;
  b(kEngine) = C_.engine_loop / h * (T.engine_loop - T_a) + k.Q_aux;
  // radiator volume: W_r (θ_c - θ_r) - G_HT (θ_c - p θ_l)
  A(kRadiator, kRadiator) = C_.radiator / h + k.W_rad;
  A(kRadiator, kEngine) = -k.W_rad + k.G_ht;
  A(kRadiator, kLt) = -k.G_ht * k.preheat;
  b(kRadiator) = C_.radiator / h * (T.radiator - T_a);
  // convector volume: W_v (θ_c - θ_v) - q_h - g_h θ_v
  A(kConvector, kConvector) = C_.convector / h + k.W_heater + k.g_heater;
  A(kConvector, kEngine) = -k.W_heater;
  b(kConvector) = C_.convector / h * (T.convector - T_a) - k.q_heater + k.Q_loop;
  // LT
  A(kLt, kLt) = C_.lt / h + k.G_lt;
  b(kLt) = C_.lt / h * (T.lt - T_a) + k.Q_lt;

  const Vec th = A.partialPivLu().solve(b);
  NetworkFluxes f;
  f.radiator_lt = k.G_lt * th(kLt);
  f.radiator_ht = k.G_ht * (th(kEngine) - k.preheat * th(kLt));
  f.heater = k.q_heater + k.g_heater * th(kConvector);
  f.surface = k.G_s * th(kMetal);
  f.to_radiator = k.W_rad * (th(kEngine) - th(kRadiator));
  f.to_convector = k.W_heater * (th(kEngine) - th(kConvector));
  f.oil_cooler = k.G_oc * (th(kOil) - th(kEngine));
  f.oil_to_metal = k.G_om * (th(kOil) - th(kMetal));
  T.metal = T_a + th(kMetal);
  T.engine_loop = T_a + th(kEngine);
  T.radiator = T_a + th(kRadiator);
  T.convector = T_a + th(kConvector);
  T.lt = T_a + th(kLt);
  T.oil = T_a + th(kOil);
  return f;
}

double CoolantNetwork::storedSince_J(const NetworkState& T, const NetworkState& T0) const {
  return C_.metal * (T.metal - T0.metal) + C_.engine_loop * (T.engine_loop - T0.engine_loop) +
         C_.radiator * (T.radiator - T0.radiator) + C_.convector * (T.convector - T0.convector) +
         C_.lt * (T.lt - T0.lt) + C_.oil * (T.oil - T0.oil);
}

}  // namespace hbt::cooling
