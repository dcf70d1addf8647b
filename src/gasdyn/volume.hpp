// Volume: 0D filling-emptying control volume (plenum, volume-based N-pipe junction) or, when built
// as a reservoir, gas at a fixed state (infinite volume) that only counts what it exchanges.
//
// Gas at rest, perfect gas, adiabatic walls:
//   dm/dt = sum_k mdot_in,k              [kg/s]
//   dU/dt = sum_k mdot_in,k h0_k         [W]    (total enthalpy of the entering/leaving gas)
//   U = m cv T [J],   p = m R T / V = (gamma-1) U/V [Pa]
// Integrated with the network time step, exactly conservative: every flow added here is the
// negative of the flow given to the connected pipe end.
//
// Explicit connections (valves, turbomachines: addFlow) use the state at the step start; their
// stable step is ~ V/(c sum A_k) (A_k the registered end/orifice areas).
// Implicit ports (OpenEnd to a finite volume when the volume is implicit, Network::
// setImplicitVolumes): the port flux into pipe end k is linearised in the volume pressure,
//   F_k(p') = F_k(p) + (dF_k/dp) dp,   dp = p' - p   (mass, momentum, energy; characteristics.hpp)
// and dp is the linearised backward-Euler solution of the volume energy balance (at fixed V,
// p = (gamma-1) U/V, so the energy equation alone gives p'):
//   dp = k S / (1 + k D),  k = (gamma-1) dt/V,  S = E_expl - sum_k E_k,  D = sum_k dE_k/dp >= 0
// (E_k energy into pipe end k, E_expl the explicit connections' energy into the volume). Both
// the pipe ends and the volume then get the corrected fluxes F_k(p'), so mass and energy stay
// conserved to round-off whatever dp is; the ports then no longer limit the step (the filling
// mode dp/dt = -(c^2/V) sum_k dmdot_k/dp p is integrated by backward Euler: unconditionally
// stable, first order, like the explicit update).
// Implicit one-cell pipes (Network::setImplicitOneCellPipes): a port whose pipe is one FSM cell
// with an explicit boundary at its other end (a valve, a turbine entry) also takes the cell's
// new pressure p_c' = p_c + dp_c into its linearisation, F_k + dF_k/dp dp + dF_k/dp_c dp_c_k. The
// cell's energy balance (V_c/((gamma-1) dt)) dp_c = E_k + G_k (G_k the energy the other end
// brings in, explicit) gives dp_c_k = alpha_k + beta_k dp with
//   alpha_k = (E_k + G_k)/(C_k - e_k),  beta_k = d_k/(C_k - e_k),  C_k = V_c/((gamma-1) dt),
//   d_k = dE_k/dp >= 0, e_k = dE_k/dp_c <= 0,
// and the volume's balance then has S' = S - sum_k e_k alpha_k, D' = sum_k (d_k + e_k beta_k)
// = sum_k d_k C_k/(C_k - e_k) >= 0 in place of S, D. The one-cell pipe's acoustic mode (its
// stable step dx/(|u| + c) when explicit) is then backward Euler; only the transport of mass
// and energy through the cell limits its step (Pipe::maxDt).
#pragma once
#include <string>
#include <vector>

#include "gasdyn/gas.hpp"
#include "gasdyn/pipe.hpp"

namespace hbt::gasdyn {

/// One pipe end connected to a Volume through an implicit port (owned by the OpenEnd).
struct VolumePort {
  Pipe* pipe = nullptr;
  End end = End::Left;
  EndFlux flux;  // into the pipe, at the volume state of the step start (final after closePorts)
  double dmdot_dp = 0.0, dmomentum_dp = 0.0, denergy_dp = 0.0;  // d flux / d p_volume
  // Implicit one-cell pipe (pipe->implicitCell()): d flux / d p of the pipe's cell (isentropic
  // change of the end state) [kg/(s Pa)], [m^2], [W/Pa].
  double dmdot_dpc = 0.0, dmomentum_dpc = 0.0, denergy_dpc = 0.0;
  double cell_alpha = 0.0, cell_beta = 0.0;  // dp_c = alpha + beta dp of the step [Pa], [-]
};

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
  /// Explicit connection of end/orifice area [m^2] (stable-step estimate).
  void registerConnection(double area) { area_sum_ += area; }
  /// Port of a pipe end of area [m^2] (finite volumes only; setup time, not during a step).
  void registerPort(VolumePort* port, double area);
  /// Implicit ports on/off (default off: ports are explicit connections).
  void setImplicit(bool on) { implicit_ = on && !reservoir_; }
  bool implicit() const { return implicit_; }
  /// Number of this volume's ports on pipe p (0, 1 or 2).
  int portsOf(const Pipe& p) const {
    int n = 0;
    for (const VolumePort* q : ports_) n += q->pipe == &p;
    return n;
  }
  /// After all boundaries have computed their fluxes: solves dp (implicit) and gives every port's
  /// final flux to its pipe end and (negated) to this volume.
  void closePorts(double dt);
  double maxDt() const;
  void advance(double dt);  // throws hbt::ModelDivergence("volume <name>", ...)
  /// Time integrals of what entered the volume since the start [kg], [J].
  double cumulativeMassIn() const { return cum_m_; }
  double cumulativeEnergyIn() const { return cum_e_; }

 private:
  Volume() = default;
  PerfectGas gas_;
  std::string name_;
  bool reservoir_ = false, implicit_ = false;
  double V_ = 0.0, p_ = 0.0, T_ = 0.0, m_ = 0.0, U_ = 0.0;
  double mdot_ = 0.0, edot_ = 0.0, area_sum_ = 0.0, port_area_ = 0.0;
  double cum_m_ = 0.0, cum_e_ = 0.0;
  std::vector<VolumePort*> ports_;
};

}  // namespace hbt::gasdyn
