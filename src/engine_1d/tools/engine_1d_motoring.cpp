// engine_1d_motoring: motoring-curve check of the 1D engine (calibration of friction/pumping).
//
//   engine_1d_motoring [--speeds 9] [--speed-range 650 2450] [--time 1.5] [--config file]
//                      [--root dir] [--out file.csv]
//   engine_1d_motoring --fired RPM LOAD [RPM LOAD ...] [--time 3] [--config file] [--root dir]
// Each speed: fuel disabled (fuel cut), speed imposed, run `time` seconds from a motored reset;
// reported values are averages of the one-cycle means over the last 0.2 s: brake torque
// (= net indicated torque - Chen-Flynn friction), its split, FMEP/PMEP [bar], p_max, boost and
// turbine-inlet pressure, against the reference (VECTO, scaled) motoring curve.
// Summary: mean |T_b - T_mot,ref| and mean ratio T_b / T_mot,ref.
// --fired: diagnostic of fired points (load = fraction of the reference full-load torque), run
// `time` s each from a reset: brake BSFC vs map, and cylinder 1's last cycle (IMEP gross/net,
// PMEP, FMEP, p_max and its angle, SOC, ignition delay, CA10/50/90, wall heat and burned fuel
// fractions, gross indicated efficiency, lambda) for the combustion/heat-loss calibration.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "common/units.hpp"
#include "engine_1d/engine_1d.hpp"

using namespace hbt::engine_1d;

namespace {

struct Args {
  int speeds = 9;
  double n_lo = 650.0, n_hi = 2450.0, sim = 1.5;  // speed range [rpm], run time per point [s]
  std::string config = "config/engine_1d.yaml", out, root;
  std::vector<double> fired;  // rpm, load pairs
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
    if (k == "--speeds") a.speeds = std::stoi(val());
    else if (k == "--speed-range") { a.n_lo = std::stod(val()); a.n_hi = std::stod(val()); }
    else if (k == "--time") a.sim = std::stod(val());
    else if (k == "--config") a.config = val();
    else if (k == "--root") a.root = val();
    else if (k == "--out") a.out = val();
    else if (k == "--fired") {
      while (i + 2 < argc && argv[i + 1][0] != '-') {
        a.fired.push_back(std::stod(argv[++i]));
        a.fired.push_back(std::stod(argv[++i]));
      }
    }
    else {
      std::fprintf(stderr, "usage: engine_1d_motoring [--speeds N] [--speed-range lo hi] [--time s]"
                           " [--config file] [--root dir] [--out file.csv]\n");
      std::exit(2);
    }
  }
  return a;
}

// mean effective pressure [bar] of a torque [Nm] over the swept volume Vd_m3 of all cylinders
double toBar(double torque_Nm, double Vd_m3) { return torque_Nm * 4.0 * hbt::units::kPi / Vd_m3 / 1e5; }

// --fired: each (rpm, load) point from a reset, brake BSFC vs map and cylinder 1's last cycle.
void runFired(Engine1D& eng, const Args& a) {
  const double Vd_m3 = eng.assembly().displacement_m3();
  const double dt = 0.02;
  std::printf("  rpm  load  T_b   BSFC  ref   err%%  | IMEPg IMEPn PMEP FMEP  pmax@deg   SOC  ID  CA10 CA50 "
              "CA90 | Qw/Qf burn/inj eta_ig lambda NOx[g/kWh]\n");
  for (std::size_t j = 0; j + 1 < a.fired.size(); j += 2) {
    const double rpm = a.fired[j], w = hbt::units::rpmToRadps(rpm), treq = a.fired[j + 1] * eng.fullLoadTorque(w);
    eng.reset(w, treq, 298.15);
    Engine1DInputs in;
    in.speed_rad_s = w;
    in.torque_request_Nm = treq;
    const int n = static_cast<int>(std::lround(a.sim / dt));
    const Engine1DOutputs* o = nullptr;
    for (int k = 0; k < n; ++k) o = &eng.step(dt, in);
    const auto& c = eng.assembly().cylinder(0).lastCycle();
    const double tb = o->brake_torque_Nm, fuel = o->fuel_mass_flow_kg_s;
    const double bsfc = fuel / (tb * w) * 3.6e9;
    const double bref = eng.reference().steadyFuel(w, tb) / (tb * w) * 3.6e9;
    std::printf("%6.0f %4.2f %6.1f %5.1f %5.1f %+5.1f | %5.2f %5.2f %4.2f %4.2f %5.1f@%4.1f %5.1f %4.1f %4.1f %4.1f "
                "%4.1f | %5.3f %5.3f %6.3f %5.2f %5.1f\n",
                rpm, a.fired[j + 1], tb, bsfc, bref, 100.0 * (bsfc / bref - 1.0), c.imep_gross_Pa / 1e5,
                c.imep_net_Pa / 1e5, c.pmep_Pa / 1e5, toBar(o->friction_torque_Nm, Vd_m3), c.pmax_Pa / 1e5,
                c.theta_pmax_deg, c.soc_main_deg, c.ignition_delay_main_deg, c.ca10_deg, c.ca50_deg,
                c.ca90_deg, c.heat_wall_J / std::max(c.heat_release_J, 1e-9),
                c.fuel_burned_kg / std::max(c.fuel_injected_kg, 1e-12), c.eta_ind_gross, c.lambda,
                o->nox_mass_flow_kg_s / (tb * w) * 3.6e9);
  }
}

