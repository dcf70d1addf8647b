// Gas-exchange elements of the engine assembly that plug into the gasdyn network:
//
// CrankValveArea (gasdyn::AreaProvider): effective area of the 2 intake or 2 exhaust poppet valves
// of one cylinder, read from the cylinder's own crank angle theta (firing TDC = 0, [-360, 360)):
//   A_eff(theta, dir) = n_v Cd_dir(L/d) pi d L(theta),  L = L_max sin(pi phi/Delta)^k  (0 outside)
//   phi = (theta - theta_open) mod 720, Delta = theta_close - theta_open (valve events of the
//   cylinder model). Tabulated at construction every 0.25 deg over the open phase only
//   (phi in [0, Delta]; the events are on the 0.25 deg grid), forward/reverse interleaved (one
//   cache line per look-up), linear interpolation, O(1); a closed valve needs no table access.
//   Valve convention (gasdyn::Valve): Forward = from the cylinder into the runner. Intake: normal
//   flow is Reverse; exhaust: normal flow is Forward.
//
// ChargeAirCoolerLink (gasdyn::Boundary) joins the compressor-outlet pipe end A (hot) and the
// charge-air duct pipe end B (cold) through the quasi-steady air-to-air intercooler of src/turbo:
//   mdot = sqrt(dp p0/(K T0)),  dp = p0_face,up - p_down   (dp = K mdot^2 T/p of the core)
//   T0_out = T0_in - eps(mdot) (T0_in - T_cool),  T_cool = T_ambient (+ offset)          [K]
// Flow direction from the wall pressures of both ends; the upstream face is solved with its
// characteristic (demand-driven outflow face), the downstream face carries the same mass flow
// at T0_out. Heat removed Q = mdot cp (T0_in - T0_out) [W] (to the cooling air); mass is
// conserved exactly, energy up to the reported heat. The core's gas volume is represented by
// the charge-air duct pipe.
#pragma once
#include <memory>
#include <vector>

#include "cylinder/cylinder.hpp"
#include "engine_1d/engine_1d_params.hpp"
#include "gasdyn/area_provider.hpp"
#include "gasdyn/boundary.hpp"
#include "gasdyn/characteristics.hpp"
#include "gasdyn/volume.hpp"
#include "turbo/intercooler.hpp"

namespace hbt::engine_1d {

class CrankValveArea final : public gasdyn::AreaProvider {
 public:
  /// open/close [deg, cylinder crank angle]; normal_is_forward: exhaust true, intake false.
  CrankValveArea(const cylinder::Cylinder& cylinder, const ValveSpec& v, double open_deg,
                 double close_deg, bool normal_is_forward);
  double effectiveArea(gasdyn::FlowDirection dir, double t) const override;
  double areaAt(double theta_deg, bool forward) const;
  /// Both effective areas [m^2] at the cylinder's current crank angle + the lead angle (one
  /// look-up). The assembly sets the lead to half the coupled step's crank angle, so a step uses
  /// the area at its mid-point (midpoint rule in the valve motion).
  void areasNow(double& forward, double& reverse) const;
  void setLead(double deg) { lead_ = deg; }
  /// Both effective areas [m^2] at crank angle theta [deg, within [-360, 360)].
  void areasAt(double theta_deg, double& forward, double& reverse) const {
    areas(theta_deg, forward, reverse);
  }
  double lift(double theta_deg) const;  // [m]

 private:
  void areas(double theta_deg, double& forward, double& reverse) const;
  const cylinder::Cylinder& cyl_;
  ValveSpec v_;
  double open_, duration_, lead_ = 0.0;
  std::vector<double> tab_;  // (forward, reverse) pairs over phi = 0 ... Delta, step kStep
};

/// The valves of one side of a cylinder: gasdyn::Valve physics (isentropic nozzle with the
/// pipe characteristic, both directions, choking; Forward = cylinder -> runner) with the
/// warm-started face solver (fast_faces.hpp) and a direct (non-virtual) area look-up.
/// The cylinder is seen through a reservoir Volume holding its p, T.
class CylinderValve final : public gasdyn::Boundary {
 public:
  CylinderValve(std::string name, gasdyn::Volume& cylinder_side, gasdyn::PipeEnd end,
                std::shared_ptr<const CrankValveArea> area);
  void computeFluxes(double t) override;
  double massFlowIn() const { return mdot_; }  // cylinder -> pipe [kg/s]

 private:
  gasdyn::Volume& vol_;
  gasdyn::PipeEnd end_;
  std::shared_ptr<const CrankValveArea> area_;
  double mdot_ = 0.0;
  gasdyn::WarmStart warm_in_, warm_out_;  // face solvers' warm starts: inflow, outflow
};

class ChargeAirCoolerLink final : public gasdyn::Boundary {
 public:
  ChargeAirCoolerLink(std::string name, gasdyn::PipeEnd hot, gasdyn::PipeEnd cold,
                      const turbo::Intercooler& cooler);
  void setCoolingAirTemperature(double T_K) { T_cool_ = T_K; }
  void computeFluxes(double t) override;
  void afterStep(double dt) override { heat_J_ += heat_W_ * dt; }
  double massFlow() const { return mdot_; }      // hot -> cold [kg/s]
  double heatRemoved() const { return heat_W_; }  // [W]
  double heatRemovedTotal() const { return heat_J_; }  // [J]
  double outletT0() const { return T0_out_; }     // [K]

 private:
  gasdyn::PipeEnd a_, b_;
  const turbo::Intercooler& ic_;
  gasdyn::WarmStart warm_up_, warm_down_;  // warm starts: upstream outflow, downstream inflow
  bool warm_forward_ = true;               // direction of warm_up_'s flow (hot -> cold)
  double T_cool_ = 298.15, mdot_ = 0.0, heat_W_ = 0.0, heat_J_ = 0.0, T0_out_ = 298.15;
};

}  // namespace hbt::engine_1d
