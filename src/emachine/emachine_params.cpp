#include "emachine/emachine_params.hpp"

#include "common/errors.hpp"

namespace hbt::emachine {

void EMachineParams::declare(ParamSet& ps) {
  ps.setPrefix("data/");
  ps.add("vemp_file", data.vemp_file, "VECTO .vemp peak envelope (drive/recuperation torque vs EM speed)");
  ps.add("ratio", data.ratio, "-", 0.2, 10.0, "EM speed / crank speed");
  ps.add("rotor_inertia_kgm2", data.rotor_inertia_kgm2, "kg m^2", 0.0, 5.0, "rotor inertia at the EM shaft (vehicle: on the crank)");
  ps.add("ratio_efficiency", data.ratio_efficiency, "-", 0.5, 1.0, "efficiency of the EM-crank ratio stage");

  EnvelopeParams& e = envelope;
  ps.setPrefix("envelope/");
  ps.add("nominal_voltage_V", e.nominal_voltage_V, "V", 12.0, 1000.0, "DC voltage of the .vemp curve");
  ps.add("max_effective_voltage_V", e.max_effective_voltage_V, "V", 12.0, 1000.0, "no envelope gain above");
  ps.add("undervoltage_zero_V", e.undervoltage_zero_V, "V", 0.0, 1000.0, "envelope 0 below");
  ps.add("undervoltage_full_V", e.undervoltage_full_V, "V", 0.0, 1000.0, "envelope full above");
  ps.add("continuous_power_W", e.continuous_power_W, "W", 100.0, 1e6, "continuous |T w| at the nominal voltage");
  ps.add("continuous_torque_Nm", e.continuous_torque_Nm, "Nm", 1.0, 1e4, "continuous |T| (EM shaft)");

  ElectricalParams& el = electrical;
  ps.setPrefix("electrical/");
  ps.add("torque_constant_Nm_A", el.torque_constant_Nm_A, "Nm/A", 0.01, 10.0, "k_t = T/I_q (phase RMS)");
  ps.add("torque_constant_ref_K", el.torque_constant_ref_K, "K", 200.0, 450.0,
         "magnet temperature at which torque_constant_Nm_A, characteristic_current_A, peak_flux_density_T hold");
  ps.add("magnet_remanence_tempco_per_K", el.magnet_remanence_tempco_per_K, "1/K", -0.01, 0.0,
         "reversible temperature coefficient of the magnet remanence");
  ps.add("characteristic_current_A", el.characteristic_current_A, "A", 0.0, 5000.0, "psi/L (field-weakening current scale)");
  ps.add("pole_pairs", el.pole_pairs, "-", 1, 40, "pole pairs");
  ps.add("phase_resistance_20C_ohm", el.phase_resistance_20C_ohm, "ohm", 1e-5, 1.0, "DC phase resistance at 20 degC");
  ps.add("resistance_tempco_per_K", el.resistance_tempco_per_K, "1/K", 0.0, 0.01, "copper temperature coefficient");
  ps.add("ac_doubling_frequency_Hz", el.ac_doubling_frequency_Hz, "Hz", 10.0, 1e5, "R_ac/R_dc = 1 + (f/f_ac)^2");
  ps.add("phase_voltage_per_dc_volt", el.phase_voltage_per_dc_volt, "-", 0.1, 0.5, "max phase RMS voltage / V_dc");

  IronParams& fe = iron;
  ps.setPrefix("iron/");
  ps.add("stator_iron_mass_kg", fe.stator_iron_mass_kg, "kg", 0.1, 500.0, "stator lamination mass");
  ps.add("peak_flux_density_T", fe.peak_flux_density_T, "T", 0.1, 2.5, "peak flux density at full magnet flux");
  ps.add("hysteresis_coeff", fe.hysteresis_coeff, "W/(kg Hz T^2)", 0.0, 1.0, "k_h");
  ps.add("eddy_coeff", fe.eddy_coeff, "W/(kg Hz^2 T^2)", 0.0, 1e-2, "k_e");
  ps.add("build_factor", fe.build_factor, "-", 1.0, 5.0, "machine / Epstein-sample loss ratio");
  ps.add("rotor_loss_fraction", fe.rotor_loss_fraction, "-", 0.0, 2.0, "rotor loss / stator iron loss");

  MechanicalParams& m = mechanical;
  ps.setPrefix("mechanical/");
  ps.add("bearing_torque_Nm", m.bearing_torque_Nm, "Nm", 0.0, 10.0, "bearing + seal friction torque");
  ps.add("windage_ref_W", m.windage_ref_W, "W", 0.0, 1e4, "windage loss at the reference speed");
  ps.add("windage_ref_speed_rad_s", m.windage_ref_speed_rad_s, "rad/s", 1.0, 1e4, "reference speed of windage_ref_W");

  InverterParams& iv = inverter;
  ps.setPrefix("inverter/");
  ps.add("conduction_resistance_ohm", iv.conduction_resistance_ohm, "ohm", 0.0, 1.0, "conduction resistance per phase");
  ps.add("switching_frequency_Hz", iv.switching_frequency_Hz, "Hz", 100.0, 2e5, "PWM frequency");
  ps.add("switching_energy_ref_J", iv.switching_energy_ref_J, "J", 0.0, 1.0, "E_on+E_off per leg at V_ref, I_ref");
  ps.add("switching_ref_voltage_V", iv.switching_ref_voltage_V, "V", 1.0, 1000.0, "reference DC voltage");
  ps.add("switching_ref_current_A", iv.switching_ref_current_A, "A", 1.0, 1e4, "reference switched current");
  ps.add("fixed_loss_W", iv.fixed_loss_W, "W", 0.0, 1000.0, "fixed loss while the inverter is active");

  ThermalParams& t = thermal;
  ps.setPrefix("thermal/");
  ps.add("C_winding_J_K", t.C_winding_J_K, "J/K", 1e-3, 1e7, "winding (copper + impregnation)");
  ps.add("C_stator_J_K", t.C_stator_J_K, "J/K", 1e-3, 1e7, "stator laminations");
  ps.add("C_rotor_J_K", t.C_rotor_J_K, "J/K", 1e-3, 1e7, "rotor core, magnets, shaft");
  ps.add("C_housing_J_K", t.C_housing_J_K, "J/K", 1e-3, 1e7, "housing with coolant jacket");
  ps.add("G_winding_stator_W_K", t.G_winding_stator_W_K, "W/K", 1e-4, 1e6, "slot liner / impregnation");
  ps.add("G_winding_housing_W_K", t.G_winding_housing_W_K, "W/K", 1e-4, 1e6, "end windings to housing");
  ps.add("G_stator_housing_W_K", t.G_stator_housing_W_K, "W/K", 1e-4, 1e6, "stator-housing shrink fit");
  ps.add("G_rotor_stator_W_K", t.G_rotor_stator_W_K, "W/K", 1e-4, 1e6, "air gap");
  ps.add("G_rotor_housing_W_K", t.G_rotor_housing_W_K, "W/K", 1e-4, 1e6, "shaft, bearings, end-space air");
  ps.add("G_housing_coolant_W_K", t.G_housing_coolant_W_K, "W/K", 1e-4, 1e6, "water jacket to LT coolant");
  ps.add("G_housing_engine_W_K", t.G_housing_engine_W_K, "W/K", 0.0, 1e6, "housing flange to the flywheel housing");
  ps.add("G_rotor_crank_W_K", t.G_rotor_crank_W_K, "W/K", 0.0, 1e6, "rotor hub to the crankshaft flange");

  DeratingParams& d = derating;
  ps.setPrefix("derating/");
  ps.add("winding_start_K", d.winding_start_K, "K", 300.0, 600.0, "winding: peak limit starts to fall");
  ps.add("winding_continuous_K", d.winding_continuous_K, "K", 300.0, 600.0, "winding: limit = continuous envelope");
  ps.add("winding_zero_K", d.winding_zero_K, "K", 300.0, 600.0, "winding: limit = 0 (insulation limit)");
  ps.add("magnet_start_K", d.magnet_start_K, "K", 300.0, 600.0, "magnets: peak limit starts to fall");
  ps.add("magnet_continuous_K", d.magnet_continuous_K, "K", 300.0, 600.0, "magnets: limit = continuous envelope");
  ps.add("magnet_zero_K", d.magnet_zero_K, "K", 300.0, 600.0, "magnets: limit = 0 (demagnetisation risk)");

  ps.setPrefix("numerics/");
  ps.add("min_temperature_K", numerics.min_temperature_K, "K", 100.0, 300.0, "divergence bound");
  ps.add("max_temperature_K", numerics.max_temperature_K, "K", 350.0, 2000.0, "divergence bound");
  ps.setPrefix("");
}

void EMachineParams::validate(const std::string& file) const {
  const auto& e = envelope;
  if (!(e.max_effective_voltage_V >= e.nominal_voltage_V))
    throw InputError(file, "envelope/max_effective_voltage_V", "must be >= nominal_voltage_V");
  if (!(e.undervoltage_full_V > e.undervoltage_zero_V))
    throw InputError(file, "envelope/undervoltage_full_V", "must be above undervoltage_zero_V");
  if (!(e.undervoltage_full_V <= e.nominal_voltage_V))
    throw InputError(file, "envelope/undervoltage_full_V", "must be <= nominal_voltage_V");
  const auto& d = derating;
  if (!(d.winding_continuous_K > d.winding_start_K))
    throw InputError(file, "derating/winding_continuous_K", "must be above winding_start_K");
  if (!(d.winding_zero_K > d.winding_continuous_K))
    throw InputError(file, "derating/winding_zero_K", "must be above winding_continuous_K");
  if (!(d.magnet_continuous_K > d.magnet_start_K))
    throw InputError(file, "derating/magnet_continuous_K", "must be above magnet_start_K");
  if (!(d.magnet_zero_K > d.magnet_continuous_K))
    throw InputError(file, "derating/magnet_zero_K", "must be above magnet_continuous_K");
  if (!(numerics.max_temperature_K > d.winding_zero_K && numerics.max_temperature_K > d.magnet_zero_K))
    throw InputError(file, "numerics/max_temperature_K", "must be above the derating zero temperatures");
  if (data.vemp_file.empty()) throw InputError(file, "data/vemp_file", "must name a .vemp file");
}

}  // namespace hbt::emachine
