#include "battery/battery_model.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"

namespace hbt::battery {

namespace {
double clamp01(double x) { return std::min(1.0, std::max(0.0, x)); }
/// 1 - e^{-x} without cancellation.
double oneMinusExp(double x) { return -std::expm1(-x); }

PackThermalParams thermalParams(const BatteryParams& p) {
  const int n = p.pack.cells_in_series * p.pack.cells_in_parallel;
  const EnclosureParams& e = p.enclosure;
  PackThermalParams t;
  t.cells_area_m2 = n * p.cell.cooled_area_m2;
  t.cells_heat_capacity_J_K = n * p.cell.mass_kg * p.cell.cp_J_kgK;
  t.housing_area_m2 = p.housing.area_m2;
  t.housing_heat_capacity_J_K = p.housing.mass_kg * e.housing_cp_J_kgK;
  t.h_cells_natural_W_m2K = e.h_cells_natural_W_m2K;
  t.h_cells_fan_W_m2K = e.h_cells_fan_W_m2K;
  t.h_wall_inside_natural_W_m2K = e.h_wall_inside_natural_W_m2K;
  t.h_wall_inside_fan_W_m2K = e.h_wall_inside_fan_W_m2K;
  t.h_outside_natural_W_m2K = e.h_outside_natural_W_m2K;
  t.emissivity_cells = e.emissivity_cells;
  t.emissivity_housing = e.emissivity_housing;
  t.radiation_mean_temperature_K = e.radiation_mean_temperature_K;
  t.flow_length_m = p.housing.flow_length_m;
  t.air_conductivity_W_mK = e.air_conductivity_W_mK;
  t.air_viscosity_m2_s = e.air_viscosity_m2_s;
  t.air_prandtl = e.air_prandtl;
  const VentilationParams& v = p.ventilation;
  t.ventilation.fan_free_flow_m3_s = v.fan_free_flow_m3_s;
  t.ventilation.fan_max_pressure_Pa = v.fan_max_pressure_Pa;
  t.ventilation.fan_count = v.fan_count;
  t.ventilation.linear_resistance_Pa_s_m3 = v.filter_resistance_Pa_s_m3 + p.housing.cell_gap_resistance_Pa_s_m3;
  t.ventilation.quadratic_resistance_Pa_s2_m6 = v.minor_loss_Pa_s2_m6;
  t.ventilation.air_pressure_Pa = v.air_pressure_Pa;
  t.ventilation.air_cp_J_kgK = v.air_cp_J_kgK;
  return t;
}
}  // namespace

BatteryModel::BatteryModel(const BatteryParams& p, const std::string& file)
    : p_(p), file_(file), thermal_(thermalParams(p)), fan_(p.fan) {
  p_.validate(file);
  if (!std::ifstream(p_.cell.table_file).good())
    throw InputError(file, "cell/table_file", "cannot read '" + p_.cell.table_file + "'");
  table_ = CellTable::read(p_.cell.table_file);
  // The usable SOC window must be reachable inside the voltage window at every tabulated T.
  for (double T : table_.temperature()) {
    const double o_lo = table_.ocv(p_.limits.soc_min, T), o_hi = table_.ocv(p_.limits.soc_max, T);
    if (!(p_.cell.min_voltage_V < o_lo)) {
      std::ostringstream os;
      os << "must be below the OCV at limits/soc_min (" << o_lo << " V at " << T << " K)";
      throw InputError(file, "cell/min_voltage_V", os.str());
    }
    if (!(p_.cell.max_voltage_V > o_hi)) {
      std::ostringstream os;
      os << "must be above the OCV at limits/soc_max (" << o_hi << " V at " << T << " K)";
      throw InputError(file, "cell/max_voltage_V", os.str());
    }
  }
  n_cells_ = p_.pack.cells_in_series * p_.pack.cells_in_parallel;
  Q_As_ = p_.cell.capacity_Ah * 3600.0;
  reset(units::celsiusToK(25.0));
}

void BatteryModel::reset(double air_T_K) { reset(air_T_K, p_.pack.initial_soc); }

void BatteryModel::reset(double air_T_K, double soc) { resetState(air_T_K, air_T_K, soc); }

void BatteryModel::resetWarm(double cells_T_K, double housing_T_K) {
  resetState(cells_T_K, housing_T_K, p_.pack.initial_soc);
}

void BatteryModel::resetState(double cells_T_K, double housing_T_K, double soc) {
  for (double T : {cells_T_K, housing_T_K})
    if (!std::isfinite(T) || T < p_.numerics.min_temperature_K || T > p_.numerics.max_temperature_K)
      throw ModelDivergence("battery", "initial temperature", "outside the numerics/ bounds or not finite");
  if (!(soc >= 0.0 && soc <= 1.0)) throw ModelDivergence("battery", "initial SOC", "outside [0, 1]");
  soc_ = soc;
  v1_ = 0.0;
  T_ = cells_T_K;
  thermal_.reset(cells_T_K, housing_T_K);
  fan_.reset(cells_T_K);
  out_ = BatteryOutputs{};
  updateStateOutputs();
  out_.terminal_voltage_V = out_.ocv_V;  // at rest
}

StepEnvelope BatteryModel::envelope(double h) const {
  const CellPoint c = table_.at(soc_, T_);
  const double x = h / c.tau1_s;
  const double f = oneMinusExp(x) / x;  // (tau1/h)(1 - e^{-h/tau1})
  StepEnvelope e;
  e.emf_V = c.ocv_V - f * v1_;
  e.r_eff_Ohm = c.r0_Ohm + c.r1_Ohm * (1.0 - f);
  const auto& l = p_.limits;
  const double f_hot = clamp01((l.max_temperature_K - T_) / (l.max_temperature_K - l.hot_derate_start_K));
  const double f_cold = clamp01((T_ - l.charge_zero_K) / (l.charge_full_K - l.charge_zero_K));
  const double f_sd = clamp01((soc_ - l.soc_min) / l.soc_taper);
  const double f_sc = clamp01((l.soc_max - soc_) / l.soc_taper);
  const double E = e.emf_V, R = e.r_eff_Ohm;
  double i_d = std::min(E / (2.0 * R), (E - p_.cell.min_voltage_V) / R);
  i_d = std::min(i_d, p_.cell.max_discharge_current_A * f_hot * f_sd);
  double j_c = std::min((p_.cell.max_voltage_V - E) / R, p_.cell.max_charge_current_A * f_cold * f_hot * f_sc);
  e.discharge_cell_current_A = std::max(0.0, i_d);
  e.charge_cell_current_A = std::max(0.0, j_c);
  e.discharge_power_W = n_cells_ * e.discharge_cell_current_A * (E - e.discharge_cell_current_A * R);
  e.charge_power_W = n_cells_ * e.charge_cell_current_A * (E + e.charge_cell_current_A * R);
  return e;
}

void BatteryModel::updateStateOutputs() {
  const int ns = p_.pack.cells_in_series, np = p_.pack.cells_in_parallel;
  out_.soc = soc_;
  out_.cell_T_K = T_;
  out_.ocv_V = ns * table_.ocv(soc_, T_);
  out_.rc_voltage_V = ns * v1_;
  const StepEnvelope e = envelope(p_.limits.horizon_s);
  out_.discharge_power_limit_W = e.discharge_power_W;
  out_.charge_power_limit_W = e.charge_power_W;
  out_.discharge_current_limit_A = np * e.discharge_cell_current_A;
  out_.charge_current_limit_A = np * e.charge_cell_current_A;
  out_.housing_T_K = thermal_.housingT_K();
  out_.enclosure_air_T_K = thermal_.airT_K();
  out_.stored_heat_change_J = thermal_.storedHeat_J();
  out_.energy_residual_J = out_.chemical_energy_J - out_.terminal_energy_J + out_.fan_energy_J -
                           out_.heat_to_air_J - out_.ventilation_heat_J - out_.stored_heat_change_J -
                           out_.rc_stored_energy_change_J;
}

void BatteryModel::step(double h, const BatteryInputs& in) {
  if (!(h > 0.0) || !std::isfinite(h)) throw ModelDivergence("battery", "time step", "must be > 0 and finite");
  if (!std::isfinite(in.power_request_W)) throw ModelDivergence("battery", "power request", "not finite");
  if (!std::isfinite(in.air_T_K) || in.air_T_K <= 0.0)
    throw ModelDivergence("battery", "air temperature", "not finite or <= 0 K");
  if (!std::isfinite(in.air_speed_m_s)) throw ModelDivergence("battery", "air speed", "not finite");
  const double N = n_cells_;
  const bool fan_on = fan_.update(T_);  // (0.) from the start-of-step cell temperature
  const double P_fan = fan_.power_W();
  const CellPoint c = table_.at(soc_, T_);
  const StepEnvelope env = envelope(h);
  const double E = env.emf_V, R = env.r_eff_Ohm;

  // Cell current for the request (2.), or the limit current (3.).
  const double P = in.power_request_W + P_fan;
  double i;
  bool limited = false;
  if (P > env.discharge_power_W) {
    i = env.discharge_cell_current_A;
    limited = true;
  } else if (P < -env.charge_power_W) {
    i = -env.charge_cell_current_A;
    limited = true;
  } else {
    const double p = P / N;
    const double disc = std::max(0.0, E * E - 4.0 * R * p);
    i = 2.0 * p / (E + std::sqrt(disc));
  }

  // RC pair, exact with i held (4.).
  const double x = h / c.tau1_s;
  const double e1 = std::exp(-x), ome1 = oneMinusExp(x), ome2 = oneMinusExp(2.0 * x);
  const double a = i * c.r1_Ohm, b = v1_ - a;
  const double v1_new = a + b * e1;
  const double int_v1sq = a * a * h + 2.0 * a * b * c.tau1_s * ome1 + b * b * 0.5 * c.tau1_s * ome2;
  const double C1 = c.tau1_s / c.r1_Ohm;

  const double vt_mean = E - i * R;  // = OCV - i R0 - (1/h)∫v1 dt, (a h + b tau1 (1-e))/h
  const double W_ch = N * c.ocv_V * i * h;
  const double W_t = N * i * vt_mean * h;
  const double W_0 = N * i * i * c.r0_Ohm * h;
  const double W_1 = N * int_v1sq / c.r1_Ohm;
  const double dE_C = N * 0.5 * C1 * (v1_new * v1_new - v1_ * v1_);

  // Thermal network, exact with the step-mean loss and the fan heat held (5.).
  const double Qdot = (W_0 + W_1) / h;
  thermal_.step(h, Qdot, P_fan, in.air_T_K, fan_on, in.air_speed_m_s);
  const double T_new = thermal_.cellsT_K(), Q_air = thermal_.heatToAmbient_J();
  const double Q_vent = thermal_.ventilationHeat_J();

  // State update.
  soc_ -= i * h / Q_As_;
  v1_ = v1_new;
  T_ = T_new;
  if (!std::isfinite(T_) || T_ < p_.numerics.min_temperature_K || T_ > p_.numerics.max_temperature_K) {
    std::ostringstream os;
    os << T_ << " K outside [" << p_.numerics.min_temperature_K << ", " << p_.numerics.max_temperature_K << "] K";
    throw ModelDivergence("battery", "cell temperature", os.str());
  }
  if (!std::isfinite(soc_) || soc_ < -0.01 || soc_ > 1.01)
    throw ModelDivergence("battery", "state of charge", "left [-0.01, 1.01]");

  // Outputs.
  const double np = p_.pack.cells_in_parallel;
  out_.current_A = np * i;
  out_.terminal_voltage_V = p_.pack.cells_in_series * vt_mean;
  out_.power_W = W_t / h;
  out_.request_W = P;
  out_.unmet_power_W = limited ? P - out_.power_W : 0.0;
  out_.request_limited = limited;
  out_.ohmic_loss_W = W_0 / h;
  out_.rc_loss_W = W_1 / h;
  out_.loss_power_W = Qdot;
  out_.heat_to_air_W = Q_air / h;
  out_.ventilation_heat_W = Q_vent / h;
  out_.fan_on = fan_on;
  out_.fan_power_W = P_fan;
  out_.fan_energy_J += P_fan * h;
  if (fan_on) out_.fan_on_time_s += h;
  const PackConductances g = thermal_.conductances(fan_on, in.air_speed_m_s, in.air_T_K);
  out_.overall_conductance_W_K = g.overall_W_K;
  out_.ventilation_conductance_W_K = g.ventilation_W_K;
  out_.chemical_energy_J += W_ch;
  out_.terminal_energy_J += W_t;
  out_.ohmic_loss_J += W_0;
  out_.rc_loss_J += W_1;
  out_.loss_energy_J += W_0 + W_1;
  out_.heat_to_air_J += Q_air;
  out_.ventilation_heat_J += Q_vent;
  out_.rc_stored_energy_change_J += dE_C;
  out_.unmet_energy_J += out_.unmet_power_W * h;
  out_.charge_throughput_Ah += std::abs(out_.current_A) * h / 3600.0;
  if (limited) out_.limited_time_s += h;
  out_.time_s += h;
  updateStateOutputs();
}

}  // namespace hbt::battery
