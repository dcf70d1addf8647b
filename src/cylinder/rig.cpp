#include "cylinder/rig.hpp"

#include <algorithm>
#include <cmath>

#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::cylinder {

double ValveProfile::lift(double theta_deg) const {
  double phi = std::fmod(theta_deg - open_deg, 720.0);
  if (phi < 0.0) phi += 720.0;
  if (phi >= duration_deg) return 0.0;
  const double s = std::sin(units::kPi * phi / duration_deg);
  return max_lift_m * s * s;
}

double ValveProfile::effectiveArea(double theta_deg) const {
  const double L = lift(theta_deg);
  if (L <= 0.0) return 0.0;
  return count * discharge_coeff *
         std::min(units::kPi * diameter_m * L, 0.25 * units::kPi * diameter_m * diameter_m);
}

double orificeMassFlow(double A, double p0, double T0, double R, double g, double p2) {
  if (A <= 0.0 || p2 >= p0) return 0.0;
  const double crit = std::pow(2.0 / (g + 1.0), g / (g - 1.0));
  const double pr = std::max(p2 / p0, crit);
  const double psi = std::sqrt(2.0 * g / (g - 1.0) *
                               (std::pow(pr, 2.0 / g) - std::pow(pr, (g + 1.0) / g)));
  return A * p0 / std::sqrt(R * T0) * psi;
}

void RigParams::declare(ParamSet& ps) {
  ps.setPrefix("cylinder_rig/");
  ps.add("speed_rpm", speed_rpm, "rpm", 300.0, 3000.0, "rig speed");
  ps.add("p_intake_Pa", p_intake_Pa, "Pa", 0.5e5, 5e5, "intake reservoir pressure");
  ps.add("T_intake_K", T_intake_K, "K", 230.0, 500.0, "intake reservoir temperature");
  ps.add("intake_burned_frac", intake_burned_frac, "-", 0.0, 0.6, "EGR burned fraction");
  ps.add("p_exhaust_Pa", p_exhaust_Pa, "Pa", 0.5e5, 5e5, "exhaust reservoir pressure");
  ps.add("T_exhaust_K", T_exhaust_K, "K", 300.0, 1200.0, "exhaust reservoir temperature");
  ps.add("fuel_per_cycle_kg", fuel_per_cycle_kg, "kg", 0.0, 300e-6, "injected fuel per cycle");
  ps.add("coolant_K", coolant_K, "K", 230.0, 400.0, "coolant temperature");
  ps.add("step_deg", step_deg, "deg", 0.01, 2.0, "rig time step");
  ps.add("intake_open_deg", intake.open_deg, "deg", -360.0, 720.0, "IVO (firing TDC = 0)");
  ps.add("intake_duration_deg", intake.duration_deg, "deg", 90.0, 360.0, "intake event length");
  ps.add("intake_max_lift_m", intake.max_lift_m, "m", 0.001, 0.03, "intake max lift");
  ps.add("intake_diameter_m", intake.diameter_m, "m", 0.01, 0.08, "intake valve diameter");
  ps.add("intake_discharge_coeff", intake.discharge_coeff, "-", 0.2, 1.0, "intake Cd");
  ps.add("exhaust_open_deg", exhaust.open_deg, "deg", -360.0, 720.0, "EVO");
  ps.add("exhaust_duration_deg", exhaust.duration_deg, "deg", 90.0, 360.0, "exhaust event length");
  ps.add("exhaust_max_lift_m", exhaust.max_lift_m, "m", 0.001, 0.03, "exhaust max lift");
  ps.add("exhaust_diameter_m", exhaust.diameter_m, "m", 0.01, 0.08, "exhaust valve diameter");
  ps.add("exhaust_discharge_coeff", exhaust.discharge_coeff, "-", 0.2, 1.0, "exhaust Cd");
  ps.setPrefix("");
}

