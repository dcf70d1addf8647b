// Turbomachine boundaries driven by an external map through a small callback interface (FlowMap),
// so the real turbine / compressor maps can be plugged in by the turbo model.
//
// TurbineEntry (pipe end = turbine inlet, outlet = a Volume: reservoir, plenum, or junction):
//   (p0, T0) = pipe end brought to rest (wall pressure, isentropic temperature),
//   mdot = map.massFlow(p0, T0, p_out, speed) [kg/s] leaves the pipe through a face carrying that
//   flow (characteristics); the outlet volume receives mdot and mdot cp T0_out with
//   T0_out = T0f (1 - eta (1 - (p_out/p0f)^((gamma-1)/gamma))) (p0f, T0f: face total state);
//   shaft power P = mdot cp (T0f - T0_out) [W]. mdot < 0 (back flow) enters the pipe at T_out.
// CompressorOutlet (inlet = a Volume, e.g. the air filter box; pipe end = compressor outlet):
//   mdot = map.massFlow(p_in, T_in, p_b, speed), p_b the pipe end wall pressure;
//   T0_out = T_in (1 + ((p_b/p_in)^((gamma-1)/gamma) - 1)/eta); the pipe receives mdot and
//   mdot cp T0_out, the inlet volume gives mdot and mdot cp T_in, absorbed power
//   P = mdot cp (T0_out - T_in) [W]. mdot < 0 (surge back flow) leaves the pipe into the inlet.
// Energy bookkeeping: pipes + volumes + turbine work - compressor work is conserved.
#pragma once
#include <memory>

#include "gasdyn/boundary.hpp"
#include "gasdyn/characteristics.hpp"
#include "gasdyn/volume.hpp"

namespace hbt::gasdyn {

class FlowMap {
 public:
  virtual ~FlowMap() = default;
  /// Mass flow [kg/s] from upstream total (p0_up [Pa], T0_up [K]) to downstream static p_down [Pa]
  /// at shaft speed `speed` (unit chosen by the map).
  virtual double massFlow(double p0_up, double T0_up, double p_down, double speed) const = 0;
  /// Isentropic efficiency [-] at the same point.
  virtual double efficiency(double p0_up, double T0_up, double p_down, double speed) const {
    return 1.0;
  }
  /// Compressor total-temperature ratio T0_out/T0_up = 1 + ((p_down/p0_up)^k - 1)/eta [-]
  /// (k = (gamma-1)/gamma of the pipe gas). A map that knows its specific work may override it
  /// with the same value obtained without a power.
  virtual double temperatureRatio(double p0_up, double T0_up, double p_down, double speed,
                                  double k) const {
    return 1.0 + (ConstPow(k)(p_down / p0_up) - 1.0) / efficiency(p0_up, T0_up, p_down, speed);
  }
};

class TurbineEntry final : public Boundary {
 public:
  TurbineEntry(std::string name, PipeEnd inlet, Volume& outlet, std::shared_ptr<const FlowMap> map);
  void setSpeed(double speed) { speed_ = speed; }
  void computeFluxes(double t) override;
  double massFlow() const { return mdot_; }  // pipe -> turbine [kg/s]
  double power() const { return power_; }    // [W]
  double work() const { return work_; }  // extracted since the start [J]
  void afterStep(double dt) override { work_ += dt * power_; }

 private:
  PipeEnd end_;
  Volume& out_;
  std::shared_ptr<const FlowMap> map_;
  double speed_ = 0.0, mdot_ = 0.0, power_ = 0.0, work_ = 0.0;
  WarmStart warm_out_, warm_in_;  // warm starts of the face solvers
};

class CompressorOutlet final : public Boundary {
 public:
  CompressorOutlet(std::string name, Volume& inlet, PipeEnd outlet,
                   std::shared_ptr<const FlowMap> map);
  void setSpeed(double speed) { speed_ = speed; }
  void computeFluxes(double t) override;
  double massFlow() const { return mdot_; }  // compressor -> pipe [kg/s]
  double power() const { return power_; }    // absorbed [W]
  double work() const { return work_; }  // absorbed since the start [J]
  void afterStep(double dt) override { work_ += dt * power_; }

 private:
  Volume& in_;
  PipeEnd end_;
  std::shared_ptr<const FlowMap> map_;
  double speed_ = 0.0, mdot_ = 0.0, power_ = 0.0, work_ = 0.0;
  WarmStart warm_;  // warm start of the delivery face solver
};

}  // namespace hbt::gasdyn
