// engine_1d_whtc: the WHTC on the 1D engine (speed imposed, torque requested through the PIDs).
//
//   engine_1d_whtc [--duration 1800] [--solver fsm|tvd] [--dt 0.01] [--out DIR] [--no-plot]
//   engine_1d_whtc --bench [--duration 300]     (FSM and TVD on the same trace: CPU cost, fuel)
//   --limiters: tally which element sets the coupled step (sampled after every macro step)
// Denormalisation per UN GTR No. 4 with the engine's own (reference) full-load and motoring curves
// (whtc.hpp); n_idle = 700 rpm x f_n (VECTO bus engine idle, speed-scaled like the map).
// Between the 1 Hz cycle points the reference speed and torque are interpolated linearly; the
// torque request is T_ref (motoring points: T_mot -> fuel cut). Actual values are the 1D engine's
// one-cycle mean brake torque sampled at every second. Cumulative fuel is compared with the
// reference map integrated along the same trace: F_ref(w, T_b,actual) (and, printed too,
// along the reference torque).
// Also printed: the map engine's NOx (config engine_map.yaml nox_map_file x its fuel) along the
// actual trace, for the 1D-vs-map NOx check.
// Output: DIR/whtc_1hz.csv, regression statistics vs the GTR criteria, and plot_whtc.py PNGs.
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "engine_1d/engine_1d.hpp"
#include "engine_1d/whtc.hpp"

using namespace hbt::engine_1d;

namespace {
struct Args {
  double duration = 1800.0, dt = 0.01;
  std::string solver, out = "engine_1d_whtc_out", config = "config/engine_1d.yaml", root;
  bool bench = false, plot = true, limiters = false;
};

struct Result {
  double fuel_1d = 0, fuel_map_act = 0, nox_map_act = 0, fuel_map_ref = 0, cpu = 0, sim = 0, work_act = 0,
         work_ref = 0, nox = 0;
  long steps = 0;
  Regression torque, speed, power, torque_pos;
};

Args parse(int argc, char** argv) {
  Args a;
  const char* env = std::getenv("HBT_SOURCE_DIR");
  a.root = env ? env : ".";
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    auto val = [&]() -> std::string {
      if (i + 1 >= argc) { std::fprintf(stderr, "missing value for %s\n", k.c_str()); std::exit(2); }
      return argv[++i];
    };
    if (k == "--duration") a.duration = std::stod(val());
    else if (k == "--solver") a.solver = val();
    else if (k == "--dt") a.dt = std::stod(val());
    else if (k == "--out") a.out = val();
    else if (k == "--config") a.config = val();
    else if (k == "--root") a.root = val();
    else if (k == "--bench") a.bench = true;
    else if (k == "--no-plot") a.plot = false;
    else if (k == "--limiters") a.limiters = true;
    else {
      std::fprintf(stderr, "usage: engine_1d_whtc [--duration s] [--solver fsm|tvd] [--dt s] "
                           "[--bench] [--out DIR] [--config file] [--root dir] [--no-plot] [--limiters]\n");
      std::exit(2);
    }
  }
  return a;
}

