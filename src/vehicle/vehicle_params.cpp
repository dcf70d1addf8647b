#include "vehicle/vehicle_params.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "common/errors.hpp"

namespace hbt::vehicle {

void VehicleParams::declare(ParamSet& ps) {
  ChassisParams& c = chassis;
  ps.setPrefix("chassis/");
  ps.add("curb_mass_kg", c.curb_mass_kg, "kg", 1000.0, 40000.0, "curb mass");
  ps.add("payload_kg", c.payload_kg, "kg", 0.0, 15000.0, "payload (passengers)");
  ps.add("cda_m2", c.cda_m2, "m^2", 1.0, 15.0, "aerodynamic drag area Cd*A");
  ps.add("air_R_J_kgK", c.air_R_J_kgK, "J/(kg K)", 280.0, 295.0, "gas constant of air");
  ps.add("rrc_front", c.rrc_front, "-", 0.001, 0.03, "rolling resistance coefficient axle 1");
  ps.add("rrc_rear", c.rrc_rear, "-", 0.001, 0.03, "rolling resistance coefficient axle 2");
  ps.add("front_axle_load_share", c.front_axle_load_share, "-", 0.1, 0.9, "static load share axle 1");
  ps.add("tyres_front", c.tyres_front, "-", 1, 8, "tyres on axle 1");
  ps.add("tyres_rear", c.tyres_rear, "-", 1, 8, "tyres on axle 2");
  ps.add("tyre_fz_iso_N", c.tyre_fz_iso_N, "N", 1e3, 1e5, "ISO test load per tyre");
  ps.add("rrc_load_exponent", c.rrc_load_exponent, "-", 0.5, 1.0, "VECTO beta (1 = no load correction)");
  ps.add("wheel_inertia_kg_m2", c.wheel_inertia_kg_m2, "kg m^2", 0.0, 100.0, "per tyre");
  ps.add("tyre_radius_m", c.tyre_radius_m, "m", 0.2, 1.0, "dynamic tyre radius");
  ps.add("rrc_temperature_coefficient_per_K", c.rrc_temperature_coefficient_per_K, "1/K", 0.0, 0.02,
         "K_t: F_r(t) = F_r,ref / (1 + K_t (t - t_ref)) (UN R117 / ISO 28580)");
  ps.add("rrc_reference_temperature_K", c.rrc_reference_temperature_K, "K", 273.15, 323.15,
         "ambient temperature of the RRC_ISO values (ISO 28580: 25 degC)");

  DrivelineParams& d = driveline;
  ps.setPrefix("driveline/");
  ps.add("gear_ratios", d.gear_ratios, "-", 0.3, 10.0, "gearbox ratios, gear 1 first");
  ps.add("gear_max_input_torque_Nm", d.gear_max_input_torque_Nm, "Nm", 0.0, 1e4, "0 = no limit");
  ps.add("axle_ratio", d.axle_ratio, "-", 1.0, 20.0, "final drive ratio");
  ps.add("axle_efficiency", d.axle_efficiency, "-", 0.5, 1.0, "axle efficiency");
  ps.add("torque_converter_file", d.torque_converter_file, "VECTO .vtcc characteristic");
  ps.add("retarder_loss_file", d.retarder_loss_file, "retarder drag table ('' = none)");
  ps.add("tc_reference_speed_rad_s", d.tc_reference_speed_rad_s, "rad/s", 10.0, 1000.0, "MP reference speed");
  ps.add("engine_inertia_kg_m2", d.engine_inertia_kg_m2, "kg m^2", 0.1, 20.0, "crank + flywheel");
  ps.add("tc_pump_inertia_kg_m2", d.tc_pump_inertia_kg_m2, "kg m^2", 0.0, 10.0, "TC pump side");
  ps.add("gearbox_input_inertia_kg_m2", d.gearbox_input_inertia_kg_m2, "kg m^2", 0.0, 10.0, "turbine + input");
  ps.add("neutral_drag_torque_Nm", d.neutral_drag_torque_Nm, "Nm", 0.0, 100.0, "AT spin loss in neutral at pump speed");

  ShiftParams& s = shift;
  ps.setPrefix("shift/");
  ps.add("upshift_speed_low_rad_s", s.upshift_speed_low_rad_s, "rad/s", 50.0, 400.0, "upshift line at pedal 0");
  ps.add("upshift_speed_high_rad_s", s.upshift_speed_high_rad_s, "rad/s", 50.0, 400.0, "upshift line at pedal 1");
  ps.add("downshift_speed_low_rad_s", s.downshift_speed_low_rad_s, "rad/s", 30.0, 400.0, "downshift line at pedal 0");
  ps.add("downshift_speed_high_rad_s", s.downshift_speed_high_rad_s, "rad/s", 30.0, 400.0, "downshift line at pedal 1");
  ps.add("hysteresis_rad_s", s.hysteresis_rad_s, "rad/s", 0.0, 100.0, "upshift only if next-gear speed >= downshift line + this");
  ps.add("max_speed_after_downshift_rad_s", s.max_speed_after_downshift_rad_s, "rad/s", 50.0, 400.0, "");
  ps.add("min_time_between_shifts_s", s.min_time_between_shifts_s, "s", 0.0, 20.0, "");
  ps.add("shift_duration_s", s.shift_duration_s, "s", 0.0, 3.0, "slip phase of a gear change (0 = instantaneous)");
  ps.add("shift_torque_intervention", s.shift_torque_intervention, "reduce engine torque by the inertia torque during upshifts");
  ps.add("lockup_speed_ratio", s.lockup_speed_ratio, "-", 0.5, 1.0, "lock-up when nu >= this");
  ps.add("lockup_min_turbine_speed_rad_s", s.lockup_min_turbine_speed_rad_s, "rad/s", 30.0, 400.0, "");
  ps.add("lockup_duration_s", s.lockup_duration_s, "s", 0.0, 3.0, "slip phase of the lock-up clutch (0 = instantaneous)");
  ps.add("unlock_engine_speed_rad_s", s.unlock_engine_speed_rad_s, "rad/s", 30.0, 400.0, "1L -> 1C below");
  ps.add("neutral_at_stop", s.neutral_at_stop, "neutral while held at standstill");

  DriverParams& r = driver;
  ps.setPrefix("driver/");
  ps.add("kp_per_s", r.kp_per_s, "1/s", 0.0, 20.0, "speed PI proportional gain (per unit mass)");
  ps.add("ki_per_s2", r.ki_per_s2, "1/s^2", 0.0, 20.0, "speed PI integral gain (per unit mass)");
  ps.add("max_brake_decel_m_s2", r.max_brake_decel_m_s2, "m/s^2", 1.0, 10.0, "friction brake capacity");
  ps.add("stop_target_speed_m_s", r.stop_target_speed_m_s, "m/s", 0.0, 1.0, "");
  ps.add("hold_speed_m_s", r.hold_speed_m_s, "m/s", 0.0, 3.0, "");
  ps.add("hold_brake_fraction", r.hold_brake_fraction, "-", 0.0, 1.0, "");
  ps.add("stop_decel_m_s2", r.stop_decel_m_s2, "m/s^2", 0.1, 5.0, "braking to standstill at a stop");
  ps.add("max_distance_error_m", r.max_distance_error_m, "m", 0.0, 100.0, "saturation of the distance error = PI integral");
  ps.add("idle_kp_Nm_s", r.idle_kp_Nm_s, "Nm s/rad", 0.0, 500.0, "idle governor P");
  ps.add("idle_ki_Nm", r.idle_ki_Nm, "Nm/rad", 0.0, 2000.0, "idle governor I");
  ps.add("idle_kd_Nm_s2", r.idle_kd_Nm_s2, "Nm s^2/rad", 0.0, 50.0, "idle governor D (on -dw/dt)");

  ps.setPrefix("aux/");
  aux.declare(ps);

  ps.setPrefix("gearbox/");
  gearbox.declare(ps);

  OilUnitParams& g = driveline_oil.gearbox;
  ps.setPrefix("driveline_oil/gearbox/");
  ps.add("heat_capacity_J_K", g.heat_capacity_J_K, "J/K", 1e3, 1e7, "ATF + wetted housing");
  ps.add("ua_ambient_W_K", g.ua_ambient_W_K, "W/K", 0.1, 1e4, "housing to ambient air");
  ps.add("cooler_open_K", g.cooler_open_K, "K", 273.15, 420.0, "oil-to-coolant cooler holds the oil at or below this");
  ps.add("reference_K", g.reference_K, "K", 273.15, 420.0, "oil temperature of the warm loss data");
  ps.add("vogel_b_K", g.vogel_b_K, "K", 100.0, 5000.0, "Vogel law of the ATF");
  ps.add("vogel_c_K", g.vogel_c_K, "K", 0.0, 250.0, "Vogel law of the ATF");
  ps.add("drag_viscosity_exponent", g.drag_viscosity_exponent, "-", 0.0, 1.5, "drag torque ~ nu^n");
  ps.add("warm_start_K", g.warm_start_K, "K", 273.15, 420.0, "oil temperature at start:=warm");
  OilUnitParams& a = driveline_oil.axle;
  a.cooler_open_K = 0.0;  // no cooler: not a key of the axle
  ps.setPrefix("driveline_oil/axle/");
  ps.add("heat_capacity_J_K", a.heat_capacity_J_K, "J/K", 1e3, 1e7, "gear oil + wetted housing");
  ps.add("ua_ambient_W_K", a.ua_ambient_W_K, "W/K", 0.1, 1e4, "housing to ambient air");
  ps.add("warm_start_K", a.warm_start_K, "K", 273.15, 420.0, "oil temperature at start:=warm");

  ps.setPrefix("numerics/");
  ps.add("max_substep_s", numerics.max_substep_s, "s", 1e-5, 0.01, "internal integration step");
  ps.setPrefix("");
}

void AuxParams::declare(ParamSet& ps) {
  ps.add("steering_pump_W", steering_pump_W, "W", 0.0, 2e4, "mechanical power");
  ps.add("air_compressor_W", air_compressor_W, "W", 0.0, 2e4, "mechanical power");
  ps.add("alternator_W", alternator_W, "W", 0.0, 2e4, "mechanical power");
  ps.add("fan_default_W", fan_default_W, "W", -1e4, 5e4, "fan power without cooling node");
  ps.add("electric_dcdc_W", electric_dcdc_W, "W", 0.0, 2e4, "24 V consumers fed by the 48 V DC/DC (hybrid)");
  ps.add("dcdc_efficiency", dcdc_efficiency, "-", 0.5, 1.0, "48 V -> 24 V DC/DC efficiency");
  ps.add("alternator_efficiency", alternator_efficiency, "-", 0.3, 1.0, "alternator mechanical -> electric");
}

void GearLossSetParams::declare(ParamSet& ps) {
  ps.add("gear_loss_map_file", gear_loss_map_file, "VECTO gearbox torque-loss map (input speed, input torque, loss)");
  ps.add("gear_load_loss_factor", gear_load_loss_factor, "-", 0.0, 3.0, "x load-dependent part of the map, per gear");
}

std::string gearLossSetFile(const std::string& config_dir, const std::string& name) {
  const std::string dir = config_dir + "/gearbox";
  std::vector<std::string> sets;
  if (std::filesystem::is_directory(dir))
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".yaml") sets.push_back(e.path().stem().string());
  std::sort(sets.begin(), sets.end());
  const bool word = !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
  if (!word || std::find(sets.begin(), sets.end(), name) == sets.end()) {
    std::string avail;
    for (const auto& s : sets) avail += (avail.empty() ? "" : ", ") + s;
    throw InputError(dir, "gearbox", "unknown gear loss set '" + name + "' (no " + dir +
                                                       "/" + name + ".yaml); available: " + avail);
  }
  return dir + "/" + name + ".yaml";
}

