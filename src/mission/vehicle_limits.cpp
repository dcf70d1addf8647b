#include "mission/vehicle_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/csv_table.hpp"
#include "common/errors.hpp"
#include "common/units.hpp"

namespace hbt::mission {

AccelerationLimits::AccelerationLimits(Table1D acc, Table1D dec, const std::string& source)
    : acc_(std::move(acc)), dec_(std::move(dec)), source_(source) {
  for (double a : acc_.y())
    if (!(a > 0.0)) throw InputError(source, "acc", "maximum acceleration must be > 0 m/s2");
  for (double d : dec_.y())
    if (!(d < 0.0)) throw InputError(source, "dec", "maximum deceleration must be < 0 m/s2");
  for (double v : acc_.x())
    if (v < 0.0) throw InputError(source, "v", "speeds must be >= 0");
}

AccelerationLimits AccelerationLimits::readVacc(const std::string& path) {
  const CsvTable t = CsvTable::read(path);
  t.requireStrictlyIncreasing("v");
  std::vector<double> v = t.column("v");
  for (double& x : v) x = units::kmhToMps(x);
  return AccelerationLimits(Table1D(v, t.column("acc"), path, "acc"),
                            Table1D(v, t.column("dec"), path, "dec"), path);
}

AccelerationLimits AccelerationLimits::constant(double acc_m_s2, double dec_m_s2) {
  const std::vector<double> v{0.0, 100.0};
  return AccelerationLimits(Table1D(v, {acc_m_s2, acc_m_s2}, "constant limits", "acc"),
                            Table1D(v, {dec_m_s2, dec_m_s2}, "constant limits", "dec"),
                            "constant limits");
}

double RoadLoad::resistance_N(double v_m_s, double grade_percent) const {
  const double alpha = std::atan(grade_percent / 100.0);
  const double g = units::kGravity_m_s2;
  return p_.mass_kg * g * (p_.rrc * std::cos(alpha) + std::sin(alpha)) +
         0.5 * p_.air_density_kg_m3 * p_.cda_m2 * v_m_s * v_m_s;
}

double RoadLoad::coastingAccel_m_s2(double v_m_s, double grade_percent) const {
  return -resistance_N(v_m_s, grade_percent) / effectiveMass_kg();
}

double RoadLoad::powerLimitedAccel_m_s2(double v_m_s, double grade_percent) const {
  if (p_.max_wheel_power_W <= 0.0) return std::numeric_limits<double>::infinity();
  const double v = std::max(v_m_s, 0.1);  // P/v is unbounded at standstill
  return (p_.max_wheel_power_W / v - resistance_N(v_m_s, grade_percent)) / effectiveMass_kg();
}

}  // namespace hbt::mission