Result runCycle(const Args& a, const std::string& solver, const std::string& csv_path, bool print) {
  Engine1DParams p = Engine1DParams::load(a.root, a.config);
  if (!solver.empty()) p.engine.solver = solver;
  Engine1D eng(p, a.root);
  const auto& ref = eng.reference();
  // The engine's own reference map engine runs without the NOx map (it is derived from this
  // engine); the map engine of the missions (config engine_map.yaml) loads it.
  const hbt::engine_map::MapEngine nox_ref(p.reference, a.root);
  auto fl = [&](double rpm) { return ref.fullLoadTorque(hbt::units::rpmToRadps(rpm)); };
  auto mot = [&](double rpm) { return ref.motoringTorque(hbt::units::rpmToRadps(rpm)); };
  const double n_idle = 700.0 * ref.scaling().speed_factor;
  const double n_max = hbt::units::radpsToRpm(ref.fullLoadCurve().speed_rad_s.back());
  const GtrReferenceSpeeds s = gtrReferenceSpeeds(fl, n_idle, n_max);
  const auto cyc = denormaliseWhtc(a.root + "/config/data/cycles/WHTC_normalized_1Hz.csv", s, fl, mot);
  if (print)
    std::printf("GTR No.4 reference speeds: n_idle %.1f, n_lo %.1f, n_pref %.1f, n_95h %.1f, n_hi %.1f rpm;"
                " P_max %.1f kW at %.0f rpm\n", s.n_idle, s.n_lo, s.n_pref, s.n_95h, s.n_hi,
                s.p_max_W / 1e3, s.n_pmax);
  std::ofstream csv(csv_path);
  csv << "t_s,speed_rpm,torque_ref_Nm,torque_Nm,power_ref_kW,power_kW,fuel_g_s,fuel_cum_g,"
         "fuel_map_cum_g,fuel_map_ref_cum_g,boost_bar,boost_target_bar,turbo_krpm,wastegate,lambda,"
         "nox_cum_g,exhaust_T_K,exhaust_kg_s,smoke_limited,fuel_cut,cpu_s\n";
  // reference at time t: cycle point k at t = k (t = 0 -> first row)
  auto at = [&](double t, double& n, double& T) {
    const double x = std::clamp(t, 0.0, static_cast<double>(cyc.size() - 1));
    const std::size_t i = std::min(static_cast<std::size_t>(x), cyc.size() - 2);
    const double f = x - i;
    n = (1 - f) * cyc[i].n_rpm + f * cyc[i + 1].n_rpm;
    T = (1 - f) * cyc[i].torque_Nm + f * cyc[i + 1].torque_Nm;
  };
  double n0, T0;
  at(0.0, n0, T0);
  eng.reset(hbt::units::rpmToRadps(n0), T0, 298.15);
  Result r;
  std::vector<double> xr, yr, xn, yn, xp, yp, xq, yq;
  const double dur = std::min(a.duration, static_cast<double>(cyc.size() - 1));
  const int steps = static_cast<int>(std::lround(dur / a.dt));
  const int per_s = static_cast<int>(std::lround(1.0 / a.dt));
  Engine1DInputs in;
  std::map<std::string, long> limiter_count;  // --limiters: what sets the coupled step
  double limiter_dt_sum = 0.0;
  for (int k = 1; k <= steps; ++k) {
    const double t = k * a.dt;
    double n, T;
    at(t - 0.5 * a.dt, n, T);  // request over the step: mid-step reference
    in.speed_rad_s = hbt::units::rpmToRadps(n);
    in.torque_request_Nm = T;
    const Engine1DOutputs& o = eng.step(a.dt, in);
    const double w = in.speed_rad_s;
    if (a.limiters) {  // sampled once per macro step, outside the model's CPU time
      std::string who;
      limiter_dt_sum += eng.assembly().stableDt(w, &who);
      ++limiter_count[who];
    }
    r.fuel_map_act += ref.steadyFuel(w, o.brake_torque_Nm) * a.dt;
    r.nox_map_act += nox_ref.noxEmissionIndex(w, o.brake_torque_Nm) * nox_ref.steadyFuel(w, o.brake_torque_Nm) * a.dt;
    r.fuel_map_ref += ref.steadyFuel(w, T) * a.dt;
    r.work_act += std::max(o.brake_torque_Nm, 0.0) * w * a.dt;
    r.work_ref += std::max(T, 0.0) * w * a.dt;
    if (k % per_s == 0) {
      double nr, Tr;
      at(t, nr, Tr);
      xr.push_back(Tr), yr.push_back(o.brake_torque_Nm);
      xn.push_back(nr), yn.push_back(n);
      xp.push_back(Tr * nr * hbt::units::kRadps_per_rpm), yp.push_back(o.brake_torque_Nm * n * hbt::units::kRadps_per_rpm);
      if (Tr > 0.0) xq.push_back(Tr), yq.push_back(o.brake_torque_Nm);
      csv << t << "," << nr << "," << Tr << "," << o.brake_torque_Nm << "," << Tr * nr * hbt::units::kRadps_per_rpm / 1e3
          << "," << o.brake_torque_Nm * n * hbt::units::kRadps_per_rpm / 1e3 << "," << o.fuel_mass_flow_kg_s * 1e3 << ","
          << o.fuel_mass_kg * 1e3 << "," << r.fuel_map_act * 1e3 << "," << r.fuel_map_ref * 1e3 << ","
          << o.boost_pressure_Pa / 1e5 << "," << o.boost_target_Pa / 1e5 << ","
          << hbt::units::radpsToRpm(o.turbo_speed_rad_s) / 1e3 << "," << o.wastegate_opening << "," << o.lambda << ","
          << o.nox_mass_kg * 1e3 << "," << o.exhaust_T_K << "," << o.exhaust_mass_flow_kg_s << ","
          << o.smoke_limited << "," << o.fuel_cut << "," << o.cpu_time_total_s << "\n";
      if (print && k % (per_s * 100) == 0) {
        std::printf("t %6.0f s  fuel 1D %8.1f g  map %8.1f g (%+5.2f %%)  cpu/sim %.4f\n", t,
                    o.fuel_mass_kg * 1e3, r.fuel_map_act * 1e3,
                    100.0 * (o.fuel_mass_kg / r.fuel_map_act - 1.0), o.cpu_time_total_s / t);
        std::fflush(stdout);
      }
    }
    r.fuel_1d = o.fuel_mass_kg;
    r.cpu = o.cpu_time_total_s;
    r.sim = o.sim_time_s;
    r.nox = o.nox_mass_kg;
    r.steps = o.gas_steps;
  }
  if (a.limiters) {
    std::vector<std::pair<long, std::string>> v;
    for (const auto& [name, n] : limiter_count) v.push_back({n, name});
    std::sort(v.rbegin(), v.rend());
    std::printf("step limiters (sampled after each macro step, %d samples, mean stable step %.3f ms):\n",
                steps, 1e3 * limiter_dt_sum / steps);
    for (const auto& [n, name] : v) std::printf("  %-32s %6.2f %%\n", name.c_str(), 100.0 * n / steps);
  }
  r.torque = regress(xr, yr);
  r.torque_pos = regress(xq, yq);
  r.speed = regress(xn, yn);
  r.power = regress(xp, yp);
  return r;
}

