// Volume: 0D filling-emptying control volume (plenum, volume-based N-pipe junction) or, when built
// as a reservoir, gas at a fixed state (infinite volume) that only counts what it exchanges.
//
// Gas at rest, perfect gas, adiabatic walls:
//   dm/dt = sum_k mdot_in,k              [kg/s]
//   dU/dt = sum_k mdot_in,k h0_k         [W]    (total enthalpy of the entering/leaving gas)
//   U = m cv T [J],   p = m R T / V [Pa]
// Integrated with the network time step (explicit, exactly conservative: every flow added here is
// the negative of the flow given to the connected pipe end). Stable time step ~ V/(c sum A_k),
// A_k the connected end/orifice areas: a junction volume of about sum_k A_k dx_k keeps it above
// the pipes' CFL step.
#pragma once
#include <string>

#include "gasdyn/gas.hpp"

namespace hbt::gasdyn {

class Volume {
 public:
  /// Finite volume [m^3] at pressure p [Pa] and temperature T [K].
  Volume(const PerfectGas& gas, std::string name, double volume_m3, double p, double T);
  /// Reservoir at a fixed state p [Pa], T [K].
  static Volume reservoir(const PerfectGas& gas, std::string name, double p, double T);

  const std::string& name() const { return name_; }
  bool isReservoir() const { return reservoir_; }
  double volume() const { return V_; }  // [m^3] (0 for a reservoir)
  double p() const { return p_; }        // [Pa]
  double T() const { return T_; }        // [K]
  double rho() const { return p_ / (gas_.R * T_); }
  double mass() const { return reservoir_ ? 0.0 : m_; }    // [kg] (0 for a reservoir)
  double energy() const { return reservoir_ ? 0.0 : U_; }  // [J]
  /// Reservoir only: impose a new state (e.g. a time-varying ambient / back pressure).
  void setReservoirState(double p, double T);

  void addFlow(double mdot_in, double energy_in) { mdot_ += mdot_in, edot_ += energy_in; }
  void registerConnection(double area) { area_sum_ += area; }
  double maxDt() const;
  void advance(double dt);  // throws hbt::ModelDivergence("volume <name>", ...)
  /// Time integrals of what entered the volume since the start [kg], [J].
  double cumulativeMassIn() const { return cum_m_; }
  double cumulativeEnergyIn() const { return cum_e_; }

 private:
  Volume() = default;
  PerfectGas gas_;
  std::string name_;
  bool reservoir_ = false;
  double V_ = 0.0, p_ = 0.0, T_ = 0.0, m_ = 0.0, U_ = 0.0;
  double mdot_ = 0.0, edot_ = 0.0, area_sum_ = 0.0;
  double cum_m_ = 0.0, cum_e_ = 0.0;
};

}  // namespace hbt::gasdyn
