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
  if (cosim::scenarioWarmStart(nh_))  // a one-box mid-shift: warm_start/ of the config
    model_->resetWarm(params_.warm_brick_T_K, params_.warm_nh3_fill, ambient_p_Pa_);
  else
    model_->reset(ambient_T_K_, ambient_p_Pa_);  // cold start at ambient
  inputs_.reset();
  exhaust_ = &addInputFrom<hybrid_bus_twin::ExhaustState>("engine", "exhaust");
  vehicle_ = &addInputFrom<hybrid_bus_twin::VehicleToCooling>("vehicle", "to_cooling");
  state_pub_ = addOwnOutput<hybrid_bus_twin::AftertreatmentState>("state");
  readWarningThresholds(warnings_);
  below_light_off_ = &addWarning("ats_below_light_off", warnings_.light_off_grace_s);
}

void AftertreatmentParticipant::checkWarnings(cosim::core::Nanos t) {
  const AtsOutputs& o = model_->outputs();
  if (below_light_off_->update(t, !o.light_off))
    below_light_off_->setMessage(cosim::core::formatText(
        "SCR not lit off for %.0f s: SCR brick %.1f degC (dosing from %.1f degC), filtered NOx "
        "conversion %.2f (light-off at %.2f)", warnings_.light_off_grace_s,
        units::kToCelsius(o.brick_T_K[kSCR]), units::kToCelsius(params_.dosing_release_T_K),
        o.nox_conversion_filtered, params_.lightoff_conversion));
}

void AftertreatmentParticipant::diagnosticValues(cosim::core::Nanos, std::vector<cosim::core::KeyValue>& kv) {
  using cosim::core::formatNumber;
  const AtsOutputs& o = model_->outputs();
  const long n = model_->scr().solverSteps();
  kv.push_back({"scr_solver_steps_window", std::to_string(n - scr_steps_at_status_)});
  kv.push_back({"scr_solver_steps_total", std::to_string(n)});
  scr_steps_at_status_ = n;
  kv.push_back({"doc_temperature_c", formatNumber(units::kToCelsius(o.brick_T_K[kDOC]))});
  kv.push_back({"scr_temperature_c", formatNumber(units::kToCelsius(o.brick_T_K[kSCR]))});
  kv.push_back({"light_off", o.light_off ? "true" : "false"});
  kv.push_back({"nox_conversion_filtered", formatNumber(o.nox_conversion_filtered)});
  kv.push_back({"back_pressure_kpa", formatNumber(1e-3 * o.back_pressure_Pa)});
}

void AftertreatmentParticipant::step(const ros::Time& t, double dt_s) {
  const auto& e = exhaust_->at(t);
  const auto& v = vehicle_->at(t);
  InputTotals now;  // cumulative since t = 0 (step_inputs.hpp)
  now.exhaust_mass_kg = e.mass_kg;
  now.exhaust_mass_T_kg_K = e.mass_temperature_kg_k;
  now.exhaust_T_time_K_s = e.temperature_time_k_s;
  now.o2_kg = e.o2_mass_kg;
  now.co2_kg = e.co2_mass_kg;
  now.h2o_kg = e.h2o_mass_kg;
  now.nox_kg = e.nox_mass_kg;
  now.hc_kg = e.hc_mass_kg;
  now.co_kg = e.co_mass_kg;
  now.distance_m = v.distance_m;
  AtsInputs point;  // the sample's own values: the first step, no-flow composition, ambient
  point.exhaust_mass_flow_kg_s = e.mass_flow_kg_s;
  point.exhaust_T_K = e.temperature_k;
  point.comp.y_O2 = e.y_o2;
  point.comp.y_CO2 = e.y_co2;
  point.comp.y_H2O = e.y_h2o;
  point.nox_mass_flow_kg_s = e.nox_mass_flow_kg_s;
  point.hc_mass_flow_kg_s = e.hc_mass_flow_kg_s;
  point.co_mass_flow_kg_s = e.co_mass_flow_kg_s;
  point.vehicle_speed_m_s = v.vehicle_speed_m_s;
  point.ambient_T_K = v.ambient_temperature_k > 0.0 ? v.ambient_temperature_k : ambient_T_K_;
  point.ambient_p_Pa = ambient_p_Pa_;
  model_->step(dt_s, inputs_.next(now, point, dt_s));
}

void AftertreatmentParticipant::publishLineAndSoot(hybrid_bus_twin::AftertreatmentState& s) const {
  const AtsOutputs& o = model_->outputs();
  const ExhaustLine& up = model_->line(kLineUpstream);  // manifold .. box_inlet, in flow order
  s.manifold_temperature_k = up.T(0);
  s.turbine_housing_temperature_k = up.T(1);
  s.downpipe_temperature_k = up.T(2);
  s.rear_pipe_temperature_k = up.T(3);
  s.box_inlet_temperature_k = up.T(4);
  s.box_mixer_temperature_k = model_->line(kLineMixer).T(0);
  s.box_outlet_temperature_k = model_->line(kLineOutlet).T(0);
  s.doc_inlet_temperature_k = o.doc_inlet_T_K;
  s.scr_inlet_temperature_k = o.scr_inlet_T_K;
  const AtsSoot& soot = model_->soot();
  s.dpf_soot_mass_kg = o.soot_mass_kg;
  s.dpf_soot_load_g_l = o.soot_load_g_L;
  s.soot_engine_out_kg = soot.engine_out_kg;
  s.soot_burnt_kg = soot.burnt_kg;
  s.soot_balance_residual_kg = soot.residual_kg();
  s.dpf_no2_to_no_mol = soot.no2_to_no_mol;
  s.scr_inlet_no2_fraction = o.scr_inlet_no2_fraction;
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
  s.line_loss_j = en.line_loss_J;
  s.reaction_heat_j = en.reaction_heat_J;
  s.stored_energy_change_j = en.stored_change_J;
  s.energy_residual_j = en.residual_J();
  s.nh3_dosed_mol = n.nh3_dosed_mol;
  s.nh3_reacted_mol = n.nh3_scr_reacted_mol;
  s.nh3_oxidised_mol = n.nh3_scr_oxidised_mol + n.nh3_asc_oxidised_mol;
  s.nh3_balance_residual_mol = n.residual_mol();
  publishLineAndSoot(s);
  state_pub_.publish(boost::make_shared<hybrid_bus_twin::AftertreatmentState>(s));
}

}  // namespace hbt::aftertreatment
