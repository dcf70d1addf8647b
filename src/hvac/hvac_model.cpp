#include "hvac/hvac_model.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace hbt::hvac {

HvacModel::HvacModel(const HvacParams& p, double payload_kg, const std::string& file)
    : p_((p.validate(file), p)),
      file_(file),
      cabin_(p_.cabin, p_.doors, p_.air),
      gains_(p_.gains, p_.cabin, payload_kg, file),
      controller_(p_.controller),
      heater_(p_.aux_heater),
      ac_(p_.ac) {
  reset(units::celsiusToK(20.0));
}

void HvacModel::reset(double cabin_T_K) {
  cabin_.reset(cabin_T_K);
  heater_.reset();
  T0_K_ = cabin_T_K;
  out_ = HvacOutputs{};
  out_.cabin_T_K = cabin_T_K;
}

double HvacModel::inServiceCabin_K(double T_a) const {
  return std::clamp(T_a, p_.controller.heating_setpoint_K, p_.controller.cooling_setpoint_K);
}

void HvacModel::checkInputs(double dt_s, const HvacInputs& in) const {
  const char* where = "hvac step input";
  if (!(dt_s > 0.0) || !std::isfinite(dt_s)) throw InputError(where, "dt", "must be > 0");
  auto chk = [&](double v, const char* key) {
    if (!std::isfinite(v)) throw InputError(where, key, "not finite");
  };
  chk(in.ambient_T_K, "ambient_T_K");
  chk(in.ambient_p_Pa, "ambient_p_Pa");
  chk(in.heater_water_T_K, "heater_water_T_K");
  chk(in.coolant_heat_W, "coolant_heat_W");
  chk(in.vehicle_speed_m_s, "vehicle_speed_m_s");
  if (!(in.ambient_T_K > 200.0 && in.ambient_T_K < 350.0))
    throw InputError(where, "ambient_T_K", "outside [200, 350] K");
  if (!(in.ambient_p_Pa > 2e4 && in.ambient_p_Pa < 2e5))
    throw InputError(where, "ambient_p_Pa", "outside [2e4, 2e5] Pa");
}

void HvacModel::step(double dt_s, const HvacInputs& in) {
  checkInputs(dt_s, in);
  // 1. gains and doors
  const double T = cabin_.temperature_K(), T_a = in.ambient_T_K;
  CabinInputs ci;
  ci.ambient_T_K = T_a;
  ci.ambient_p_Pa = in.ambient_p_Pa;
  ci.doors_open = std::fabs(in.vehicle_speed_m_s) < p_.doors.open_below_speed_m_s;
  out_.people_W = gains_.people_W(T_a);
  out_.solar_W = gains_.solar_W(T_a);
  ci.gain_W = out_.people_W + out_.solar_W;
  // 2. the controller's demand
  const ClimateDemand d = controller_.demand(T, T_a, cabin_.conductance(ci, T).total(), ci.gain_W);
  // 3. auxiliary heater, 4. A/C
  const AuxHeaterState& h = heater_.step(dt_s, in.heater_water_T_K, d.heating_W > 0.0);
  const AcOperation ac = ac_.operate(d.cooling_W, T_a, in.engine_running);
  // 5. the cabin with the convectors' delivered heat and the A/C's cooling
  ci.heat_W = std::max(0.0, in.coolant_heat_W);
  ci.cool_W = ac.cooling_W;
  const CabinFlows f = cabin_.step(dt_s, ci);
  if (!std::isfinite(cabin_.temperature_K()) || cabin_.temperature_K() < 200.0 || cabin_.temperature_K() > 400.0)
    throw ModelDivergence("hvac", "cabin temperature", "= " + std::to_string(cabin_.temperature_K()) +
                                                           " K outside [200, 400] K");
  out_.engine_run_request =
      d.cooling_W > 0.0 && cabin_.temperature_K() > p_.controller.cooling_setpoint_K + p_.controller.engine_run_above_K;
  out_.heating_demand_W = d.heating_W;
  out_.cooling_demand_W = d.cooling_W;
  out_.doors_open = ci.doors_open;
  out_.coolant_heat_W = ci.heat_W;
  book(dt_s, f, h, ac);
}

// Bookkeeping of the step: the flows of the exact update and the machines' energies.
void HvacModel::book(double h, const CabinFlows& f, const AuxHeaterState& hs, const AcOperation& ac) {
  HvacOutputs& o = out_;
  o.time_s += h;
  o.cabin_T_K = cabin_.temperature_K();
  o.aux_heater_on = hs.on;
  o.aux_heater_heat_W = hs.heat_W;
  o.aux_heater_fuel_kg_s = hs.fuel_kg_s;
  o.aux_heater_heat_J = hs.heat_J;
  o.aux_heater_fuel_kg = hs.fuel_kg;
  o.ac_cooling_W = ac.cooling_W;
  o.compressor_power_W = ac.shaft_W;
  o.cop = ac.cop;
  o.electric_power_W = ac.electric_W + hs.electric_W;
  o.body_W = f.body_W;
  o.fresh_air_W = f.fresh_air_W;
  o.doors_W = f.doors_W;
  o.coolant_heat_J += o.coolant_heat_W * h;
  o.people_J += o.people_W * h;
  o.solar_J += o.solar_W * h;
  o.ac_cooling_J += ac.cooling_W * h;
  o.body_J += f.body_W * h;
  o.fresh_air_J += f.fresh_air_W * h;
  o.doors_J += f.doors_W * h;
  o.compressor_energy_J += ac.shaft_W * h;
  o.electric_energy_J += o.electric_power_W * h;
  o.stored_change_J = cabin_.heatCapacity_J_K() * (o.cabin_T_K - T0_K_);
  o.energy_residual_J = o.coolant_heat_J + o.people_J + o.solar_J - o.ac_cooling_J - o.body_J - o.fresh_air_J -
                        o.doors_J - o.stored_change_J;
}

}  // namespace hbt::hvac
