// engine_1d_steady: steady-state validation of the 1D engine against the reference (bench) map.
//
//   engine_1d_steady [--speeds 9] [--loads 21] [--points N] [--solver fsm|tvd] [--out DIR]
//                    [--max-time 8] [--inertia-factor 0.25] [--config config/engine_1d.yaml]
//                    [--speed-range lo hi] [--load-range lo hi] [--ambient-C 25] [--no-plot]
// Grid: `speeds` speeds evenly from 650 to 2450 rpm x `loads` loads evenly from 10 % to 100 % of
// the reference full-load torque at that speed (9 x 21 = 189 points). --points N keeps N points
// spread evenly over that grid (fast subsets for tests).
// Each point: runSteadyPoint (steady_point.hpp: speed imposed, torque requested through the
// PIDs, macro step 20 ms, run to periodic steady state; reported values: averages over the last
// 0.2 s) at ambient --ambient-C (default 25 C). Points are run in order of rising load at each speed and
// start from the previous point's state (reset only at a new speed). The steady state does not
// depend on the turbo inertia J, so J is multiplied by --inertia-factor (default 0.25) to shorten
// the spool-up; everything else is the transient model.
// BSFC statistics are printed for all points and for the validation region (config
// engine_1d/validation: >= 1100 rpm and >= 35 % load, where the reference map and its own drag
// curve agree); every point stays in the CSV with in_region (0/1) and region_note (the reason).
// Output: DIR/steady_points.csv (one row per point) and, via plot_steady.py, contour PNGs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "engine_1d/engine_1d.hpp"
#include "engine_1d/steady_point.hpp"

using namespace hbt::engine_1d;

namespace {

struct Args {
  int speeds = 9, loads = 21, points = 0;
  std::string solver, out = "engine_1d_steady_out", config = "config/engine_1d.yaml", root;
  double max_time = 8.0, inertia_factor = 0.25, n_lo = 650.0, n_hi = 2450.0;
  double load_lo = 0.10, load_hi = 1.0, ambient_C = 25.0;
  bool plot = true;
};

Args parse(int argc, char** argv) {
  Args a;
  const char* env = std::getenv("HBT_SOURCE_DIR");
  a.root = env ? env : ".";
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    auto val = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "missing value for %s\n", k.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (k == "--speeds") a.speeds = std::stoi(val());
    else if (k == "--loads") a.loads = std::stoi(val());
    else if (k == "--points") a.points = std::stoi(val());
    else if (k == "--solver") a.solver = val();
    else if (k == "--out") a.out = val();
    else if (k == "--config") a.config = val();
    else if (k == "--root") a.root = val();
    else if (k == "--max-time") a.max_time = std::stod(val());
    else if (k == "--inertia-factor") a.inertia_factor = std::stod(val());
    else if (k == "--speed-range") { a.n_lo = std::stod(val()); a.n_hi = std::stod(val()); }
    else if (k == "--load-range") { a.load_lo = std::stod(val()); a.load_hi = std::stod(val()); }
    else if (k == "--ambient-C") a.ambient_C = std::stod(val());
    else if (k == "--no-plot") a.plot = false;
    else {
      std::fprintf(stderr,
                   "usage: engine_1d_steady [--speeds N] [--loads M] [--points N] [--solver fsm|tvd]"
                   " [--out DIR] [--max-time s] [--inertia-factor f] [--speed-range lo hi]"
                   " [--load-range lo hi] [--ambient-C 25] [--config file] [--root dir] [--no-plot]\n");
      std::exit(2);
    }
  }
  return a;
}

// One operating point of the grid: speed and load indices, speed [rpm], load [-].
struct Pt { int is, il; double rpm, load; };

// speeds x loads evenly over the ranges; --points N keeps N points spread evenly over it.
std::vector<Pt> buildGrid(const Args& a) {
  std::vector<Pt> grid;
  for (int i = 0; i < a.speeds; ++i)
    for (int j = 0; j < a.loads; ++j) {
      const double rpm = a.speeds > 1 ? a.n_lo + (a.n_hi - a.n_lo) * i / (a.speeds - 1) : a.n_lo;
      const double ld = a.loads > 1 ? a.load_lo + (a.load_hi - a.load_lo) * j / (a.loads - 1) : a.load_hi;
      grid.push_back({i, j, rpm, ld});
    }
  if (a.points > 0 && a.points < static_cast<int>(grid.size())) {
    std::vector<Pt> sub;
    for (int k = 0; k < a.points; ++k)
      sub.push_back(grid[static_cast<std::size_t>(std::lround((grid.size() - 1.0) * k / std::max(1, a.points - 1)))]);
    grid = sub;
  }
  return grid;
}

