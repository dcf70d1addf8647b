// Parameters of the 48 V P1 e-machine with its inverter (torque envelope, loss model, thermal
// network, thermal derating). SI units (temperatures in K, speeds in rad/s). Keys (group/key) =
// config/emachine.yaml, where every value and its source is documented.
#pragma once
#include <string>

#include "common/params.hpp"
#include "common/units.hpp"

namespace hbt::emachine {

/// Data file and the ratio stage between the machine and the crankshaft.
struct DataParams {
  /// VECTO .vemp: drive / recuperation torque vs EM speed at the nominal voltage (peak envelope).
  std::string vemp_file =
      "config/data/vehicle/citybus_P1_hybrid_48V/GenericEM_15kW_220Nm_fullload.vemp";
  double ratio = 2.0;             // EM speed / crank speed (VECTO EM_ratio)
  double ratio_efficiency = 0.98; // of that ratio stage (VECTO EM_mech_efficiency)
  /// Rotor inertia at the EM shaft [kg m²] (VECTO .vem); not used by the e-machine model: the
  /// vehicle adds rotor_inertia_kgm2 · ratio² to the crank inertia (crankInertia_kgm2()).
  double rotor_inertia_kgm2 = 0.198;
  double crankInertia_kgm2() const { return rotor_inertia_kgm2 * ratio * ratio; }
};

/// Peak envelope scaling with the DC voltage, continuous envelope, under-voltage cut-off.
struct EnvelopeParams {
  double nominal_voltage_V = 48.0;          // voltage of the .vemp curve
  double max_effective_voltage_V = 52.0;    // above: no further gain of the envelope
  double undervoltage_zero_V = 24.0;        // envelope 0 below
  double undervoltage_full_V = 36.0;        // envelope full above (linear between)
  double continuous_power_W = 15000.0;      // |T ω| of the continuous envelope at V_nom
  double continuous_torque_Nm = 220.0;      // |T| of the continuous envelope (EM side)
};

/// Phase-current model of the PMSM (per-phase RMS quantities) and copper losses.
struct ElectricalParams {
  double torque_constant_Nm_A = 0.73;       // k_t = T / I_q (3 x back-EMF constant) at torque_constant_ref_K
  double torque_constant_ref_K = units::celsiusToK(20.0);  // magnet temperature of k_t, I_ch, B̂
  double magnet_remanence_tempco_per_K = -0.0011;          // α_Br of the NdFeB grade (reversible)
  double characteristic_current_A = 150.0; // I_ch = ψ/L: field-weakening current scale
  int pole_pairs = 6;
  double phase_resistance_20C_ohm = 2.5e-3; // DC phase resistance at 20 °C
  double resistance_tempco_per_K = 0.00393; // copper
  double ac_doubling_frequency_Hz = 500.0;  // R_ac/R_dc = 1 + (f/f_ac)^2
  double phase_voltage_per_dc_volt = 0.408248290463863; // V_ph,max (RMS) / V_dc = 1/√6 (SVPWM)
};

/// Stator iron (two-term Steinmetz/Bertotti with exponent 2) and rotor losses.
struct IronParams {
  double stator_iron_mass_kg = 14.0;
  double peak_flux_density_T = 1.5;          // B̂ at full magnet flux (teeth/yoke average)
  double hysteresis_coeff = 0.021;           // k_h [W/(kg Hz T^2)]
  double eddy_coeff = 6.0e-5;                // k_e [W/(kg Hz^2 T^2)]
  double build_factor = 2.0;                 // punching, assembly, PWM harmonics
  double rotor_loss_fraction = 0.2;          // rotor iron + magnet eddy / stator iron loss
};

struct MechanicalParams {
  double bearing_torque_Nm = 0.1;            // Coulomb bearing + seal friction (EM shaft)
  double windage_ref_W = 40.0;               // windage at the reference speed (∝ ω^3)
  double windage_ref_speed_rad_s = units::rpmToRadps(4864.577923);
};

/// 48 V MOSFET inverter: conduction ∝ I^2, switching ∝ V_dc I, fixed loss while active.
struct InverterParams {
  double conduction_resistance_ohm = 0.6e-3; // per phase: switch R_ds,on + busbars
  double switching_frequency_Hz = 16000.0;
  double switching_energy_ref_J = 5.0e-3;    // E_on + E_off per leg and PWM period at V_ref, I_ref
  double switching_ref_voltage_V = 48.0;
  double switching_ref_current_A = 300.0;    // instantaneous phase current of E_ref
  double fixed_loss_W = 40.0;                // gate drives, control, DC-link ESR (while active)
};

/// Lumped-parameter thermal network: winding W, stator iron S, rotor + magnets R, housing +
/// coolant jacket H; H exchanges heat with the LT coolant.
struct ThermalParams {
  double C_winding_J_K = 2600.0;
  double C_stator_J_K = 6400.0;
  double C_rotor_J_K = 4800.0;
  double C_housing_J_K = 5400.0;
  double G_winding_stator_W_K = 20.0;
  double G_winding_housing_W_K = 3.0;
  double G_stator_housing_W_K = 150.0;
  double G_rotor_stator_W_K = 2.5;
  double G_rotor_housing_W_K = 1.0;
  double G_housing_coolant_W_K = 120.0;
  double G_housing_engine_W_K = 35.0;       // housing flange -> flywheel housing (engine)
  double G_rotor_crank_W_K = 4.0;           // rotor hub -> crankshaft flange (engine)
};

/// Thermal derating of the torque limits: between `start` and `continuous` the live limit goes
/// from the peak to the continuous envelope, between `continuous` and `zero` from the
/// continuous envelope to 0. Winding = mean winding node, magnet = rotor node.
struct DeratingParams {
  double winding_start_K = units::celsiusToK(140.0);
  double winding_continuous_K = units::celsiusToK(160.0);
  double winding_zero_K = units::celsiusToK(180.0);
  double magnet_start_K = units::celsiusToK(120.0);
  double magnet_continuous_K = units::celsiusToK(135.0);
  double magnet_zero_K = units::celsiusToK(150.0);
};

struct NumericsParams {
  double min_temperature_K = 200.0;  // a node outside [min, max] = ModelDivergence
  double max_temperature_K = 600.0;
};

struct EMachineParams {
  DataParams data;
  EnvelopeParams envelope;
  ElectricalParams electrical;
  IronParams iron;
  MechanicalParams mechanical;
  InverterParams inverter;
  ThermalParams thermal;
  DeratingParams derating;
  NumericsParams numerics;
  /// Registers every parameter as "<group>/<key>" (groups data, envelope, electrical, iron,
  /// mechanical, inverter, thermal, derating, numerics) = config/emachine.yaml.
  void declare(ParamSet& ps);
  /// Cross-field checks (ordering of the derating and voltage thresholds). Throws
  /// InputError(file, key).
  void validate(const std::string& file = "(emachine parameters)") const;
};

}  // namespace hbt::emachine