// The motoring curve: each speed with fuel cut, averages over the last 0.2 s vs the reference.
void runMotoring(Engine1D& eng, const Args& a) {
  const double Vd_m3 = eng.assembly().displacement_m3();
  std::ofstream csv;
  if (!a.out.empty()) {
    csv.open(a.out);
    csv << "speed_rpm,brake_Nm,ref_motoring_Nm,err_pct,indicated_Nm,friction_Nm,fmep_bar,"
           "pmep_bar,pmax_bar,boost_Pa,p3_Pa\n";
  }
  const double dt = 0.01;
  const int lag = static_cast<int>(std::lround(0.2 / dt));
  double sum_abs = 0.0, sum_ratio = 0.0;
  std::printf("  rpm   T_b[Nm]  ref[Nm]   err   T_i,net  T_f   FMEP  PMEP(bar)  pmax  p_im   p3\n");
  for (int i = 0; i < a.speeds; ++i) {
    const double rpm = a.speeds > 1 ? a.n_lo + (a.n_hi - a.n_lo) * i / (a.speeds - 1) : a.n_lo;
    const double w = hbt::units::rpmToRadps(rpm);
    eng.reset(w, eng.motoringTorque(w), 298.15);
    Engine1DInputs in;
    in.speed_rad_s = w;
    in.torque_request_Nm = eng.motoringTorque(w);
    in.fuel_enabled = false;
    const int n = static_cast<int>(std::lround(a.sim / dt));
    double tb = 0, ti = 0, tf = 0, pmax = 0, pim = 0, p3 = 0;
    for (int k = 0; k < n; ++k) {
      const Engine1DOutputs& o = eng.step(dt, in);
      if (k >= n - lag) {
        tb += o.brake_torque_Nm / lag, ti += o.indicated_torque_Nm / lag;
        tf += o.friction_torque_Nm / lag, pmax += o.peak_cylinder_pressure_Pa / lag;
        pim += o.boost_pressure_Pa / lag, p3 += o.turbine_inlet_p_Pa / lag;
      }
    }
    const double ref = eng.motoringTorque(w), err = 100.0 * (tb / ref - 1.0);
    sum_abs += std::fabs(tb - ref);
    sum_ratio += tb / ref;
    // friction torque is a positive loss; the net indicated torque (gas exchange + compression/
    // expansion wall-heat loss) is negative when motored
    const double fmep = toBar(tf, Vd_m3), pmep = toBar(-ti, Vd_m3);
    std::printf("%6.0f %8.1f %8.1f %+6.1f%% %7.1f %6.1f %5.2f %5.2f %8.1f %6.3f %6.3f\n", rpm, tb,
                ref, err, ti, tf, fmep, pmep, pmax / 1e5, pim / 1e5, p3 / 1e5);
    if (csv)
      csv << rpm << "," << tb << "," << ref << "," << err << "," << ti << "," << tf << "," << fmep
          << "," << pmep << "," << pmax / 1e5 << "," << pim << "," << p3 << "\n";
  }
  std::printf("motoring: mean |T_b - T_ref| = %.1f Nm, mean T_b/T_ref = %.3f\n", sum_abs / a.speeds,
              sum_ratio / a.speeds);
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = parse(argc, argv);
  try {
    Engine1DParams p = Engine1DParams::load(a.root, a.config);
    Engine1D eng(p, a.root);
    if (!a.fired.empty()) runFired(eng, a);
    else runMotoring(eng, a);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "engine_1d_motoring: %s\n", e.what());
    return 1;
  }
  return 0;
}
