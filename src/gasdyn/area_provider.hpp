// Area providers: the effective flow area of a valve/orifice, kept separate from the flow solver.
//
//   A_eff(t, direction) = Cd(L/d, direction) x A_geo(L),  A_geo = n_valves pi d L   (curtain area)
// with the lift L [m] from a lift profile over crank angle theta [deg], theta(t) = theta_0 +
// 6 N (t - t_0) for an engine speed N [rpm] (360 deg per revolution), wrapped to [0, 720) deg.
// Direction Forward / Reverse is defined by the boundary using the provider (Valve: Forward =
// from the volume into the pipe; PipeOrifice: Forward = from pipe A to pipe B).
#pragma once
#include "common/table1d.hpp"

namespace hbt::gasdyn {

enum class FlowDirection { Forward, Reverse };

class AreaProvider {
 public:
  virtual ~AreaProvider() = default;
  /// Effective (Cd x geometric) area [m^2] at time t [s] for the given flow direction.
  virtual double effectiveArea(FlowDirection dir, double t) const = 0;
};

/// Fixed orifice: A_eff = Cd A_geo in both directions (Cd may differ by direction).
class ConstantArea final : public AreaProvider {
 public:
  ConstantArea(double geometric_area_m2, double cd_forward, double cd_reverse);
  double effectiveArea(FlowDirection dir, double t) const override;
  void setGeometricArea(double a_m2) { area_ = a_m2; }  // e.g. a wastegate opening

 private:
  double area_, cd_f_, cd_r_;
};

/// Poppet valve(s): lift profile(crank angle) x discharge coefficient(L/d).
class LiftProfileArea final : public AreaProvider {
 public:
  /// lift_m(theta_deg) over the 720 deg cycle, cd_forward / cd_reverse over L/d [-].
  LiftProfileArea(Table1D lift_m, Table1D cd_forward, Table1D cd_reverse, double valve_diameter_m,
                  int n_valves);
  /// Crank kinematics: angle theta0_deg at time t0_s, engine speed rpm (constant until reset).
  void setCrank(double theta0_deg, double t0_s, double rpm);
  double crankAngle(double t) const;  // [deg] in [0, 720)
  double lift(double t) const;        // [m]
  double effectiveArea(FlowDirection dir, double t) const override;

 private:
  Table1D lift_, cd_f_, cd_r_;
  double d_;
  int n_;
  double theta0_ = 0.0, t0_ = 0.0, rpm_ = 0.0;
};

}  // namespace hbt::gasdyn