// BSFC error statistics over the points run [%] and the cost.
struct Totals {
  int n_conv = 0, n_reg = 0;
  double sum_abs = 0, max_abs = 0, cpu_all = 0, sim_all = 0, sum_reg = 0, max_reg = 0;
};

void writeCsvHeader(std::ofstream& csv) {
  csv << "speed_rpm,load,torque_req_Nm,torque_Nm,bsfc_g_kWh,bsfc_ref_g_kWh,bsfc_err_pct,"
         "fuel_kg_s,fuel_ref_kg_s,air_kg_s,lambda,boost_Pa,boost_target_Pa,T_im_K,p3_Pa,T3_K,"
         "pmax_bar,turbo_krpm,wastegate,nox_g_kWh,exhaust_T_K,back_pressure_Pa,smoke_limited,"
         "converged,sim_s,cpu_s,imep_gross_bar,pmep_bar,fmep_bar,eta_ind_gross,ca50_deg,"
         "ignition_delay_deg,ambient_T_K,in_region,region_note\n";
}

// One point: run to steady state, add it to the totals, write its CSV row and its line.
void runPoint(Engine1D& eng, const Pt& q, double w, double treq, const SteadyPointOptions& opt,
              const BsfcValidationRegion& region, std::ofstream& csv, Totals& tot) {
  const SteadyPointResult sp = runSteadyPoint(eng, q.rpm, treq, opt);
  const Engine1DOutputs* o = &sp.mean;
  const bool conv = sp.converged;
  const double t = sp.sim_s, cpu = sp.cpu_s;
  tot.cpu_all += cpu;
  tot.sim_all += t;
  const double Tb = o->brake_torque_Nm, fuel = o->fuel_mass_flow_kg_s;
  const double fref = sp.fuel_ref_kg_s, bsfc = sp.bsfc_g_kWh, bref = sp.bsfc_ref_g_kWh;
  const double err = sp.bsfc_err_pct;
  std::string reason;
  const bool in_region = region.contains(q.rpm, q.load, &reason);
  tot.n_conv += conv;
  tot.sum_abs += std::fabs(err);
  tot.max_abs = std::max(tot.max_abs, std::fabs(err));
  if (in_region) {
    ++tot.n_reg;
    tot.sum_reg += std::fabs(err);
    tot.max_reg = std::max(tot.max_reg, std::fabs(err));
  }
  // Loss split and combustion phasing: mean over the cylinders' last complete cycles.
  double imep_g = 0, pmep = 0, eta_g = 0, ca50 = 0, delay = 0;
  const int ncyl = eng.assembly().cylinders();
  for (int c = 0; c < ncyl; ++c) {
    const auto& r = eng.assembly().cylinder(c).lastCycle();
    imep_g += r.imep_gross_Pa / ncyl, pmep += r.pmep_Pa / ncyl, eta_g += r.eta_ind_gross / ncyl;
    ca50 += r.ca50_deg / ncyl, delay += r.ignition_delay_main_deg / ncyl;
  }
  const double Vd_m3 = eng.assembly().displacement_m3();
  const double fmep = o->friction_torque_Nm * 4.0 * hbt::units::kPi / Vd_m3;
  csv << q.rpm << "," << q.load << "," << treq << "," << Tb << "," << bsfc << "," << bref << ","
      << err << "," << fuel << "," << fref << "," << o->air_mass_flow_kg_s << "," << o->lambda
      << "," << o->boost_pressure_Pa << "," << o->boost_target_Pa << ","
      << o->intake_manifold_T_K << "," << o->turbine_inlet_p_Pa << "," << o->turbine_inlet_T_K
      << "," << o->peak_cylinder_pressure_Pa / 1e5 << "," << hbt::units::radpsToRpm(o->turbo_speed_rad_s) / 1e3
      << "," << o->wastegate_opening << "," << o->nox_mass_flow_kg_s / (Tb * w) * 3.6e9 << ","
      << o->exhaust_T_K << "," << o->back_pressure_Pa << "," << o->smoke_limited << ","
      << conv << "," << t << "," << cpu << "," << imep_g / 1e5 << "," << pmep / 1e5 << ","
      << fmep / 1e5 << "," << eta_g << "," << ca50 << "," << delay << "," << opt.ambient_T_K << "," << in_region
      << ",\"" << reason << "\"\n";
  csv.flush();
  std::printf("%6.0f rpm %5.0f Nm (%3.0f%%): Tb %6.1f BSFC %6.1f ref %6.1f err %+5.1f%% lambda %4.2f "
              "boost %4.2f bar pmax %5.1f bar NOx %5.2f g/kWh %s %.1f s cpu %.2f s%s\n",
              q.rpm, treq, 100 * q.load, Tb, bsfc, bref, err, o->lambda, o->boost_pressure_Pa / 1e5,
              o->peak_cylinder_pressure_Pa / 1e5, o->nox_mass_flow_kg_s / (Tb * w) * 3.6e9,
              conv ? "conv" : "NOT-CONVERGED", t, cpu, in_region ? "" : " (outside region)");
  std::fflush(stdout);
}

