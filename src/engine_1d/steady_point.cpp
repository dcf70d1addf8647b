#include "engine_1d/steady_point.hpp"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "common/units.hpp"

namespace hbt::engine_1d {
namespace {
double cpuNow() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

struct Sample { double torque, fuel, boost, turbo; };
}  // namespace

SteadyPointResult runSteadyPoint(Engine1D& eng, double rpm, double treq,
                                 const SteadyPointOptions& opt) {
  const double w = units::rpmToRadps(rpm), dt = opt.dt_s;
  Engine1DInputs in;
  in.speed_rad_s = w;
  in.torque_request_Nm = treq;
  in.ambient_T_K = opt.ambient_T_K;
  std::vector<Sample> hist;
  std::vector<Engine1DOutputs> outs;
  const double c0 = cpuNow();
  double t = 0.0;
  bool conv = false;
  const int lag = static_cast<int>(std::lround(0.2 / dt));
  while (t < opt.max_time_s - 1e-9) {
    const Engine1DOutputs& o = eng.step(dt, in);
    t += dt;
    hist.push_back({o.brake_torque_Nm, o.fuel_mass_flow_kg_s, o.boost_pressure_Pa,
                    o.turbo_speed_rad_s});
    outs.push_back(o);
    if (t < 1.0 || static_cast<int>(hist.size()) < 2 * lag) continue;
    auto avg = [&](int from) {
      Sample m{0, 0, 0, 0};
      for (int k = from; k < from + lag; ++k) {
        const Sample& h = hist[hist.size() - 2 * lag + k];
        m.torque += h.torque / lag, m.fuel += h.fuel / lag, m.boost += h.boost / lag,
            m.turbo += h.turbo / lag;
      }
      return m;
    };
    const Sample s0 = avg(0), s1 = avg(lag);
    auto rel = [](double x, double y) { return std::fabs(x - y) / std::max(std::fabs(y), 1e-12); };
    if (std::fabs(s1.torque - s0.torque) < std::max(0.003 * std::fabs(treq), 1.0) &&
        rel(s1.fuel, s0.fuel) < 0.003 && rel(s1.boost, s0.boost) < 0.005 &&
        rel(s1.turbo, s0.turbo) < 0.005 && std::fabs(s1.torque - treq) < std::max(0.01 * treq, 3.0)) {
      conv = true;
      break;
    }
  }
  SteadyPointResult r;
  r.cpu_s = cpuNow() - c0;
  r.sim_s = t;
  r.converged = conv;
  r.mean = outs.back();
  const int k0 = std::max(0, static_cast<int>(outs.size()) - lag);
  const int nk = static_cast<int>(outs.size()) - k0;
  for (double Engine1DOutputs::*f :
       {&Engine1DOutputs::brake_torque_Nm, &Engine1DOutputs::fuel_mass_flow_kg_s,
        &Engine1DOutputs::air_mass_flow_kg_s, &Engine1DOutputs::lambda,
        &Engine1DOutputs::boost_pressure_Pa, &Engine1DOutputs::intake_manifold_T_K,
        &Engine1DOutputs::turbine_inlet_p_Pa, &Engine1DOutputs::turbine_inlet_T_K,
        &Engine1DOutputs::turbo_speed_rad_s, &Engine1DOutputs::wastegate_opening,
        &Engine1DOutputs::nox_mass_flow_kg_s, &Engine1DOutputs::exhaust_T_K,
        &Engine1DOutputs::friction_torque_Nm}) {
    double s = 0;
    for (int k = k0; k < static_cast<int>(outs.size()); ++k) s += outs[k].*f;
    r.mean.*f = s / nk;
  }
  const double Tb = r.mean.brake_torque_Nm, fuel = r.mean.fuel_mass_flow_kg_s;
  r.fuel_ref_kg_s = eng.reference().steadyFuel(w, Tb);
  r.bsfc_g_kWh = fuel / (Tb * w) * 3.6e9;
  r.bsfc_ref_g_kWh = r.fuel_ref_kg_s / (Tb * w) * 3.6e9;
  r.bsfc_err_pct = 100.0 * (r.bsfc_g_kWh / r.bsfc_ref_g_kWh - 1.0);
  r.nox_g_kWh = r.mean.nox_mass_flow_kg_s / (Tb * w) * 3.6e9;
  return r;
}

bool BsfcValidationRegion::contains(double rpm, double load, std::string* reason) const {
  // 1e-9: grid points exactly on a limit (1100 rpm, 35 %) are inside.
  const bool slow = rpm < min_speed_rpm - 1e-9, light = load < min_load - 1e-9;
  if (reason) {
    char buf[256];
    if (slow)
      std::snprintf(buf, sizeof buf,
                    "below %.0f rpm: the map's low-speed corner needs eta_ind_gross ~0.34 (1D: 0.44)%s",
                    min_speed_rpm, light ? " and below the load limit" : "");
    else if (light)
      std::snprintf(buf, sizeof buf,
                    "below %.0f %% load: the map's fired losses are 35-45 %% of its own drag curve",
                    100.0 * min_load);
    else
      buf[0] = '\0';
    *reason = buf;
  }
  return !slow && !light;
}

}  // namespace hbt::engine_1d