void VehicleParams::validate(const std::string& file) const {
  const auto& d = driveline;
  const std::size_t n = d.gear_ratios.size();
  if (n < 1) throw InputError(file, "driveline/gear_ratios", "at least one gear");
  for (std::size_t i = 1; i < n; ++i)
    if (!(d.gear_ratios[i] < d.gear_ratios[i - 1]))
      throw InputError(file, "driveline/gear_ratios", "ratios must decrease from gear 1");
  if (d.gear_max_input_torque_Nm.size() != n)
    throw InputError(file, "driveline/gear_max_input_torque_Nm", "one value per gear");
  if (gearbox.gear_load_loss_factor.size() != n)
    throw InputError(file, "gearbox/gear_load_loss_factor", "one value per gear (driveline/gear_ratios)");
  const auto& s = shift;
  if (!(s.upshift_speed_high_rad_s >= s.upshift_speed_low_rad_s))
    throw InputError(file, "shift/upshift_speed_high_rad_s", "must be >= upshift_speed_low_rad_s");
  if (!(s.downshift_speed_high_rad_s >= s.downshift_speed_low_rad_s))
    throw InputError(file, "shift/downshift_speed_high_rad_s", "must be >= downshift_speed_low_rad_s");
  if (!(s.downshift_speed_low_rad_s < s.upshift_speed_low_rad_s))
    throw InputError(file, "shift/downshift_speed_low_rad_s", "must be below the upshift line");
  if (!(s.unlock_engine_speed_rad_s < s.lockup_min_turbine_speed_rad_s))
    throw InputError(file, "shift/unlock_engine_speed_rad_s", "must be below lockup_min_turbine_speed_rad_s");
  if (!(s.unlock_engine_speed_rad_s > d.idle_speed_rad_s))
    throw InputError(file, "shift/unlock_engine_speed_rad_s", "must be above the idle speed");
}

}  // namespace hbt::vehicle
