#include "aftertreatment/node/aftertreatment_participant.hpp"
#include <boost/make_shared.hpp>

#include <hybrid_bus_twin/AftertreatmentState.h>

#include <algorithm>

#include "common/units.hpp"
#include "cosim/param_loader.hpp"

namespace hbt::aftertreatment {

void AftertreatmentParticipant::configure() {
  ParamSet ps;
  params_.declare(ps);
  cosim::applyRosParams(pnh_, ps, configFile());
  params_.validate(configFile());
  ambient_T_K_ = cosim::scenarioAmbient_K(nh_);
  ambient_p_Pa_ = cosim::scenarioAmbientPressure_Pa(nh_);  // tailpipe pressure
  model_ = std::make_unique<Aftertreatment>(params_);
  model_->reset(ambient_T_K_, ambient_p_Pa_);  // cold start at ambient
  clearAccumulator();
  exhaust_ = &addInput<hybrid_bus_twin::ExhaustState>("/engine/exhaust");
  vehicle_ = &addInput<hybrid_bus_twin::VehicleToCooling>("/vehicle/to_cooling");
  state_pub_ = addOutput<hybrid_bus_twin::AftertreatmentState>("/aftertreatment/state");
  below_light_off_ = &addWarning("ats_below_light_off", diagnosticsParams().aftertreatment.light_off_grace_s);
}

void AftertreatmentParticipant::checkWarnings(cosim::core::Nanos t) {
  const AtsOutputs& o = model_->outputs();
  if (below_light_off_->update(t, !o.light_off))
    below_light_off_->setMessage(cosim::core::formatText(
        "SCR not lit off for %.0f s: SCR brick %.1f degC (dosing from %.1f degC), filtered NOx "
        "conversion %.2f (light-off at %.2f)", diagnosticsParams().aftertreatment.light_off_grace_s,
        units::kToCelsius(o.brick_T_K[kSCR]), units::kToCelsius(params_.dosing_release_T_K),
        o.nox_conversion_filtered, params_.lightoff_conversion));
}

void AftertreatmentParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  const AtsOutputs& o = model_->outputs();
  const long n = model_->scr().solverSteps();
  kv.push_back({"cvode_steps_window", std::to_string(n - cvode_steps_at_status_)});
  kv.push_back({"cvode_steps_total", std::to_string(n)});
  cvode_steps_at_status_ = n;
  kv.push_back({"doc_temperature_c", formatNumber(units::kToCelsius(o.brick_T_K[kDOC]))});
  kv.push_back({"scr_temperature_c", formatNumber(units::kToCelsius(o.brick_T_K[kSCR]))});
  kv.push_back({"light_off", o.light_off ? "true" : "false"});
  kv.push_back({"nox_conversion_filtered", formatNumber(o.nox_conversion_filtered)});
  kv.push_back({"back_pressure_kpa", formatNumber(1e-3 * o.back_pressure_Pa)});
}

void AftertreatmentParticipant::clearAccumulator() {
  acc_t_ = acc_m_ = acc_mT_ = acc_nox_ = acc_hc_ = acc_co_ = 0.0;
  acc_yO2_ = acc_yCO2_ = acc_yH2O_ = acc_T_ = acc_v_ = acc_Tamb_ = 0.0;
}

void AftertreatmentParticipant::step(const ros::Time& t, double dt_s) {
  const auto& e = exhaust_->at(t);
  const auto& v = vehicle_->at(t);
  const double m = std::max(0.0, e.mass_flow_kg_s);
  acc_t_ += dt_s;
  acc_m_ += m * dt_s;
  acc_mT_ += m * e.temperature_k * dt_s;
  acc_T_ += e.temperature_k * dt_s;
  acc_yO2_ += m * e.y_o2 * dt_s;
  acc_yCO2_ += m * e.y_co2 * dt_s;
  acc_yH2O_ += m * e.y_h2o * dt_s;
  acc_nox_ += e.nox_mass_flow_kg_s * dt_s;
  acc_hc_ += e.hc_mass_flow_kg_s * dt_s;
  acc_co_ += e.co_mass_flow_kg_s * dt_s;
  acc_v_ += v.vehicle_speed_m_s * dt_s;
  acc_Tamb_ += (v.ambient_temperature_k > 0.0 ? v.ambient_temperature_k : ambient_T_K_) * dt_s;
  if (acc_t_ < params_.model_step_s - 1e-9) return;

  AtsInputs in;
  in.exhaust_mass_flow_kg_s = acc_m_ / acc_t_;
  if (acc_m_ > 0.0) {
    in.exhaust_T_K = acc_mT_ / acc_m_;
    in.comp.y_O2 = acc_yO2_ / acc_m_;
    in.comp.y_CO2 = acc_yCO2_ / acc_m_;
    in.comp.y_H2O = acc_yH2O_ / acc_m_;
  } else {
    in.exhaust_T_K = acc_T_ / acc_t_;  // no flow: the temperature does not matter
  }
  in.comp.y_N2 = 1.0 - in.comp.y_O2 - in.comp.y_CO2 - in.comp.y_H2O;
  in.nox_mass_flow_kg_s = std::max(0.0, acc_nox_ / acc_t_);
  in.hc_mass_flow_kg_s = std::max(0.0, acc_hc_ / acc_t_);
  in.co_mass_flow_kg_s = std::max(0.0, acc_co_ / acc_t_);
  in.vehicle_speed_m_s = std::max(0.0, acc_v_ / acc_t_);
  in.ambient_T_K = acc_Tamb_ / acc_t_;
  in.ambient_p_Pa = ambient_p_Pa_;
  model_->step(acc_t_, in);
  clearAccumulator();
}

