// Gearbox and retarder losses from VECTO tables.
//
// Gearbox loss map L(ω_in, T_in) [Nm at the input shaft] on a full speed × torque grid
// (bilinear, clamped at the grid edges, symmetric in the sign of T_in as in the source XML):
//   drag part  L_0(ω)      = L(ω, 0)                    -> at the gearbox input speed with a
//                                                          gear engaged (crank speed when
//                                                          locked, turbine speed in 1C); not
//                                                          in neutral (VehicleModel uses the
//                                                          neutral spin loss there)
//   load part  L_T(ω, T)   = f_g · (L(ω, |T|) - L(ω, 0))  -> at the gearbox input shaft;
//                                                          f_g per gear (1 for mapped gears,
//                                                          0 for direct gear 4: no mesh load)
// Retarder drag R(ω_out) [Nm at its shaft], linear in speed, clamped.
// Loss torques oppose rotation; callers multiply by a smooth sign (linear within ±1 rad/s).
#pragma once
#include <string>
#include <vector>

#include "common/table1d.hpp"
#include "common/table2d.hpp"

namespace hbt::vehicle {

class GearLossMap {
 public:
  GearLossMap() = default;
  /// Reads columns "input speed [rpm]", "input torque [Nm]", "torque loss [Nm]". Throws
  /// InputError (file, column) unless the points form a complete grid with loss >= 0.
  explicit GearLossMap(const std::string& path);
  double total(double w_in_rad_s, double torque_in_Nm) const;  // L(|ω|, |T|)
  double drag(double w_in_rad_s) const { return total(w_in_rad_s, 0.0); }
  double load(double w_in_rad_s, double torque_in_Nm) const {
    return total(w_in_rad_s, torque_in_Nm) - drag(w_in_rad_s);
  }

 private:
  Table2D loss_;  // L(ω [rad/s], T_in [Nm]) [Nm]
};

/// Retarder drag torque table vs shaft speed; empty path = no retarder (0 Nm).
class RetarderLoss {
 public:
  RetarderLoss() = default;
  explicit RetarderLoss(const std::string& path);
  double torque(double w_rad_s) const;  // >= 0, magnitude at |ω|
  bool present() const { return !tab_.empty(); }

 private:
  Table1D tab_;
};

/// Smooth sign: ω/ε clamped to [-1, 1] (ε = 1 rad/s): Coulomb-like losses vanish at standstill.
inline double smoothSign(double w, double eps = 1.0) {
  return w >= eps ? 1.0 : (w <= -eps ? -1.0 : w / eps);
}

}  // namespace hbt::vehicle
