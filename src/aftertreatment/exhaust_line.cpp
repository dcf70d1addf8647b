#include "aftertreatment/exhaust_line.hpp"

#include <algorithm>
#include <cmath>

#include "aftertreatment/gas.hpp"
#include "aftertreatment/lumped_wall.hpp"
#include "common/errors.hpp"

namespace hbt::aftertreatment {

namespace {
// Outer film resistance [m^2 K/W] where no external heat transfer acts.
constexpr double kNoFilmResistance_m2K_W = 1e12;
constexpr double kExhaustPrandtl = 0.70;  // lean exhaust (~75 % N2), 400-900 K
}  // namespace

ExhaustLine::ExhaustLine(std::vector<std::string> names, std::vector<PipeSegmentParams> segments,
                         const LineParams& line, double h_natural_W_m2K)
    : names_(std::move(names)), seg_(std::move(segments)), line_(line), h_natural_(h_natural_W_m2K) {
  for (const auto& s : seg_) C_.push_back(s.wall_mass_kg * s.wall_cp_J_kgK);
  T_.assign(seg_.size(), 298.15);
}

void ExhaustLine::setUniformTemperature(double T_K) { T_.assign(seg_.size(), T_K); }

double ExhaustLine::energyStored() const {
  double e = 0.0;
  for (std::size_t i = 0; i < seg_.size(); ++i) e += C_[i] * T_[i];
  return e;
}

double ExhaustLine::nusselt(int i, double mdot, double Tg) const {
  const PipeSegmentParams& s = seg_[i];
  const double Re = 4.0 * mdot / (units::kPi * s.diameter_m * viscosity(Tg));
  const double turb = s.pulsating
      ? line_.pulsating_nusselt_c * std::pow(Re, line_.pulsating_nusselt_re_exponent)
      : line_.pipe_nusselt_c * std::pow(Re, line_.pipe_nusselt_re_exponent) *
            std::pow(kExhaustPrandtl, line_.pipe_nusselt_pr_exponent);
  return std::max(line_.laminar_nusselt, turb);
}

double ExhaustLine::gasSideHA(int i, double mdot, double Tg) const {
  const PipeSegmentParams& s = seg_[i];
  const double h = nusselt(i, mdot, Tg) * conductivity(Tg) / s.diameter_m;
  return h * s.inner_area_m2;
}

double ExhaustLine::outerUA(int i, double T_wall, double T_amb, double v) const {
  const PipeSegmentParams& s = seg_[i];
  if (s.outer_area_m2 <= 0.0) return 0.0;
  const double D_out = s.outer_area_m2 / (units::kPi * s.length_m);
  const double he = outerFilmH(T_wall, T_amb, s.air_speed_factor * v, D_out, h_natural_, s.emissivity);
  const double R = s.insulation_thickness_m / s.insulation_k_W_mK + (he > 0.0 ? 1.0 / he : kNoFilmResistance_m2K_W);
  return s.outer_area_m2 / R;
}

double ExhaustLine::step(double dt, double mdot, double cp, double Tg, double T_amb, double v,
                         BrickEnergy& e) {
  const double mcp = mdot * cp;
  for (std::size_t i = 0; i < seg_.size(); ++i) {
    const int k = static_cast<int>(i);
    const double T0 = T_[i];
    const double G = mcp > 0.0 ? -mcp * std::expm1(-gasSideHA(k, mdot, Tg) / mcp) : 0.0;
    const double UA = outerUA(k, T0, T_amb, v);
    const WallStep w = exactWallStep(T0, C_[i], G, UA, 0.0, Tg, T_amb, dt);
    if (!std::isfinite(w.T1) || w.T1 <= 0.0)
      throw ModelDivergence("exhaust line " + names_[i], "wall temperature",
                            "non-physical value " + std::to_string(w.T1));
    T_[i] = w.T1;
    const double q_gas = G * (Tg - w.Tbar);
    e.gas_to_wall_J += q_gas * dt;
    e.can_loss_J += UA * (w.Tbar - T_amb) * dt;
    e.stored_J += C_[i] * (w.T1 - T0);
    if (mcp > 0.0) Tg -= q_gas / mcp;
    else Tg = w.Tbar;
  }
  return Tg;
}

}  // namespace hbt::aftertreatment
