// Parameters of the vehicle, driveline, shift strategy, driver and auxiliaries (SI units).
// Keys (group/key) = config/vehicle.yaml, where every value's source is documented.
#pragma once
#include <string>
#include <vector>

#include "common/params.hpp"
#include "common/units.hpp"
#include "vehicle/driveline_oil.hpp"

namespace hbt::vehicle {

struct ChassisParams {
  double curb_mass_kg = 15160.0;          // SPEC §2
  double payload_kg = 1500.0;             // scenario parameter, SPEC §2 default
  double cda_m2 = 5.36;                   // drag area Cd·A (VECTO 2015 AT-TC demo city bus)
  double ambient_pressure_Pa = units::kStandardAtmosphere_Pa;  // air density ρ = p/(R_air T_ambient); the node sets the scenario's
  double air_R_J_kgK = 287.05;
  double rrc_front = 0.0055;              // RRC_ISO axle 1 (P31 XML)
  double rrc_rear = 0.0063;               // RRC_ISO axle 2, twin tyres (P31 XML)
  double front_axle_load_share = 0.38;    // static axle load share (VECTO AT-TC city bus)
  int tyres_front = 2;
  int tyres_rear = 4;
  double tyre_fz_iso_N = 31300.0;         // ISO test load F_zISO (P31 XML)
  double rrc_load_exponent = 0.9;         // VECTO β: RRC = RRC_ISO (F_z/F_zISO)^(β-1)
  double wheel_inertia_kg_m2 = 14.9;      // per tyre, Wheels.csv 315/70 R22.5
  double tyre_radius_m = 0.4915;          // dynamic radius: d·3.05/(2π), d = 1012.5 mm
  // Tyre rolling resistance vs ambient temperature, UN R117 / ISO 28580 (C3, LI > 121):
  // F_r(t) = F_r25 / (1 + K_t (t - t_ref)), t = ambient [K or degC alike: a difference]
  double rrc_temperature_coefficient_per_K = 0.006;  // K_t [1/K]
  double rrc_reference_temperature_K = 298.15;       // t_ref = 25 degC
};

struct DrivelineParams {
  std::vector<double> gear_ratios{3.364, 1.909, 1.421, 1.000, 0.720, 0.615};  // APT-S
  std::vector<double> gear_max_input_torque_Nm{1900.0, 1900.0, 0.0, 0.0, 0.0, 0.0};  // 0 = none
  double axle_ratio = 6.5;                // P31 XML single portal axle
  double axle_efficiency = 0.95;          // VECTO AT-TC demo city bus
  std::string torque_converter_file =
      "config/data/vehicle/generic_primary_bus_P31/torque_converter_APT-S_standard_values.vtcc";
  std::string retarder_loss_file =
      "config/data/vehicle/generic_primary_bus_P31/retarder_loss_map.csv";  // "" = none
  double tc_reference_speed_rad_s = units::rpmToRadps(1000.0);  // MP1000 reference
  double engine_inertia_kg_m2 = 3.8;      // crank + flywheel (VECTO AT-TC demo 7.7 l engine)
  double tc_pump_inertia_kg_m2 = 0.5;     // VECTO AT-TC demo TC inertia, on the pump side
  double gearbox_input_inertia_kg_m2 = 0.3;  // turbine + input shaft + sets (assumption)
  double idle_speed_rad_s = units::rpmToRadps(700.0);  // P31 XML idling speed
  double neutral_drag_torque_Nm = 12.0;   // AT spin loss in neutral at the pump (estimate)
};

/// Gear loss set (config/gearbox/<set>.yaml, group `gearbox:`, launch argument gearbox:=<set>):
/// the gearbox torque-loss map and the per-gear factor on its load part. Defaults = "typical".
struct GearLossSetParams {
  std::string gear_loss_map_file =  // VECTO generic-bus AT: eta = 0.925 in every gear
      "config/data/vehicle/gearbox_typical/gear_loss_map_generic_bus_AT_eta0925.csv";
  std::vector<double> gear_load_loss_factor{1.0, 1.0, 1.0, 1.0, 1.0, 1.0};  // × load part of map
  /// Registers the keys (without prefix) = the `gearbox:` group of a gear loss set.
  void declare(ParamSet& ps);
};

/// The gear loss sets shipped in config/gearbox/ (launch argument gearbox:=<set>).
/// Path of set `name` under `config_dir` (config/gearbox/<name>.yaml); InputError naming the
/// launch argument "gearbox" and the available sets when the name is not a plain word or no
/// such file exists.
std::string gearLossSetFile(const std::string& config_dir, const std::string& name);

struct ShiftParams {
  double upshift_speed_low_rad_s = units::rpmToRadps(1200.0);    // at accelerator 0
  double upshift_speed_high_rad_s = units::rpmToRadps(2200.0);   // at accelerator 1
  double downshift_speed_low_rad_s = units::rpmToRadps(850.0);   // at accelerator 0
  double downshift_speed_high_rad_s = units::rpmToRadps(1100.0); // at accelerator 1
  double hysteresis_rad_s = units::rpmToRadps(100.0);  // post-upshift speed >= downshift line + this
  double max_speed_after_downshift_rad_s = units::rpmToRadps(2200.0);
  double min_time_between_shifts_s = 2.0;
  double shift_duration_s = 0.6;          // clutch-to-clutch slip (inertia) phase; 0 = impulse
  bool shift_torque_intervention = true;  // TCU cuts engine torque by the inertia torque (upshift)
  double lockup_speed_ratio = 0.85;       // 1C -> 1L when ν >= this ...
  double lockup_min_turbine_speed_rad_s = units::rpmToRadps(1000.0);  // ... and ω_t >= this
  double lockup_duration_s = 0.4;         // slip phase of the lock-up clutch; 0 = impulse
  double unlock_engine_speed_rad_s = units::rpmToRadps(800.0);        // 1L -> 1C below this
  bool neutral_at_stop = true;            // ZF EcoLife-like standstill neutral
};

struct DriverParams {
  double kp_per_s = 1.0;                  // speed PI: ΔF = m (kp e + ki ∫e)
  double ki_per_s2 = 0.3;                 // on the distance error e_s = ∫e dt
  double max_brake_decel_m_s2 = 5.0;      // F_brake,max = m_total · this (UN R13 M3 ≥ 5 m/s²)
  double stop_target_speed_m_s = 0.01;    // target below this = stop requested
  double hold_speed_m_s = 0.5;            // stop requested and v below this: hold brake
  double hold_brake_fraction = 0.3;       // hold brake pedal [-]
  double stop_decel_m_s2 = 1.5;           // braking to standstill once the target is at rest
  double max_distance_error_m = 2.0;      // saturation of the distance error (PI state) [m]
  double idle_kp_Nm_s = 25.0;             // idle governor PI on ω_idle - ω_e
  double idle_ki_Nm = 10.0;
  double idle_kd_Nm_s2 = 0.7;             // ... and D on the crank acceleration dω_e/dt
};

struct AuxParams {
  double steering_pump_W = 1000.0;        // mechanical, constant (documented estimate)
  double air_compressor_W = 1500.0;       // mechanical, constant (documented estimate)
  double alternator_W = 2500.0;           // mechanical input, constant (1.75 kW el. / 0.7)
  double fan_default_W = 800.0;           // used until the cooling node provides fan power
  // Hybrid: the 24 V consumers fed from the 48 V battery through a DC/DC converter instead of
  // the alternator (not on the crank): electric power [W] and converter efficiency [-]. The
  // battery draws electric_dcdc_W / dcdc_efficiency (VehicleOutputs::dcdc_input_power_W).
  double electric_dcdc_W = 0.0;
  double dcdc_efficiency = 0.95;
  // Mechanical-to-electric efficiency of the alternator [-]: the crank load of an electric
  // consumer added at run time (the HVAC's) in a set without a DC/DC.
  double alternator_efficiency = 0.7;
  /// The set feeds its 24 V consumers from the 48 V battery through the DC/DC (else the alternator).
  bool electricViaDcdc() const { return electric_dcdc_W > 0.0; }
  /// Registers the keys (without prefix) = the `aux:` group of an auxiliary set
  /// (config/aux/<set>.yaml, selected with the launch argument aux:=<set>).
  void declare(ParamSet& ps);
};

struct NumericsParams {
  double max_substep_s = 0.001;           // internal Heun substep
};

/// Oil nodes of the gearbox and the axle (config/vehicle.yaml, group driveline_oil/).
struct DrivelineOilParams {
  // ATF + housing; oil-to-coolant cooler at 80 °C; spin losses ∝ ν^0.21 (Changenet & Velex)
  OilUnitParams gearbox{1.3e5, 20.0, 353.15, 353.15, 858.5, 161.8, 0.21, 353.15};
  // gear oil + axle housing, no cooler (temperature only: see src/vehicle/README.md)
  OilUnitParams axle{1.4e5, 30.0, 0.0, 353.15, 858.5, 161.8, 0.21, 343.15};
};

struct VehicleParams {
  ChassisParams chassis;
  DrivelineParams driveline;
  GearLossSetParams gearbox;  // group gearbox/ (a separate file, config/gearbox/<set>.yaml)
  ShiftParams shift;
  DriverParams driver;
  AuxParams aux;
  NumericsParams numerics;
  DrivelineOilParams driveline_oil;
  double totalMass_kg() const { return chassis.curb_mass_kg + chassis.payload_kg; }
  /// Registers every parameter as "<group>/<key>" (groups chassis, driveline, shift, driver,
  /// numerics, driveline_oil = config/vehicle.yaml; aux = config/aux/<set>.yaml; gearbox =
  /// config/gearbox/<set>.yaml).
  void declare(ParamSet& ps);
  /// Cross-field checks (vector lengths, ordering of shift lines). Throws InputError(file, key).
  void validate(const std::string& file = "(vehicle parameters)") const;
};

}  // namespace hbt::vehicle
