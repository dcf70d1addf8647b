// Hydrodynamic torque converter from a VECTO .vtcc characteristic (columns by position:
// speed ratio ν [-], torque ratio μ [-], input torque at the reference speed MP_ref [Nm]).
//
//   ν   = ω_t / ω_p                                  (turbine / pump speed)
//   T_p = MP_ref(ν) · (ω_p / ω_ref)²                 pump (engine-side) torque [Nm]
//   T_t = μ(ν) · T_p        (traction, ν <= 1)      turbine torque [Nm]
//   T_t = T_p / μ(ν)        (overrun,  ν > 1: the turbine drives; μ = T_p/T_t <= 1)
//   P_loss = T_p ω_p - T_t ω_t = T_p ω_p (1 - μν) resp. T_p ω_p (1 - ν/μ) >= 0
// (with T_t = μ T_p in overrun the APT-S table, μ = 0.95..1 for ν = 1..1.1, would create
// energy; the test checks P_loss >= 0 over ν = 0..5).
// ν is clamped to [0, ν_max of the table]; T_p = 0 when the pump does not turn (ω_p <= 0).
#pragma once
#include <string>

#include "common/table1d.hpp"

namespace hbt::vehicle {

class TorqueConverter {
 public:
  TorqueConverter() = default;
  /// Reads the .vtcc. Throws InputError (file, column): ν not strictly increasing or not
  /// starting at 0, μ <= 0, MP_ref(0) <= 0 (no stall torque).
  TorqueConverter(const std::string& path, double reference_speed_rad_s);

  double speedRatio(double w_pump, double w_turbine) const;
  double torqueRatio(double nu) const { return mu_(nu); }
  double referenceTorque(double nu) const { return mp_(nu); }
  double pumpTorque(double w_pump, double w_turbine) const;
  double turbineTorque(double w_pump, double w_turbine) const;
  double maxSpeedRatio() const { return mu_.xMax(); }
  double referenceSpeed() const { return w_ref_; }

 private:
  Table1D mu_, mp_;
  double w_ref_ = 0.0;
};

}  // namespace hbt::vehicle
