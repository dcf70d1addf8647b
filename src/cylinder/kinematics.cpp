#include "cylinder/kinematics.hpp"

#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::cylinder {

SliderCrank::SliderCrank(const Geometry& g) : g_(g) {
  if (!(g.bore_m > 0 && g.stroke_m > 0 && g.rod_m > g.stroke_m / 2 && g.compression_ratio > 1))
    throw InputError("cylinder geometry", "geometry", "bore, stroke, rod > stroke/2, CR > 1 required");
  r_ = 0.5 * g.stroke_m;
  l_ = g.rod_m;
  Ap_ = 0.25 * units::kPi * g.bore_m * g.bore_m;
  Vd_ = Ap_ * g.stroke_m;
  Vc_ = Vd_ / (g.compression_ratio - 1.0);
}

}  // namespace hbt::cylinder