void report(const Result& r, double tmax, double nmax, double pmax) {
  auto line = [](const char* name, const Regression& g, const RegressionLimits& L) {
    std::printf("  %-22s slope %.4f [%.2f, %.2f]  intercept %+8.2f [+-%.1f]  r2 %.4f [>= %.3f]  "
                "SEE %8.2f [<= %.1f]  -> %s\n", name, g.slope, L.slope_lo, L.slope_hi, g.intercept,
                L.intercept_max, g.r2, L.r2_min, g.see, L.see_max, L.pass(g) ? "PASS" : "FAIL");
  };
  std::printf("GTR No.4 regression (1 Hz, %d points):\n", r.torque.n);
  line("torque [Nm]", r.torque, torqueLimits(tmax));
  line("torque, T_ref>0 only", r.torque_pos, torqueLimits(tmax));
  line("speed [rpm]", r.speed, speedLimits(nmax));
  line("power [W]", r.power, powerLimits(pmax));
  std::printf("cycle work: actual %.3f kWh, reference %.3f kWh (%.1f %%)\n", r.work_act / 3.6e6,
              r.work_ref / 3.6e6, 100.0 * r.work_act / r.work_ref);
  std::printf("cumulative fuel: 1D %.1f g, map along actual trace %.1f g -> error %+.2f %% "
              "(target |e| <= 2 %%); map along reference trace %.1f g (%+.2f %%)\n",
              r.fuel_1d * 1e3, r.fuel_map_act * 1e3, 100.0 * (r.fuel_1d / r.fuel_map_act - 1.0),
              r.fuel_map_ref * 1e3, 100.0 * (r.fuel_1d / r.fuel_map_ref - 1.0));
  std::printf("engine-out NOx %.1f g = %.2f g/kWh; CPU %.2f s for %.1f s simulated: CPU/sim = %.4f, "
              "%ld coupled steps (%.2f us/step)\n", r.nox * 1e3, r.nox * 1e3 / (r.work_act / 3.6e6),
              r.cpu, r.sim, r.cpu / r.sim, r.steps, 1e6 * r.cpu / std::max(r.steps, 1L));
  std::printf("map engine NOx along the actual trace (its nox_map_file x its fuel): %.1f g = %.2f g/kWh "
              "(1D vs map engine %+.1f %%)\n", r.nox_map_act * 1e3, r.nox_map_act * 1e3 / (r.work_act / 3.6e6),
              100.0 * (r.nox / r.nox_map_act - 1.0));
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = parse(argc, argv);
  try {
    if (std::system(("mkdir -p '" + a.out + "'").c_str()) != 0) throw std::runtime_error("mkdir");
    Engine1DParams p = Engine1DParams::load(a.root, a.config);
    hbt::engine_map::MapEngine ref(p.reference, a.root);
    double pw;
    const double pmax = ref.peakPower(&pw), tmax = ref.peakTorque();
    const double nmax = hbt::units::radpsToRpm(ref.fullLoadCurve().speed_rad_s.back());
    if (!a.bench) {
      const Result r = runCycle(a, a.solver, a.out + "/whtc_1hz.csv", true);
      report(r, tmax, nmax, pmax);
      if (a.plot) {
        std::fflush(stdout);
        const std::string py = "/usr/bin/python3 '" + a.root + "/src/engine_1d/tools/plot_whtc.py' '" +
                               a.out + "/whtc_1hz.csv' '" + a.out + "'";
        if (std::system(py.c_str()) != 0) std::fprintf(stderr, "plot_whtc.py failed\n");
      }
      return 0;
    }
    std::printf("benchmark: WHTC %.0f s, FSM then TVD (fine mesh x%.1f)\n", a.duration,
                p.engine.tvd_mesh_factor);
    const Result f = runCycle(a, "fsm", a.out + "/whtc_fsm_1hz.csv", false);
    std::printf("FSM:\n");
    report(f, tmax, nmax, pmax);
    const Result t = runCycle(a, "tvd", a.out + "/whtc_tvd_1hz.csv", false);
    std::printf("TVD:\n");
    report(t, tmax, nmax, pmax);
    std::printf("\nBENCH: FSM CPU/sim %.4f (target <= 0.03), TVD CPU/sim %.4f, FSM/TVD cost %.1f %% "
                "(target <= 15 %%), cumulative fuel FSM %.2f g vs TVD %.2f g: %+.2f %% (target 1 %%)\n",
                f.cpu / f.sim, t.cpu / t.sim, 100.0 * f.cpu / t.cpu, f.fuel_1d * 1e3, t.fuel_1d * 1e3,
                100.0 * (f.fuel_1d / t.fuel_1d - 1.0));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "engine_1d_whtc: %s\n", e.what());
    return 1;
  }
  return 0;
}