SingleCylinderRig::SingleCylinderRig(const CylinderParams& cp, const RigParams& rp)
    : rp_(rp), cyl_(cp, "rig") {
  cyl_.setCoolantTemperature(rp.coolant_K);
  cyl_.setFuelPerCycle(rp.fuel_per_cycle_kg);
  cyl_.initialize(-360.0, rp.p_exhaust_Pa, rp.T_exhaust_K, xb_exh_);
}

PortFlow SingleCylinderRig::valveFlow(const ValveProfile& v, double p_res, double T_res,
                                      double xb_res) const {
  PortFlow f;
  const double A = v.effectiveArea(cyl_.crankAngle_deg());
  if (A <= 0.0) return f;
  const double pc = cyl_.pressure_Pa();
  if (p_res > pc) {
    const double R = (1 - xb_res) * cyl_.thermo().group(kAir).R + xb_res * cyl_.thermo().group(kBurned).R;
    const double cp = (1 - xb_res) * cyl_.thermo().group(kAir).cp(T_res) +
                      xb_res * cyl_.thermo().group(kBurned).cp(T_res);
    f.mdot_kg_s = orificeMassFlow(A, p_res, T_res, R, cp / (cp - R), pc);
    f.Hdot_W = f.mdot_kg_s * cyl_.enthalpyOf(T_res, xb_res);
    f.burned_frac = xb_res;
  } else {
    f.mdot_kg_s = -orificeMassFlow(A, pc, cyl_.temperature_K(), cyl_.gasConstant_J_kgK(),
                                   cyl_.gamma(), p_res);
    f.Hdot_W = f.mdot_kg_s * cyl_.specificEnthalpy_J_kg();
    f.burned_frac = cyl_.burnedFraction();
  }
  return f;
}

PortFlows SingleCylinderRig::step() {
  const double omega = units::rpmToRadps(rp_.speed_rpm);
  const double dt = units::degToRad(rp_.step_deg) / omega;
  PortFlows f;
  f.intake = valveFlow(rp_.intake, rp_.p_intake_Pa, rp_.T_intake_K, rp_.intake_burned_frac);
  f.exhaust = valveFlow(rp_.exhaust, rp_.p_exhaust_Pa, rp_.T_exhaust_K, xb_exh_);
  if (f.exhaust.mdot_kg_s < 0.0) {
    out_m_ -= f.exhaust.mdot_kg_s * dt;
    out_mxb_ -= f.exhaust.mdot_kg_s * dt * f.exhaust.burned_frac;
  }
  const int before = cyl_.cyclesCompleted();
  cyl_.advance(dt, omega, f);
  if (cyl_.cyclesCompleted() != before && out_m_ > 0.0) {
    xb_exh_ = out_mxb_ / out_m_;
    out_m_ = out_mxb_ = 0.0;
  }
  return f;
}

CycleResults SingleCylinderRig::runCycles(int n) {
  const int target = cyl_.cyclesCompleted() + n;
  const long guard = static_cast<long>((n + 1) * 720.0 / rp_.step_deg) + 10;
  for (long i = 0; cyl_.cyclesCompleted() < target; ++i) {
    if (i > guard) throw ModelDivergence("cylinder rig", "cycle", "cycle did not complete");
    step();
  }
  return cyl_.lastCycle();
}

CycleResults SingleCylinderRig::runToPeriodic(int max_cycles, double tol) {
  CycleResults prev = runCycles(1);
  for (int i = 1; i < max_cycles; ++i) {
    const CycleResults c = runCycles(1);
    const double d1 = std::fabs(c.imep_net_Pa - prev.imep_net_Pa) / std::max(std::fabs(c.imep_net_Pa), 1e4);
    const double d2 = std::fabs(c.trapped_mass_kg - prev.trapped_mass_kg) / c.trapped_mass_kg;
    if (d1 < tol && d2 < tol) return c;
    prev = c;
  }
  return prev;
}

}  // namespace hbt::cylinder
