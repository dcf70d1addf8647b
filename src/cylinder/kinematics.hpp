// Slider-crank kinematics of one cylinder.
//
// Crank angle θ measured from firing TDC of this cylinder (θ = 0); the four-stroke cycle spans
// θ ∈ [−360°, 360°) with gas-exchange TDC at ±360° and BDCs at ±180° (functions take radians).
// With crank radius r = S/2, rod length l, piston area A_p = π B²/4, λ_r = r/l:
//   s(θ)   = r + l − (r cos θ + sqrt(l² − r² sin² θ))                  piston travel from TDC [m]
//   V(θ)   = V_c + A_p s(θ),   V_c = V_d / (ε − 1),  V_d = A_p S       [m³]
//   dV/dθ  = A_p r sin θ (1 + r cos θ / sqrt(l² − r² sin² θ))           [m³/rad]
//   A_w(θ) = f_head A_p + f_piston A_p + π B (s(θ) + h_top)             wall area [m²]
//   c_m    = 2 S n,  n = ω/(2π)                                          mean piston speed [m/s]
// f_head ≥ 1 and f_piston ≥ 1 account for the fire-deck and the piston-bowl surface; h_top is the
// height of the liner exposed above the piston at TDC (top land / squish gap).
#pragma once
#include <cmath>

#include "common/units.hpp"

namespace hbt::cylinder {

struct Geometry {
  double bore_m = 0.104;
  double stroke_m = 0.132;
  double rod_m = 0.195;
  double compression_ratio = 16.8;
  double head_area_factor = 1.10;    // fire-deck area / piston area
  double piston_area_factor = 1.50;  // piston crown incl. bowl / piston area
  double top_land_height_m = 0.0015;
};

class SliderCrank {
 public:
  explicit SliderCrank(const Geometry& g = Geometry());
  double displacement() const { return Vd_; }      // m³
  double clearanceVolume() const { return Vc_; }  // m³
  double pistonArea() const { return Ap_; }       // m²
  const Geometry& geometry() const { return g_; }
  /// Piston travel from TDC [m] at crank angle θ [rad].
  double travel(double theta_rad) const {
    const double s = std::sin(theta_rad), c = std::cos(theta_rad);
    return r_ + l_ - (r_ * c + std::sqrt(l_ * l_ - r_ * r_ * s * s));
  }
  double volume(double theta_rad) const { return Vc_ + Ap_ * travel(theta_rad); }
  double dVdtheta(double theta_rad) const {
    const double s = std::sin(theta_rad), c = std::cos(theta_rad);
    return Ap_ * r_ * s * (1.0 + r_ * c / std::sqrt(l_ * l_ - r_ * r_ * s * s));
  }
  /// Heat-exchanging surfaces [m²]: head, piston, liner.
  double headArea() const { return g_.head_area_factor * Ap_; }
  double pistonCrownArea() const { return g_.piston_area_factor * Ap_; }
  double linerArea(double theta_rad) const {
    return units::kPi * g_.bore_m * (travel(theta_rad) + g_.top_land_height_m);
  }
  double meanPistonSpeed(double omega_rad_s) const {
    return 2.0 * g_.stroke_m * omega_rad_s / (2.0 * units::kPi);
  }

 private:
  Geometry g_;
  double r_, l_, Ap_, Vd_, Vc_;
};

/// Wraps an angle in degrees into the four-stroke cycle [−360, 360).
inline double wrapCycleDeg(double deg) {
  double x = std::fmod(deg + 360.0, 720.0);
  if (x < 0.0) x += 720.0;
  return x - 360.0;
}

}  // namespace hbt::cylinder
