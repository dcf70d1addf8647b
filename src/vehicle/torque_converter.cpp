#include "vehicle/torque_converter.hpp"

#include <algorithm>

#include "common/csv_table.hpp"
#include "common/errors.hpp"

namespace hbt::vehicle {

TorqueConverter::TorqueConverter(const std::string& path, double w_ref) : w_ref_(w_ref) {
  const CsvTable t = CsvTable::read(path);
  if (t.header().size() != 3)
    throw InputError(path, "(header)", "expected 3 columns: speed ratio, torque ratio, MP_ref");
  const std::string cn = t.header()[0], cm = t.header()[1], cp = t.header()[2];
  t.requireStrictlyIncreasing(cn);
  const auto& nu = t.column(cn);
  const auto& mu = t.column(cm);
  const auto& mp = t.column(cp);
  if (nu.front() != 0.0) throw InputError(path, normaliseColumnName(cn), "must start at 0 (stall)");
  for (std::size_t i = 0; i < nu.size(); ++i)
    if (!(mu[i] > 0.0))
      throw InputError(path, normaliseColumnName(cm), "data row " + std::to_string(i + 1) + ": must be > 0");
  if (!(mp.front() > 0.0)) throw InputError(path, normaliseColumnName(cp), "stall torque must be > 0");
  if (!(w_ref > 0.0)) throw InputError(path, "tc_reference_speed_rad_s", "must be > 0");
  mu_ = Table1D(nu, mu, path, normaliseColumnName(cn));
  mp_ = Table1D(nu, mp, path, normaliseColumnName(cn));
}

double TorqueConverter::speedRatio(double wp, double wt) const {
  if (wp <= 0.0) return mu_.xMax();
  return std::clamp(wt / wp, 0.0, mu_.xMax());
}

double TorqueConverter::pumpTorque(double wp, double wt) const {
  if (wp <= 0.0) return 0.0;
  const double r = wp / w_ref_;
  return mp_(speedRatio(wp, wt)) * r * r;
}

double TorqueConverter::turbineTorque(double wp, double wt) const {
  const double nu = speedRatio(wp, wt);
  // Overrun (ν > 1, the turbine drives the pump): torque ratio taken as T_p/T_t, so that the
  // loss T_p ω_p (1 - ν/μ) stays >= 0 also where the table has μ < 1 just above ν = 1.
  return nu > 1.0 ? pumpTorque(wp, wt) / mu_(nu) : mu_(nu) * pumpTorque(wp, wt);
}

}  // namespace hbt::vehicle
