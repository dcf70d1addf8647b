#include "cooling/coolant_network.hpp"

namespace hbt::cooling {

namespace {
enum Node { kMetal = 0, kEngine = 1, kRadiator = 2, kConvector = 3, kLt = 4 };
}  // namespace

NetworkFluxes CoolantNetwork::step(double h, double T_a, const NetworkCoefficients& k, NetworkState& T) const {
  using Mat5 = Eigen::Matrix<double, 5, 5>;
  using Vec5 = Eigen::Matrix<double, 5, 1>;
  Mat5 A = Mat5::Zero();
  Vec5 b;
  // metal + oil
  A(kMetal, kMetal) = C_.metal / h + k.G_mc + k.G_s;
  A(kMetal, kEngine) = -k.G_mc;
  b(kMetal) = C_.metal / h * (T.metal - T_a) + k.Q_engine;
  // engine loop
  A(kEngine, kEngine) = C_.engine_loop / h + k.G_mc + k.W_rad + k.W_heater;
  A(kEngine, kMetal) = -k.G_mc;
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
  b(kConvector) = C_.convector / h * (T.convector - T_a) - k.q_heater;
  // LT
  A(kLt, kLt) = C_.lt / h + k.G_lt;
  b(kLt) = C_.lt / h * (T.lt - T_a) + k.Q_lt;

  const Vec5 th = A.partialPivLu().solve(b);
  NetworkFluxes f;
  f.radiator_lt = k.G_lt * th(kLt);
  f.radiator_ht = k.G_ht * (th(kEngine) - k.preheat * th(kLt));
  f.heater = k.q_heater + k.g_heater * th(kConvector);
  f.surface = k.G_s * th(kMetal);
  f.to_radiator = k.W_rad * (th(kEngine) - th(kRadiator));
  f.to_convector = k.W_heater * (th(kEngine) - th(kConvector));
  T.metal = T_a + th(kMetal);
  T.engine_loop = T_a + th(kEngine);
  T.radiator = T_a + th(kRadiator);
  T.convector = T_a + th(kConvector);
  T.lt = T_a + th(kLt);
  return f;
}

double CoolantNetwork::storedSince_J(const NetworkState& T, const NetworkState& T0) const {
  return C_.metal * (T.metal - T0.metal) + C_.engine_loop * (T.engine_loop - T0.engine_loop) +
         C_.radiator * (T.radiator - T0.radiator) + C_.convector * (T.convector - T0.convector) +
         C_.lt * (T.lt - T0.lt);
}

}  // namespace hbt::cooling