void printSummary(const Args& a, const std::string& solver, int n, const Totals& tot,
                  const BsfcValidationRegion& region) {
  std::printf("\n%d points (%d converged), solver %s, ambient %.1f C: all points: BSFC error mean "
              "|e| = %.2f %%, max |e| = %.2f %%; CPU %.1f s for %.1f s simulated (%.3f)\n",
              n, tot.n_conv, solver.c_str(), a.ambient_C, tot.sum_abs / n, tot.max_abs, tot.cpu_all,
              tot.sim_all, tot.cpu_all / tot.sim_all);
  if (tot.n_reg > 0)
    std::printf("validation region (>= %.0f rpm, >= %.0f %% load; %d points): BSFC error mean |e| = "
                "%.2f %%, max |e| = %.2f %% (targets 3 %% / 8 %%)\n",
                region.min_speed_rpm, 100.0 * region.min_load, tot.n_reg, tot.sum_reg / tot.n_reg, tot.max_reg);
  else
    std::printf("validation region (>= %.0f rpm, >= %.0f %% load): no point of this grid\n",
                region.min_speed_rpm, 100.0 * region.min_load);
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = parse(argc, argv);
  try {
    Engine1DParams p = Engine1DParams::load(a.root, a.config);
    if (!a.solver.empty()) p.engine.solver = a.solver;
    p.turbo.shaft.inertia_kg_m2 *= a.inertia_factor;
    Engine1D eng(p, a.root);
    const std::vector<Pt> grid = buildGrid(a);
    std::string cmd = "mkdir -p '" + a.out + "'";
    if (std::system(cmd.c_str()) != 0) throw std::runtime_error("cannot create " + a.out);
    std::ofstream csv(a.out + "/steady_points.csv");
    writeCsvHeader(csv);
    const BsfcValidationRegion region{p.engine.validation_min_speed_rpm, p.engine.validation_min_load};
    SteadyPointOptions opt;
    opt.max_time_s = a.max_time;
    opt.ambient_T_K = 273.15 + a.ambient_C;
    int last_speed = -1;
    Totals tot;
    for (const Pt& q : grid) {
      const double w = hbt::units::rpmToRadps(q.rpm), treq = q.load * eng.fullLoadTorque(w);
      if (q.is != last_speed) eng.reset(w, treq, opt.ambient_T_K);
      last_speed = q.is;
      runPoint(eng, q, w, treq, opt, region, csv, tot);
    }
    printSummary(a, p.engine.solver, static_cast<int>(grid.size()), tot, region);
    if (a.plot) {
      std::fflush(stdout);
      const std::string py = "/usr/bin/python3 '" + a.root + "/src/engine_1d/tools/plot_steady.py' '" +
                             a.out + "/steady_points.csv' '" + a.out + "'";
      if (std::system(py.c_str()) != 0) std::fprintf(stderr, "plot_steady.py failed\n");
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "engine_1d_steady: %s\n", e.what());
    return 1;
  }
  return 0;
}