void AftertreatmentParticipant::publishOutputs(const ros::Time& t) {
  const AtsOutputs& o = model_->outputs();
  const AtsEnergy& en = model_->energy();
  const AtsNitrogen& n = model_->nitrogen();
  const Brick& scr = model_->brick(kSCR);
  hybrid_bus_twin::AftertreatmentState s;
  s.header.stamp = t;
  s.back_pressure_pa = o.back_pressure_Pa;
  s.doc_temperature_k = o.brick_T_K[kDOC];
  s.dpf_temperature_k = o.brick_T_K[kDPF];
  s.scr_temperature_k = o.brick_T_K[kSCR];
  s.asc_temperature_k = o.brick_T_K[kASC];
  s.nox_conversion = o.nox_conversion;
  s.tailpipe_nox_mass_flow_kg_s = o.tailpipe_nox_kg_s;
  s.tailpipe_nox_mass_kg = o.tailpipe_nox_kg;
  s.urea_mass_flow_kg_s = o.adblue_kg_s;
  s.light_off = o.light_off;
  s.doc_outlet_temperature_k = o.brick_out_T_K[kDOC];
  s.dpf_outlet_temperature_k = o.brick_out_T_K[kDPF];
  s.scr_outlet_temperature_k = o.brick_out_T_K[kSCR];
  s.outlet_temperature_k = o.outlet_T_K;
  s.scr_inlet_slice_temperature_k = scr.T(0);
  s.scr_outlet_slice_temperature_k = scr.T(scr.slices() - 1);
  s.doc_dp_pa = o.brick_dp_Pa[kDOC];
  s.dpf_dp_pa = o.brick_dp_Pa[kDPF];
  s.scr_dp_pa = o.brick_dp_Pa[kSCR];
  s.asc_dp_pa = o.brick_dp_Pa[kASC];
  s.muffler_dp_pa = o.muffler_dp_Pa;
  s.nox_conversion_filtered = o.nox_conversion_filtered;
  s.doc_no2_fraction = o.doc_no2_fraction;
  s.engine_nox_mass_kg = o.engine_nox_kg;
  s.nh3_slip_mass_flow_kg_s = o.nh3_slip_kg_s;
  s.nh3_slip_mass_kg = o.nh3_slip_kg;
  s.urea_mass_kg = o.adblue_kg;
  s.anr = o.anr;
  s.nh3_stored_mol = o.nh3_stored_mol;
  s.light_off_time_s = o.light_off_time_s;
  s.enthalpy_in_j = en.enthalpy_in_J;
  s.enthalpy_out_j = en.enthalpy_out_J;
  s.can_loss_j = en.can_loss_J;
  s.reaction_heat_j = en.reaction_heat_J;
  s.stored_energy_change_j = en.stored_change_J;
  s.energy_residual_j = en.residual_J();
  s.nh3_dosed_mol = n.nh3_dosed_mol;
  s.nh3_reacted_mol = n.nh3_scr_reacted_mol;
  s.nh3_oxidised_mol = n.nh3_scr_oxidised_mol + n.nh3_asc_oxidised_mol;
  s.nh3_balance_residual_mol = n.residual_mol();
  state_pub_.publish(boost::make_shared<hybrid_bus_twin::AftertreatmentState>(s));
}

}  // namespace hbt::aftertreatment
