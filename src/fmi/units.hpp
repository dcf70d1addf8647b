// Units of an FMU's variables (FMI 2.0 section 2.2.2, UnitDefinitions): a unit is its SI
// dimension, the exponents of the base units kg, m, s, A, K, mol, cd and rad, with a factor and
// an offset such that
//     value_SI = factor * value_unit + offset
// (e.g. degC: K = 1, factor 1, offset 273.15; kW: kg m2 s-3, factor 1000; bar: kg m-1 s-2,
// factor 1e5; rpm declared as rad s-1: factor 2 pi / 60). A variable without a unit is
// dimensionless with factor 1 and offset 0.
//
// unitToSi() gives the conversion of a variable's values to SI after checking that its unit has
// the dimension the caller expects; rad is a dimension of its own (an rpm declared as s-1 is
// not an angular speed in rad/s).
#pragma once
#include <array>
#include <string>

namespace hbt::fmi {

/// Exponents of kg, m, s, A, K, mol, cd, rad (the order of BaseUnit's attributes).
struct SiDimension {
  std::array<int, 8> exponent{};
  bool operator==(const SiDimension& o) const { return exponent == o.exponent; }
  bool operator!=(const SiDimension& o) const { return !(*this == o); }
  /// e.g. "kg.m2.s-3", "1" for dimensionless.
  std::string str() const;
  /// The name of base unit i (0..7) as BaseUnit's attribute spells it.
  static const char* baseName(int i);
};

/// A unit of UnitDefinitions: its name, SI dimension, factor and offset.
struct UnitDefinition {
  std::string name;
  SiDimension dimension;
  double factor = 1.0;  // FMI 2.0 default
  double offset = 0.0;  // FMI 2.0 default
};

/// The SI unit a caller expects: its name for messages ("K", "W", "Pa", "rad/s") and dimension.
struct SiUnit {
  std::string name;
  SiDimension dimension;
};
namespace si {
SiUnit dimensionless();
SiUnit kelvin();
SiUnit watt();
SiUnit pascal();
SiUnit radianPerSecond();
SiUnit second();
}  // namespace si

/// value_SI = factor * value + offset, and back.
struct UnitConversion {
  double factor = 1.0;
  double offset = 0.0;
  double toSi(double value) const { return factor * value + offset; }
  double fromSi(double value_si) const { return (value_si - offset) / factor; }
};

}  // namespace hbt::fmi
