// Pipe-end boundaries (see characteristics.hpp for the face relations they use).
//   ClosedEnd   u = 0 at the face; flux (0, p_b A, 0), p_b the reflected wall pressure.
//   OpenEnd     pipe end open to a Volume (reservoir, plenum or volume-based junction): inflow
//               isentropic from the volume's state taken as total (p, T), outflow at the volume's
//               static pressure; subsonic or choked. Any number of OpenEnds may share one Volume
//               (N-pipe plenum / junction); the volume receives exactly minus the pipe flux.
//               To a finite volume the end is a VolumePort: the volume gives the final flux to
//               the pipe end in closePorts() (linearised in its pressure if it is implicit).
//   Valve       orifice between a Volume and a pipe end, effective area from an AreaProvider
//               (Forward = from the volume into the pipe), isentropic nozzle (choked/subsonic) +
//               characteristic of the pipe end solved together; both directions.
//   PipeOrifice orifice between two pipe ends (Forward = pipe A -> pipe B; direction from the
//               ends' wall pressures): the upstream face solves nozzle(face total state -> the
//               downstream end-cell static pressure) with its characteristic (quasi-steady,
//               explicit in the downstream pressure); the downstream face then carries that same
//               mass flow and total enthalpy, so mass and energy are conserved exactly.
#pragma once
#include <memory>

#include "gasdyn/area_provider.hpp"
#include "gasdyn/boundary.hpp"
#include "gasdyn/characteristics.hpp"
#include "gasdyn/volume.hpp"

namespace hbt::gasdyn {

class ClosedEnd final : public Boundary {
 public:
  ClosedEnd(std::string name, PipeEnd end);
  void computeFluxes(double t) override;

 private:
  PipeEnd end_;
};

class OpenEnd final : public Boundary {
 public:
  OpenEnd(std::string name, PipeEnd end, Volume& volume);
  void computeFluxes(double t) override;
  /// Last mass flow into the pipe [kg/s] (final, after the volume closed its ports).
  double massFlowIn() const { return vol_.isReservoir() ? mdot_ : port_.flux.mdot_in; }

 private:
  void cellSensitivity(const EndState& s, double p0, double T0, const FaceState& f);
  PipeEnd end_;
  Volume& vol_;
  VolumePort port_;  // finite volumes only
  double mdot_ = 0.0;
};

class Valve final : public Boundary {
 public:
  Valve(std::string name, Volume& volume, PipeEnd end, std::shared_ptr<const AreaProvider> area);
  void computeFluxes(double t) override;
  double massFlowIn() const { return mdot_; }  // last mass flow volume -> pipe [kg/s]

 private:
  Volume& vol_;
  PipeEnd end_;
  std::shared_ptr<const AreaProvider> area_;
  double mdot_ = 0.0;
};

class PipeOrifice final : public Boundary {
 public:
  PipeOrifice(std::string name, PipeEnd a, PipeEnd b, std::shared_ptr<const AreaProvider> area);
  void computeFluxes(double t) override;
  double massFlowAtoB() const { return mdot_; }  // [kg/s]

 private:
  PipeEnd a_, b_;
  std::shared_ptr<const AreaProvider> area_;
  double mdot_ = 0.0;
};

/// Connects a face state to its pipe end and (with the opposite sign) to a volume; returns mdot_in.
double applyFace(const FaceState& f, const PipeEnd& end, Volume* vol);

}  // namespace hbt::gasdyn
